// The optional `sizing` section (SizingInputs.h): every key reaches the Scene, absent keys mean
// "not given" (0), the Kloss way-3 data are kept for the nominal torque, and bad values are
// rejected with file:line: key.
#include <gtest/gtest.h>

#include "SceneTestSupport.h"

namespace rollerdyn {
namespace {

using test::expectSceneError;
using test::kMinimalScene;
using test::replaced;

const std::string kSizing =
    "sizing:\n"                          // 24
    "  motor_nominal_torque: 210\n"      // 25
    "  motor_efficiency: 0.91\n"         // 26
    "  target_delta: 0.05\n"             // 27
    "  coupling_rated_torque: 8000\n"    // 28
    "  bearing_rating:\n"                // 29
    "    guide_roller: 30000\n"          // 30
    "    rod_end: 40000\n"               // 31
    "    crank_pin: 120000\n"            // 32
    "    main_bearing: 250000\n";        // 33

TEST(SceneSizing, EveryKeyReachesTheScene) {
  const Scene s = parseSceneText(kMinimalScene + kSizing, "test.yaml");
  EXPECT_DOUBLE_EQ(s.sizing.motor_nominal_torque, 210);
  EXPECT_DOUBLE_EQ(s.sizing.motor_efficiency, 0.91);
  EXPECT_DOUBLE_EQ(s.sizing.target_delta, 0.05);
  EXPECT_DOUBLE_EQ(s.sizing.coupling_rated_torque, 8000);
  EXPECT_DOUBLE_EQ(s.sizing.rating_guide_roller, 30000);
  EXPECT_DOUBLE_EQ(s.sizing.rating_rod_end, 40000);
  EXPECT_DOUBLE_EQ(s.sizing.rating_crank_pin, 120000);
  EXPECT_DOUBLE_EQ(s.sizing.rating_main_bearing, 250000);
  EXPECT_EQ(s.sizing.motor_nominal_power, 0);
  EXPECT_EQ(s.sizing.motor_omega_nominal, 0);  // the fixture gives critical_slip (way 1)
}

TEST(SceneSizing, AbsentSectionMeansNothingGivenAndKlossDataAreKept) {
  const Scene a = parseSceneText(kMinimalScene, "test.yaml");
  EXPECT_EQ(a.sizing.motor_nominal_torque, 0);
  EXPECT_EQ(a.sizing.target_delta, 0);
  const Scene b = parseSceneText(
      replaced("  critical_slip: 0.1", "  omega_nominal: 102.1\n  overload_ratio: 2.4"), "test.yaml");
  EXPECT_DOUBLE_EQ(b.sizing.motor_omega_nominal, 102.1);
  EXPECT_DOUBLE_EQ(b.sizing.motor_overload_ratio, 2.4);
}

TEST(SceneSizing, NominalPowerNeedsTheNominalSpeed) {
  expectSceneError(kMinimalScene + "sizing:\n  motor_nominal_power: 22000\n",
                   {"test.yaml:25: sizing.motor_nominal_power: expected a nominal power together with "
                    "motor.omega_nominal"});
  const Scene s = parseSceneText(
      replaced("  critical_slip: 0.1", "  omega_nominal: 102.1\n  overload_ratio: 2.4") +
          "sizing:\n  motor_nominal_power: 22000\n",
      "test.yaml");
  EXPECT_DOUBLE_EQ(s.sizing.motor_nominal_power, 22000);
}

TEST(SceneSizing, RejectsBadValuesWithFileLineAndKey) {
  expectSceneError(replaced("    rod_end: 40000", "    rod_end: -1", kMinimalScene + kSizing),
                   {"test.yaml:31: sizing.bearing_rating.rod_end: expected a number > 0 [N]"});
  expectSceneError(replaced("  motor_efficiency: 0.91", "  motor_efficiency: 1.5", kMinimalScene + kSizing),
                   {"test.yaml:26: sizing.motor_efficiency: expected a number in (0, 1]"});
  expectSceneError(replaced("  target_delta: 0.05", "  target_delta: small", kMinimalScene + kSizing),
                   {"test.yaml:27: sizing.target_delta"});
  expectSceneError(kMinimalScene + kSizing + "  motor_nominal_power: 22000\n",
                   {"sizing.motor_nominal_power: expected at most one of sizing.motor_nominal_torque and "
                    "sizing.motor_nominal_power"});
  expectSceneError(replaced("    crank_pin: 120000", "    crank_pn: 120000", kMinimalScene + kSizing),
                   {"test.yaml:32: sizing.bearing_rating.crank_pn", "did you mean 'crank_pin'?"});
}

TEST(SceneSizing, FatigueCurvesAndCouplingRatingsReachTheScene) {
  const Scene s = parseSceneText(kMinimalScene +
                                     "sizing:\n"
                                     "  fatigue:\n"
                                     "    rod_force: {endurance_amplitude: 20000, knee_cycles: 2.0e+6, slope: 5, ultimate: 1.0e+6}\n"
                                     "    below_knee: cutoff\n"
                                     "    required_starts: 1000\n"
                                     "  coupling: {rated_torque: 5000, damping_power: 300, temperature_factor: 1.4}\n",
                                 "test.yaml");
  EXPECT_DOUBLE_EQ(s.sizing.fatigue.rod_force.endurance_amplitude, 20000);
  EXPECT_DOUBLE_EQ(s.sizing.fatigue.rod_force.knee_cycles, 2e6);
  EXPECT_DOUBLE_EQ(s.sizing.fatigue.rod_force.slope, 5);
  EXPECT_DOUBLE_EQ(s.sizing.fatigue.rod_force.ultimate, 1e6);
  EXPECT_FALSE(s.sizing.fatigue.coupling_torque.given());
  EXPECT_FALSE(s.sizing.fatigue.haibach);
  EXPECT_DOUBLE_EQ(s.sizing.fatigue.required_starts, 1000);
  EXPECT_DOUBLE_EQ(s.sizing.coupling.rated_torque, 5000);
  EXPECT_DOUBLE_EQ(s.sizing.coupling.damping_power, 300);
  EXPECT_DOUBLE_EQ(s.sizing.coupling.temperature_factor, 1.4);
  EXPECT_DOUBLE_EQ(s.sizing.coupling.start_factor, 1.0);  // the factors default to 1
  const Scene a = parseSceneText(kMinimalScene, "test.yaml");
  EXPECT_TRUE(a.sizing.fatigue.haibach);
  EXPECT_FALSE(a.sizing.coupling.anyGiven());
}

TEST(SceneSizing, AnSnCurveNeedsItsKneeAndSlopeTogether) {
  expectSceneError(kMinimalScene + "sizing:\n  fatigue:\n    coupling_torque: {endurance_amplitude: 900, knee_cycles: 1.0e+6}\n",
                   {"sizing.fatigue.coupling_torque.slope", "all three of"});
  expectSceneError(kMinimalScene + "sizing:\n  coupling: {temperature_factor: 0.8}\n",
                   {"sizing.coupling.temperature_factor: expected a number in [1, 10]"});
}

// Two rated torques of one coupling would give two verdicts that can disagree: the single rating
// against the largest peak, or the makers' T_KN / T_Kmax, never both. The makers' vibratory torque
// and damping power sit beside the single rating (no rating of theirs repeats it).
TEST(SceneSizing, TheCouplingIsRatedOneWayOnly) {
  expectSceneError(kMinimalScene + kSizing + "  coupling: {rated_torque: 9000}\n",
                   {"sizing.coupling_rated_torque: expected either sizing.coupling_rated_torque", "not both"});
  expectSceneError(kMinimalScene + kSizing + "  coupling: {max_torque: 20000}\n",
                   {"sizing.coupling_rated_torque: expected either"});
  const Scene s = parseSceneText(kMinimalScene + kSizing + "  coupling: {vibratory_torque: 2000}\n", "test.yaml");
  EXPECT_DOUBLE_EQ(s.sizing.coupling.vibratory_torque, 2000);
}

TEST(SceneSizing, OverridesReachTheSizingSection) {
  const Scene s = parseSceneText(kMinimalScene, "test.yaml", {"sizing.target_delta=0.08"});
  EXPECT_DOUBLE_EQ(s.sizing.target_delta, 0.08);
}

}  // namespace
}  // namespace rollerdyn
