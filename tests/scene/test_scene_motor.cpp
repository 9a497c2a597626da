// The motor section beyond Kloss: motor.model, rated supply, equivalent circuit and catalogue
// keys reach the Scene, coupled-key rules are enforced with file, line and key, and Kloss's
// numbers are derived from the catalogue only when the scene gives no Kloss data.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "SceneTestSupport.h"
#include "scene/SceneParser.h"

namespace rollerdyn {
namespace {

using test::expectSceneError;
using test::kMinimalScene;
using test::replaced;
using test::without;

// Appended after line 18 (rotor_inertia): keys of the motor map.
std::string withMotorKeys(const std::string& keys, const std::string& base = kMinimalScene) {
  return replaced("  rotor_inertia: 0.138", "  rotor_inertia: 0.138\n" + keys, base);
}

const std::string kCatalogue =
    "  voltage: 380\n"                   // 19
    "  catalogue:\n"                     // 20
    "    power: 22000\n"                 // 21
    "    omega_nominal: 102.1\n"         // 22
    "    current: 41.5\n"                // 23
    "    power_factor: 0.9\n"            // 24
    "    efficiency: 0.9\n"              // 25
    "    starting_torque_ratio: 1.3\n"   // 26
    "    breakdown_torque_ratio: 2.4\n"  // 27
    "    starting_current_ratio: 6.5";   // 28

const std::string kCircuit =
    "  voltage: 173.2\n"
    "  circuit:\n"
    "    R_s: 0.03\n"
    "    L_sigma_s: 0.000324\n"
    "    L_m: 0.009226\n"
    "    R_r: 0.04\n"
    "    L_sigma_r: 0.000324";

TEST(SceneMotor, DefaultsKeepTheStaticKlossLaw) {
  const Scene s = parseSceneText(kMinimalScene, "test.yaml");
  EXPECT_EQ(s.induction.model, MotorModel::Kloss);
  EXPECT_DOUBLE_EQ(s.induction.frequency, 50.0);
  EXPECT_EQ(s.induction.connection, WindingConnection::Star);
  EXPECT_EQ(s.induction.pole_pairs, 3);  // round(2π·50/104.72)
  EXPECT_FALSE(s.induction.circuit.given());
  EXPECT_FALSE(s.induction.catalogue.given());
  EXPECT_EQ(s.induction.torque_time_constant, 0.0);
}

TEST(SceneMotor, CatalogueKeysDoNotChangeGivenKlossData) {
  const Scene plain = parseSceneText(kMinimalScene, "test.yaml");
  const Scene with = parseSceneText(withMotorKeys(kCatalogue), "test.yaml");
  EXPECT_EQ(with.motor.breakdown_torque, plain.motor.breakdown_torque);
  EXPECT_EQ(with.motor.critical_slip, plain.motor.critical_slip);
  EXPECT_EQ(with.motor.omega_sync, plain.motor.omega_sync);
  EXPECT_TRUE(with.induction.catalogue.given());
  EXPECT_DOUBLE_EQ(with.induction.catalogue.nominalTorque(), 22000 / 102.1);
  EXPECT_EQ(with.induction.catalogue.cages, 2);
}

TEST(SceneMotor, KlossFromTheCatalogueWhenNotGiven) {
  std::string text = without("  breakdown_torque: 215.4", without("  critical_slip: 0.1"));
  const Scene s = parseSceneText(withMotorKeys(kCatalogue, text), "test.yaml");
  const double m_n = 22000 / 102.1, s_n = 1 - 102.1 / 104.72;
  EXPECT_DOUBLE_EQ(s.motor.breakdown_torque, 2.4 * m_n);
  EXPECT_DOUBLE_EQ(s.motor.critical_slip, s_n * (2.4 + std::sqrt(2.4 * 2.4 - 1)));
}

TEST(SceneMotor, BreakdownTorqueStillRequiredWithoutCatalogue) {
  expectSceneError(without("  breakdown_torque: 215.4"),
                   {"test.yaml:14: motor.breakdown_torque:", "required unless motor.catalogue is given",
                    "nothing (key missing)"});
}

TEST(SceneMotor, CriticalSlipWithoutBreakdownTorqueIsRefusedWithCatalogue) {
  expectSceneError(withMotorKeys(kCatalogue, without("  breakdown_torque: 215.4")),
                   {"motor.breakdown_torque:", "with the critical slip given"});
}

TEST(SceneMotor, EveryModelWordParses) {
  for (const char* w : {"kloss", "kloss_dynamic", "circuit", "park"}) {
    const Scene s = parseSceneText(withMotorKeys(std::string("  model: ") + w + "\n" + kCircuit), "t.yaml");
    EXPECT_STREQ(toString(s.induction.model), w);
  }
  // A misspelt word is refused, with the closest one suggested (the second trial's parkk and
  // star-delta got none).
  expectSceneError(withMotorKeys("  model: parks"), {"test.yaml:19: motor.model: expected one of: kloss, "
                                                     "kloss_dynamic, circuit, park, got parks (did you mean 'park'?)"});
}

// The effects a scene builds (console, summary.json, bench) name the motor by its law.
TEST(SceneMotor, EffectsNameTheMotorByItsLaw) {
  for (const char* w : {"kloss", "kloss_dynamic", "circuit", "park"}) {
    const Scene s = parseSceneText(withMotorKeys(std::string("  model: ") + w + "\n" + kCircuit), "t.yaml");
    const std::vector<std::string> e = s.effects();
    EXPECT_EQ(e.front(), std::string(w) + "_motor");
    EXPECT_EQ(std::count_if(e.begin(), e.end(), [](const std::string& x) { return x.find("motor") != std::string::npos; }),
              1);
  }
  const Scene off = parseSceneText(withMotorKeys("  enabled: false"), "t.yaml");
  for (const std::string& x : off.effects()) EXPECT_EQ(x.find("motor"), std::string::npos) << x;
}

TEST(SceneMotor, MachineModelNeedsCircuitOrCatalogue) {
  expectSceneError(withMotorKeys("  model: park\n  voltage: 380"),
                   {"test.yaml:19: motor.model:", "motor.circuit.* or motor.catalogue.*", "got park"});
}

TEST(SceneMotor, MachineModelNeedsTheVoltage) {
  std::string circuit_without_voltage = kCircuit.substr(kCircuit.find('\n') + 1);
  expectSceneError(withMotorKeys("  model: circuit\n" + circuit_without_voltage),
                   {"motor.voltage:", "required for motor.model circuit", "nothing (key missing)"});
}

TEST(SceneMotor, CircuitKeysComeTogether) {
  expectSceneError(withMotorKeys("  voltage: 380\n  circuit:\n    R_s: 0.03\n    L_m: 0.01"),
                   {"motor.circuit.L_sigma_s:", "the equivalent circuit is given (motor.circuit.R_s)"});
  expectSceneError(withMotorKeys(kCircuit + "\n    R_r2: 0.2"),
                   {"motor.circuit.L_sigma_r2:", "a second cage needs both R_r2 and L_sigma_r2"});
  const Scene s = parseSceneText(withMotorKeys(kCircuit + "\n    R_r2: 0.2\n    L_sigma_r2: 0.0001"), "t.yaml");
  EXPECT_TRUE(s.induction.circuit.doubleCage());
  EXPECT_DOUBLE_EQ(s.induction.circuit.R_r2, 0.2);
}

TEST(SceneMotor, CatalogueKeysComeTogether) {
  expectSceneError(withMotorKeys("  voltage: 380\n  catalogue:\n    power: 22000\n    current: 41.5"),
                   {"motor.catalogue.omega_nominal:", "the catalogue is given (motor.catalogue.power)"});
}

TEST(SceneMotor, CatalogueNominalSpeedBelowSynchronous) {
  std::string c = kCatalogue;
  c.replace(c.find("102.1"), 5, "105.0");
  expectSceneError(withMotorKeys(c), {"test.yaml:22: motor.catalogue.omega_nominal:",
                                      "a number in (0, omega_sync = 104.72) [rad/s], got 105"});
}

TEST(SceneMotor, CatalogueRangesComeFromTheSchema) {
  std::string c = kCatalogue;
  c.replace(c.find("0.9\n"), 3, "1.2");
  expectSceneError(withMotorKeys(c), {"test.yaml:24: motor.catalogue.power_factor:", "in (0, 1)", "got 1.2"});
}

TEST(SceneMotor, PolePairsMustMatchTheSynchronousSpeed) {
  expectSceneError(withMotorKeys(kCircuit + "\n  pole_pairs: 2"),
                   {"motor.omega_sync:", "2·pi·f_n/p (157.079632679 rad/s", "got 104.72"});
  // Without machine data a Kloss scene is not held to it (old scenes with any ω0 stay valid).
  const Scene s = parseSceneText(withMotorKeys("  pole_pairs: 2"), "t.yaml");
  EXPECT_EQ(s.induction.pole_pairs, 2);
  // Without pole_pairs the hint lists the synchronous speeds of the usual pole pairs (a p inferred
  // from the wrong ω0 itself would point at p = 1 whatever the machine).
  expectSceneError(withMotorKeys(kCircuit), {"motor.omega_sync:", "314.159265359 rad/s (p = 1), 157.079632679 rad/s (p = 2), 104.719755" , "got 1000"},
                   {"motor.omega_sync=1000"});
  // --set of the frequency is blamed as the override that broke the rule.
  expectSceneError(withMotorKeys(kCircuit), {"--set #1 (motor.frequency=60)", "motor.frequency:"},
                   {"motor.frequency=60"});
}

TEST(SceneMotor, DynamicKlossTimeConstantAndSupplyReachTheScene) {
  const Scene s = parseSceneText(
      withMotorKeys("  model: kloss_dynamic\n  torque_time_constant: 0.02\n  connection: delta\n  frequency: 50"),
      "t.yaml");
  EXPECT_EQ(s.induction.model, MotorModel::KlossDynamic);
  EXPECT_DOUBLE_EQ(s.induction.torque_time_constant, 0.02);
  EXPECT_EQ(s.induction.connection, WindingConnection::Delta);
  expectSceneError(withMotorKeys("  torque_time_constant: 0"),
                   {"test.yaml:19: motor.torque_time_constant: expected a number > 0 [s], got 0"});
}

TEST(SceneMotor, OverridesReachTheMotorKeys) {
  const Scene s = parseSceneText(withMotorKeys(kCircuit), "t.yaml", {"motor.model=park", "motor.circuit.R_s=0.05"});
  EXPECT_EQ(s.induction.model, MotorModel::Park);
  EXPECT_DOUBLE_EQ(s.induction.circuit.R_s, 0.05);
  EXPECT_NEAR(s.induction.phaseVoltage(), 100.0, 0.01);
}

}  // namespace
}  // namespace rollerdyn

