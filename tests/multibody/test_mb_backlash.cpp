// The multibody model with the reducer's backlash (physics/CouplingLaw.h, the same law as the
// reduced model's): its energy audit closes in both formulations, and it agrees with the reduced
// model on a run whose teeth part and meet again.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "multibody/MultibodySimulation.h"
#include "reduced/ReducedModel.h"
#include "support/Loveikin2018Scene.h"

namespace rollerdyn {
namespace {

// The four-cart drive of Loveikin, Pochka, Romasevych (2018) from rest with 0.1° of backlash,
// without guide friction (whose normal-force laws differ between the models by design).
Scene backlashScene() {
  Scene sc = test_scenes::loveikin2018Scene();
  sc.loads.guide_friction = 0.0;
  sc.reducer.backlash = 0.0017453;
  sc.simulation.t_end = 2.0;
  sc.simulation.output_step = 1e-3;
  return sc;
}

double share(const RunResult& r, int state, double t0) {
  const std::vector<double> c = r.timeseries.column("tooth_contact"), t = r.timeseries.column("t");
  int n = 0, k = 0;
  for (std::size_t i = 0; i < c.size(); ++i)
    if (t[i] >= t0) ++n, k += c[i] == state;
  return n ? double(k) / n : NAN;
}

TEST(MultibodyBacklash, EnergyAuditClosesInBothFormulations) {
  for (Formulation f : {Formulation::Constrained, Formulation::Minimal}) {
    Scene sc = backlashScene();
    sc.simulation.formulation = f;
    sc.simulation.accuracy = 1e-9;
    sc.simulation.constraint_tolerance = 1e-9;
    const RunResult r = runMultibodyModel(sc);
    ASSERT_TRUE(r.stats.complete) << toString(f) << ": " << r.stats.status;
    ASSERT_TRUE(r.timeseries.has("tooth_contact"));
    EXPECT_GT(share(r, 0, 1.0), 0.0) << toString(f);  // the teeth do part
    EXPECT_GT(r.energy.damping_dissipation, 0.0);
    EXPECT_LT(std::abs(r.energy.residualRelative()), 1e-6) << toString(f) << ": " << r.energy.residual() << " J";
  }
}

TEST(MultibodyBacklash, AgreesWithTheReducedModelThroughImpacts) {
  Scene sc = backlashScene();
  sc.simulation.accuracy = 1e-8;
  sc.simulation.formulation = Formulation::Minimal;
  const RunResult mb = runMultibodyModel(sc);
  const RunResult red = runReducedModel(sc);
  ASSERT_TRUE(mb.stats.complete && red.stats.complete) << mb.stats.status << " / " << red.stats.status;
  const std::vector<double> wm = mb.timeseries.column("omega_crank"), wr = red.timeseries.column("omega_crank");
  const std::vector<double> Mm = mb.timeseries.column("coupling_torque"), Mr = red.timeseries.column("coupling_torque");
  ASSERT_EQ(wm.size(), wr.size());
  double dw = 0, dM = 0, Mmax = 0;
  for (std::size_t i = 0; i < wm.size(); ++i) {
    dw = std::max(dw, std::abs(wm[i] - wr[i]));
    dM = std::max(dM, std::abs(Mm[i] - Mr[i]));
    Mmax = std::max(Mmax, std::abs(Mr[i]));
  }
  EXPECT_LT(dw, 1e-4 * 104.72 / 9.8) << dw;
  EXPECT_LT(dM, 1e-3 * Mmax) << dM << " of " << Mmax;
  EXPECT_NEAR(share(mb, 0, 1.0), share(red, 0, 1.0), 0.005);
  EXPECT_GT(share(red, 0, 1.0), 0.0);
}

}  // namespace
}  // namespace rollerdyn
