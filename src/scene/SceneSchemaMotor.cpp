// Scene keys of the motor: its characteristic and model, its equivalent circuit, its catalogue data,
// its starting method and switch-off; part of the scene schema (SceneSchema.cpp).
#include "scene/MotorModels.h"
#include "scene/SchemaSections.h"

namespace rollerdyn {

using namespace schema_builders;

namespace {
// motor.model: its words, meanings and sources are the rows of the motor-law table.
KeySpec motorModelKey() {
  std::vector<std::string> words;
  std::string meaning = "law of the motor torque: ", sources;
  for (const MotorModelInfo& law : motorModelTable()) {
    const std::string sep = words.empty() ? "" : "; ";
    meaning += sep + law.word + ", " + law.meaning;
    sources += sep + law.source + " (" + law.word + ")";
    words.push_back(law.word);
  }
  // The default is the first row: the papers' static Kloss formula.
  return choice("motor.model", Presence::Optional, words, words.front(), meaning + " (motor.md)").from(sources);
}

// The characteristic, the rotor and the law, up to motor.model.
std::vector<KeySpec> motorKeysBeforeTheLaws() {
  using P = Presence;
  return {
      KeySpec{"motor.enabled", KeyKind::Flag, "-", P::Optional, anyFinite(), 1.0, "", {},
              "whether the motor torque is applied (false: the machine runs free from its initial "
              "speed)"},
      number("motor.omega_sync", "rad/s", P::Required, positive(), 0.0,
             "synchronous rotor speed ω0")
          .from(L2018 + " eq. (37)"),
      number("motor.breakdown_torque", "N·m", P::Conditional, positive(), 0.0,
             "breakdown (critical) torque M_kr at the rotor, Kloss's formula")
          .from(L2018 + " eq. (37); " + L2007 + " eq. (7)")
          .when("required unless motor.catalogue is given (then M_k/M_n·P_n/ω_n of the catalogue)"),
      number("motor.critical_slip", "-", P::Conditional, between(0.0, false, 1.0, false), 0.0,
             "critical slip s_kr of the Kloss formula (way 1 of 3)")
          .from(L2018 + " eq. (37)")
          .when("give the critical slip exactly one way"),
      number("motor.omega_critical", "rad/s", P::Conditional, positive(), 0.0,
             "critical rotor speed ω_kr < ω0; s_kr = 1 − ω_kr/ω0 (way 2 of 3)")
          .from(L2007 + " eq. (7)")
          .when("give the critical slip exactly one way"),
      number("motor.omega_nominal", "rad/s", P::Conditional, positive(), 0.0,
             "nominal rotor speed ω_n < ω0, s_n = 1 − ω_n/ω0 (way 3 of 3, with motor.overload_ratio)")
          .from(L2018 + " eq. (37)")
          .when("give the critical slip exactly one way"),
      number("motor.overload_ratio", "-", P::Conditional, between(1.0, false, kInf, false), 0.0,
             "λ = M_kr/M_n (way 3 of 3, with motor.omega_nominal); s_kr = s_n·(λ + √(λ² − 1)) < 1")
          .from(L2018 + " eq. (37)")
          .when("with motor.omega_nominal"),
      number("motor.rotor_inertia", "kg·m²", P::Required, positive(), 0.0,
             "rotor inertia J_p")
          .from(L2018 + " eq. (1)"),
      motorModelKey(),
  };
}

// The rated supply and the winding, after the laws' own keys.
std::vector<KeySpec> motorKeysAfterTheLaws() {
  using P = Presence;
  return {
      number("motor.voltage", "V", P::Conditional, positive(), 0.0,
             "U_n, rated line-to-line RMS voltage")
          .when("required for motor.model " + motorModelWords(false, "and") + ", and with motor.circuit or motor.catalogue"),
      number("motor.frequency", "Hz", P::Optional, positive(), 50.0,
             "f_n, rated supply frequency"),
      choice("motor.connection", P::Optional, {"star", "delta"}, "star",
             "stator winding connection at the rated voltage; the circuit's values are per phase of "
             "the equivalent star either way, delta allows a star-delta start"),
      integer("motor.pole_pairs", P::Conditional, between(1.0, true, 64.0, true), 0.0,
              "p, pole pairs; ω0 must equal 2π·f_n/p where the machine's data are used")
          .when("round(2π·f_n/ω0)"),
  };
}
}  // namespace

// motor.* but the circuit, the catalogue, the start and the stop; the laws' own keys follow
// motor.model.
std::vector<KeySpec> motorSchemaKeys() {
  std::vector<KeySpec> keys = motorKeysBeforeTheLaws();
  for (const MotorModelInfo& law : motorModelTable())
    for (const MotorLawKey& own : law.own_keys) keys.push_back(own.spec());
  for (KeySpec& k : motorKeysAfterTheLaws()) keys.push_back(std::move(k));
  return keys;
}

// motor.circuit.*.
std::vector<KeySpec> motorCircuitSchemaKeys() {
  using P = Presence;
  return {
      number("motor.circuit.R_s", "Ω", P::Conditional, nonNegative(), 0.0,
             "stator resistance per phase of the equivalent star")
          .from("Pedra (2008) fig. 1")
          .when("the five running-cage values together, or none"),
      number("motor.circuit.L_sigma_s", "H", P::Conditional, positive(), 0.0,
             "stator leakage inductance per phase of the equivalent star")
          .from("Pedra (2008) fig. 1")
          .when("the five running-cage values together, or none"),
      number("motor.circuit.L_m", "H", P::Conditional, positive(), 0.0,
             "magnetizing inductance per phase of the equivalent star")
          .from("Pedra (2008) fig. 1")
          .when("the five running-cage values together, or none"),
      number("motor.circuit.R_r", "Ω", P::Conditional, positive(), 0.0,
             "rotor (first cage) resistance referred to the stator, per phase")
          .from("Pedra (2008) fig. 1")
          .when("the five running-cage values together, or none"),
      number("motor.circuit.L_sigma_r", "H", P::Conditional, positive(), 0.0,
             "rotor (first cage) leakage inductance referred to the stator, per phase")
          .from("Pedra (2008) fig. 1")
          .when("the five running-cage values together, or none"),
      number("motor.circuit.R_r2", "Ω", P::Conditional, positive(), 0.0,
             "second rotor cage's resistance (double cage), referred to the stator, per phase")
          .from("Pedra (2008) fig. 1")
          .when("with motor.circuit.L_sigma_r2, or neither (single cage)"),
      number("motor.circuit.L_sigma_r2", "H", P::Conditional, positive(), 0.0,
             "second rotor cage's leakage inductance (double cage), referred to the stator, per phase")
          .from("Pedra (2008) fig. 1")
          .when("with motor.circuit.R_r2, or neither (single cage)"),
  };
}

// motor.catalogue.*.
std::vector<KeySpec> motorCatalogueSchemaKeys() {
  using P = Presence;
  return {
      number("motor.catalogue.power", "W", P::Conditional, positive(), 0.0, "P_n, rated shaft power")
          .from("the motor's data sheet")
          .when("the eight catalogue values together, or none"),
      number("motor.catalogue.omega_nominal", "rad/s", P::Conditional, positive(), 0.0,
             "ω_n, rated rotor speed (< ω0)")
          .from("the motor's data sheet")
          .when("the eight catalogue values together, or none"),
      number("motor.catalogue.current", "A", P::Conditional, positive(), 0.0,
             "I_n, rated line current at motor.voltage")
          .from("the motor's data sheet")
          .when("the eight catalogue values together, or none"),
      number("motor.catalogue.power_factor", "-", P::Conditional, between(0.0, false, 1.0, false), 0.0,
             "cos φ_n at the rated point")
          .from("the motor's data sheet")
          .when("the eight catalogue values together, or none"),
      number("motor.catalogue.efficiency", "-", P::Conditional, between(0.0, false, 1.0, false), 0.0,
             "η_n at the rated point")
          .from("the motor's data sheet")
          .when("the eight catalogue values together, or none"),
      number("motor.catalogue.starting_torque_ratio", "-", P::Conditional, positive(), 0.0,
             "M_s/M_n, torque at standstill over the rated torque")
          .from("the motor's data sheet")
          .when("the eight catalogue values together, or none"),
      number("motor.catalogue.breakdown_torque_ratio", "-", P::Conditional,
             between(1.0, false, kInf, false), 0.0, "M_k/M_n, largest torque over the rated torque")
          .from("the motor's data sheet")
          .when("the eight catalogue values together, or none"),
      number("motor.catalogue.starting_current_ratio", "-", P::Conditional,
             between(1.0, false, kInf, false), 0.0, "I_s/I_n, current at standstill over the rated current")
          .from("the motor's data sheet")
          .when("the eight catalogue values together, or none"),
      integer("motor.catalogue.cages", P::Optional, between(1.0, true, 2.0, true), 2.0,
              "rotor cages of the circuit fitted to the catalogue (2 honours the starting torque)")
          .from("Pedra (2008)"),
  };
}

// Starting method and switch-off, motor.start.* and motor.stop.* (scene/MotorSwitching.h,
// motor/Supply.h).
std::vector<KeySpec> motorSwitchingSchemaKeys() {
  using P = Presence;
  return {
      choice("motor.start.method", P::Optional,
             {"direct_on_line", "star_delta", "soft_starter", "frequency_converter"}, "direct_on_line",
             "how the motor is switched on and brought up to speed"),
      number("motor.start.t_on", "s", P::Optional, nonNegative(), 0.0, "switch-on time"),
      number("motor.start.phase_deg", "deg", P::Optional, anyFinite(), 0.0,
             "point on the wave at switch-on: angle of the supply voltage phasor (phase a at its peak = 0)"),
      number("motor.start.changeover_time", "s", P::Conditional, positive(), 0.0,
             "star-delta: changeover to delta at this time")
          .when("star_delta: this or motor.start.changeover_speed"),
      number("motor.start.changeover_speed", "rad/s", P::Conditional, positive(), 0.0,
             "star-delta: changeover to delta when the rotor reaches this speed")
          .when("star_delta: this or motor.start.changeover_time"),
      number("motor.start.changeover_gap", "s", P::Optional, nonNegative(), 0.0,
             "star-delta: dead time of the open transition, stator disconnected"),
      number("motor.start.ramp_time", "s", P::Conditional, positive(), 0.0,
             "soft starter, frequency converter: duration t_ramp of the voltage or frequency ramp")
          .when("required with soft_starter and frequency_converter"),
      number("motor.start.initial_voltage", "-", P::Conditional, between(0.0, false, 1.0, true), 0.0,
             "soft starter: U_0/U_n at switch-on")
          .when("required with soft_starter"),
      number("motor.start.current_limit", "A", P::Optional, nonNegative(), 0.0,
             "soft starter: RMS stator phase current I_lim the start is held to, during the ramp and after it, "
             "until the motor draws no more than I_lim at the rated voltage (then the bypass closes: U reaches "
             "U_n continuously); 0 = none (motor models with a current only)"),
      number("motor.start.max_start_time", "s", P::Optional, nonNegative(), 20.0,
             "soft starter with a current limit: a start still current-limited this long after the switch-on "
             "trips the starter (the motor is disconnected, a failed start); must exceed the ramp time; 0 = never "
             "trips. Default 20 s: a typical starter's factory setting of its excess-start-time protection (e.g. "
             "the Digistart D4's), and of the order of a motor's permitted locked-rotor time; set it slightly "
             "longer than a healthy start"),
      number("motor.start.initial_frequency", "Hz", P::Conditional, positive(), 0.0,
             "frequency converter: f_0 at switch-on (< the rated frequency)")
          .when("required with frequency_converter"),
      number("motor.start.boost", "-", P::Optional, between(0.0, true, 1.0, false), 0.0,
             "frequency converter: voltage boost U/U_n at zero frequency, U/U_n = boost + (1 - boost)·f/f_n"),
      number("motor.stop.t_off", "s", P::Optional, positive(), kInf,
             "switch-off time (coast-down); absent = never"),
      number("motor.stop.brake_torque", "N·m", P::Optional, nonNegative(), 0.0,
             "mechanical brake torque on the motor shaft after switch-off, at the rotor; 0 = no brake"),
      number("motor.stop.brake_delay", "s", P::Optional, nonNegative(), 0.0,
             "the brake engages this long after the switch-off"),
      number("motor.stop.t_restart", "s", P::Optional, positive(), kInf,
             "reconnection direct on line at the rated supply after a switch-off (brake released); absent = never"),
  };
}

}  // namespace rollerdyn