namespace rollerdyn {
namespace {

// The papers' scenes carry catalogue data for the other motor laws, yet stay on the static
// Kloss law with exactly the printed Kloss numbers.
TEST(SceneMotor, PaperScenesKeepKlossAndThePrintedNumbers) {
  const std::string dir = std::string(ROLLERDYN_SOURCE_DIR) + "/model/";
  const Scene a = parseSceneFile(dir + "balanced-4cart.yaml");
  EXPECT_EQ(a.induction.model, MotorModel::Kloss);
  EXPECT_EQ(a.motor.breakdown_torque, 517.14);
  const double s_n = 1 - 102.1 / 104.72;
  EXPECT_EQ(a.motor.critical_slip, s_n * (2.4 + std::sqrt(2.4 * 2.4 - 1.0)));
  ASSERT_TRUE(a.induction.catalogue.given());
  EXPECT_NEAR(a.induction.catalogue.starting_torque_ratio * a.induction.catalogue.nominalTorque(), 280.1, 0.05);
  const Scene b = parseSceneFile(dir + "energy-balanced-3cart.yaml");
  EXPECT_EQ(b.induction.model, MotorModel::Kloss);
  EXPECT_EQ(b.motor.breakdown_torque, 293.8);
  EXPECT_EQ(b.motor.critical_slip, 1.0 - 94.95 / 104.72);
  ASSERT_TRUE(b.induction.catalogue.given());
  EXPECT_NEAR(b.induction.catalogue.nominalTorque(), 146.9, 0.05);
  EXPECT_EQ(b.induction.pole_pairs, 3);
}

}  // namespace
}  // namespace rollerdyn
