// The flywheel for a target δ* by the excess work (DriveSizing.h, StartLoad.h): the load's energy
// swing of a revolution at constant crank speed, ΔA, gives J* = ΔA/(δ*·ω̄²).
//  * Closed form: with no loads, no friction and no gravity, the torque that keeps ω constant is
//    ½·J'(φ)·ω², whose integral is ½·ω²·(J(φ) - J(φ0)); so ΔA = ½·ω²·(J_max - J_min), computed
//    here from the reduced inertia J(φ) itself (not its derivative, which the code integrates).
//  * Against runs: the proposal, added to the scene, brings δ near δ* where the run's own δ·J
//    held constant (the energy method) fell far short (six carts at 90°: 563 kg·m² proposed,
//    1307 needed). Bounds from the measured spread: -16 % (an elastic coupling whose mode is near
//    an excited order) to +24 % (the motor's slip lowers δ further) of what runs need, so the
//    resulting δ lies within 0.75 ... 1.3 δ*.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "analysis/SizingSummary.h"
#include "analysis/Summary.h"
#include "cli/CliTestSupport.h"
#include "reduced/ReducedModel.h"
#include "scene/SceneParser.h"
#include "studies/StartLoad.h"

namespace rollerdyn {
namespace {

using test::model;

TEST(FlywheelExcessWork, ALoadFreeMachinesExcessWorkIsHalfOmegaSquaredTimesTheInertiaSwing) {
  const Scene s = parseSceneFile(model("energy-balanced-3cart.yaml"),
                                 {"loads.roller_force_front=0", "loads.roller_force_rear=0", "loads.gravity=0"});
  const StartLoad l = startLoadOf(s);
  ASSERT_TRUE(std::isfinite(l.excess_work) && std::isfinite(l.excess_work_speed));
  // The speed: the motor's static curve against a load of zero mean is the synchronous crank speed.
  EXPECT_NEAR(l.excess_work_speed, s.motor.omega_sync / s.reducer.ratio, 1e-6 * l.excess_work_speed);
  const ReducedModel m(s);
  double lo = INFINITY, hi = -INFINITY;
  for (int i = 0; i < 36000; ++i) {
    const double J = m.crankSideInertia(2 * M_PI * i / 36000);
    lo = std::min(lo, J), hi = std::max(hi, J);
  }
  const double w = l.excess_work_speed, expected = 0.5 * w * w * (hi - lo);
  std::printf("  ΔA %.6g J, ½ω²(J_max - J_min) = %.6g J (J %.5g ... %.5g kg·m² at %.5g rad/s)\n", l.excess_work,
              expected, lo, hi, w);
  // 3600 trapezoids against a closed form: error ~(2π/3600)²/12·|J'''|/|J'| of the 3rd harmonic ~ 3e-6.
  EXPECT_NEAR(l.excess_work, expected, 1e-4 * expected);
  EXPECT_GT(expected, 100.0);  // the inertia swing of three carts at 120° is no rounding error
}

double deltaWith(const std::string& scene, std::vector<std::string> o, double flywheel) {
  o.push_back("flywheel.inertia=" + std::to_string(flywheel));
  const Scene s = parseSceneFile(model(scene), o);
  return makeSummary(s, runReducedModel(s))["delta"].get<double>();
}

TEST(FlywheelExcessWork, TheProposedFlywheelBringsDeltaNearTheTargetWhereTheEnergyMethodFellShort) {
  const std::vector<std::string> six = {"carts.count=6", "crank.offset_deg=90", "initial.crank_speed=10.4",
                                        "simulation.t_end=20", "simulation.reactions=false"};
  for (const auto& [scene, o] : std::vector<std::pair<std::string, std::vector<std::string>>>{
           {"balanced-4cart.yaml", six}, {"energy-balanced-3cart.yaml", {"simulation.reactions=false"}}}) {
    std::vector<std::string> with_target = o;
    with_target.push_back("sizing.target_delta=0.05");
    const Scene s = parseSceneFile(model(scene), with_target);
    const StartLoad load = startLoadOf(s);
    const nlohmann::json f = makeSummary(s, runReducedModel(s), &load)["sizing"]["flywheel"];
    ASSERT_TRUE(f["excess_work"].is_number()) << f.dump();
    const double proposed = f["flywheel_crankshaft"], energy = f["added_inertia_energy_method"];
    const double d = deltaWith(scene, o, proposed), d_energy = deltaWith(scene, o, energy);
    std::printf("  %s: proposed %.4g kg·m² gives δ %.4g; the energy method's %.4g kg·m² gives δ %.4g (δ* 0.05)\n",
                scene.c_str(), proposed, d, energy, d_energy);
    EXPECT_GT(d, 0.75 * 0.05);
    EXPECT_LT(d, 1.3 * 0.05);
    EXPECT_LT(std::abs(d - 0.05), std::abs(d_energy - 0.05));  // closer than the energy method
  }
}

// With the proposed flywheel in place the run's δ (0.058) still exceeds δ* (0.05) and the excess
// work alone would add nothing (J* 1302 below the present 1310 kg·m²): the trial read "this run
// already meets δ*". The proposal then comes from the run's δ·J, "met" only from the measured δ,
// and the motor-shaft figure is the whole flywheel there, as the crankshaft's is.
TEST(FlywheelExcessWork, ARunWithTheProposedFlywheelIsNotMetByAnEstimate) {
  const Scene s = parseSceneFile(model("balanced-4cart.yaml"),
                                 {"carts.count=6", "crank.offset_deg=90", "initial.crank_speed=10.4", "simulation.t_end=15",
                                  "simulation.reactions=false", "sizing.target_delta=0.05", "flywheel.inertia=1103"});
  const StartLoad load = startLoadOf(s);
  const nlohmann::json j = makeSummary(s, runReducedModel(s), &load);
  const nlohmann::json& f = j["sizing"]["flywheel"];
  ASSERT_GT(j["delta"].get<double>(), 0.05);
  const double added = f["added_inertia_crankshaft"];
  EXPECT_GT(added, 100.0) << f.dump();
  EXPECT_NEAR(added, f["added_inertia_energy_method"].get<double>(), 1e-9);
  const double u = s.reducer.ratio;
  EXPECT_NEAR(f["flywheel_crankshaft"].get<double>(), 1103 + added, 1e-6);
  EXPECT_NEAR(f["flywheel_motor_shaft"].get<double>(), (1103 + added) / (s.reducer.delta * u * u), 1e-9);
  const std::string text = sizingText(j);
  EXPECT_NE(text.find("for δ* = 0.05"), std::string::npos) << text;
  // The whole flywheel and what it adds, not one number read as either (the third trial).
  EXPECT_NE(text.find("kg·m² in all on the crankshaft ("), std::string::npos) << text;
  EXPECT_NE(text.find("more than now)"), std::string::npos) << text;
  EXPECT_NE(text.find("less the present J 1310: nothing;"), std::string::npos) << text;
  EXPECT_EQ(text.find("already meets"), std::string::npos) << text;
}

}  // namespace
}  // namespace rollerdyn
