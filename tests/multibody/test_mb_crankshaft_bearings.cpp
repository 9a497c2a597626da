// Each main bearing's reaction in a real multibody run (crankshaft.*; analysis/CrankshaftBearings.h):
// the bearings together carry the resultant the model computes, the crank-pin forces (with the
// split rods' pin masses) explain all of it, where the throws sit changes each bearing's share
// but not the resultant, and a scene without the keys keeps its reactions table as it was.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "analysis/CrankshaftBearings.h"
#include "analysis/SteadyState.h"
#include "multibody/MultibodyModel.h"
#include "multibody/MultibodySimulation.h"
#include "scene/SceneParser.h"

namespace rollerdyn {
namespace {

Scene shortRun(std::vector<std::string> more) {
  std::vector<std::string> o = {"simulation.t_end=1.5"};
  o.insert(o.end(), more.begin(), more.end());
  return parseSceneFile(std::string(ROLLERDYN_SOURCE_DIR) + "/model/balanced-4cart.yaml", o);
}

double peakOf(const Table& t, const std::string& x, const std::string& y) {
  const std::vector<double> a = t.column(x), b = t.column(y);
  double p = 0;
  for (std::size_t i = 0; i < a.size(); ++i) p = std::max(p, std::hypot(a[i], b[i]));
  return p;
}

TEST(MultibodyCrankshaftBearings, BearingsTogetherCarryTheResultantAtEveryRow) {
  for (const char* rods : {"rods.model=split", "rods.model=distributed"}) {
    const RunResult run = runMultibodyModel(shortRun(
        {rods, "crankshaft.throw_positions=[0.2, 0.4, 0.6, 0.8]", "crankshaft.bearing_positions=[0, 0.5, 1.0]"}));
    const Table& r = run.reactions;
    ASSERT_TRUE(r.has("bearing_x_3")) << rods;
    ASSERT_FALSE(r.has("bearing_x_4")) << rods;
    const double scale = peakOf(r, "bearing_x", "bearing_y");
    ASSERT_GT(scale, 1e3) << rods;
    for (const char* c : {"x", "y"}) {
      const std::vector<double> R = r.column(std::string("bearing_") + c);
      const std::vector<double> b1 = r.column(std::string("bearing_") + c + "_1"),
                                b2 = r.column(std::string("bearing_") + c + "_2"),
                                b3 = r.column(std::string("bearing_") + c + "_3");
      for (std::size_t i = 0; i < R.size(); ++i) ASSERT_NEAR(b1[i] + b2[i] + b3[i], R[i], 1e-9 * scale) << rods << " row " << i;
    }
  }
}

TEST(MultibodyCrankshaftBearings, CrankPinForcesExplainTheWholeResultant) {
  // Every throw on bearing 1: it must take the whole resultant, and bearing 2 only half of what
  // the crank-pin forces (and the split rods' pin masses) do not explain, which is the rotors'
  // token masses' weight on the axis (2 g: 0.02 N). Leaving the pin masses out would put
  // 4·32 kg·(g + r·ω²) there instead.
  const RunResult run = runMultibodyModel(shortRun(
      {"rods.model=split", "crankshaft.throw_positions=[0, 0, 0, 0]", "crankshaft.bearing_positions=[0, 1]"}));
  const Table& r = run.reactions;
  const std::vector<double> x2 = r.column("bearing_x_2"), y2 = r.column("bearing_y_2");
  for (std::size_t i = 0; i < x2.size(); ++i) ASSERT_LT(std::hypot(x2[i], y2[i]), 0.05) << "row " << i;
}

TEST(MultibodyCrankshaftBearings, FiringOrderChangesTheBearingsButNotTheResultant) {
  // The same four crank angles {0, 90, 180, 270}° in two orders along the shaft: cart j's angle
  // moves, so the carts' phases differ, but the set of pin forces at each instant is the same, only
  // placed at other throws.
  const std::vector<std::string> shaft = {"crankshaft.throw_positions=[0.2, 0.4, 0.6, 0.8]",
                                          "crankshaft.bearing_positions=[0, 1.0]"};
  std::vector<std::string> a = shaft, b = shaft;
  a.push_back("crank.angles_deg=[0, 90, 180, 270]");
  b.push_back("crank.angles_deg=[0, 180, 90, 270]");
  const RunResult ra = runMultibodyModel(shortRun(a)), rb = runMultibodyModel(shortRun(b));
  const double Ra = peakOf(ra.reactions, "bearing_x", "bearing_y"), Rb = peakOf(rb.reactions, "bearing_x", "bearing_y");
  EXPECT_NEAR(Ra, Rb, 1e-6 * Ra);
  const double a1 = peakOf(ra.reactions, "bearing_x_1", "bearing_y_1"), b1 = peakOf(rb.reactions, "bearing_x_1", "bearing_y_1");
  EXPECT_GT(std::abs(a1 - b1), 0.01 * a1) << "bearing 1's peak: " << a1 << " N against " << b1 << " N";
}

TEST(MultibodyCrankshaftBearings, ShaftSegmentAtTheCouplingCarriesTheCouplingTorque) {
  // The shipped scene's crankshaft has no inertia of its own (crank.inertia_per_crank = 0,
  // crank.shaft_inertia = 0, distributed rods): the coupling's torque goes wholly into the crank
  // pins, so the torque of the segment from the coupling, Σ r × F over the pins, must peak where
  // the coupling torque the model computes peaks.
  const Scene sc = shortRun({"simulation.t_end=6", "crankshaft.throw_positions=[0.2, 0.4, 0.6, 0.8]",
                             "crankshaft.bearing_positions=[0, 1.0]"});
  const RunResult run = runMultibodyModel(sc);
  const SteadyState w = detectSteadyState(run, sc.simulation.steady_window_revolutions);
  ASSERT_TRUE(w.reached);
  const CrankshaftSizing c = sizeCrankshaft(sc, run, w);
  ASSERT_TRUE(c.available) << c.reason;
  const std::vector<double> t = run.reactions.column("t"), M = run.reactions.column("coupling_torque");
  double peak = 0;
  for (std::size_t i = 0; i < t.size(); ++i)
    if (t[i] >= w.t_begin && t[i] <= w.t_end) peak = std::max(peak, std::abs(M[i]));
  ASSERT_GT(peak, 1.0);
  EXPECT_NEAR(c.segment_torque_peak[0], peak, 1e-6 * peak);
}

TEST(MultibodyCrankshaftBearings, WithoutTheKeysTheReactionsTableKeepsItsColumns) {
  const Scene sc = shortRun({});
  const RunResult run = runMultibodyModel(sc);
  EXPECT_EQ(run.reactions.columns, MultibodyModel(sc).reactionColumns());
  EXPECT_FALSE(run.reactions.has("bearing_x_1"));
}

}  // namespace
}  // namespace rollerdyn
