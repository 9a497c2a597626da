// The motor section of a scene file: Kloss's breakdown torque and critical slip, motor.model,
// the rated supply, and the machine as an equivalent circuit (motor.circuit.*) or as catalogue
// data (motor.catalogue.*). Rules coupling several keys live here; single keys' types and
// ranges are in the schema (SceneSchema.cpp).
#include <cmath>
#include <string>
#include <vector>

#include "scene/MotorModels.h"
#include "scene/SceneReader.h"

namespace rollerdyn::scene_detail {

namespace {

// ω0 printed to a few digits (104.72 for 2π·50/3 = 104.7198) must still count as 2π·f/p.
constexpr double kSyncSpeedTolerance = 1e-3;

const char* const kCatalogueValueKeys[] = {
    "motor.catalogue.power",        "motor.catalogue.omega_nominal",
    "motor.catalogue.current",      "motor.catalogue.power_factor",
    "motor.catalogue.efficiency",   "motor.catalogue.starting_torque_ratio",
    "motor.catalogue.breakdown_torque_ratio", "motor.catalogue.starting_current_ratio"};
const char* const kCircuitKeys[] = {"motor.circuit.R_s", "motor.circuit.L_sigma_s", "motor.circuit.L_m",
                                    "motor.circuit.R_r", "motor.circuit.L_sigma_r"};

// The catalogue's rated speed below ω0, and a single cage's breakdown torque above its starting
// torque (its torque at standstill is always below its maximum).
void checkCatalogue(const Reader& in, const MotorCatalogue& c, double omega0) {
  if (c.omega_nominal >= omega0) {
    const std::string w0 = formatNumber(omega0);
    if (blameSecond(in.doc(), "motor.catalogue.omega_nominal", "motor.omega_sync"))
      in.doc().fail("motor.omega_sync", "a number > motor.catalogue.omega_nominal = " +
                                            formatNumber(c.omega_nominal) + " [rad/s]", w0);
    in.doc().fail("motor.catalogue.omega_nominal", "a number in (0, omega_sync = " + w0 + ") [rad/s]",
                  formatNumber(c.omega_nominal));
  }
  if (c.breakdown_torque_ratio <= c.starting_torque_ratio && c.cages == 1) {
    in.doc().fail("motor.catalogue.breakdown_torque_ratio",
                  "a ratio above starting_torque_ratio = " + formatNumber(c.starting_torque_ratio),
                  formatNumber(c.breakdown_torque_ratio));
  }
}

// All catalogue values, or none: a fit to part of a data sheet would be underdetermined.
MotorCatalogue readCatalogue(const Reader& in, double omega0) {
  MotorCatalogue c;
  c.cages = in.integer("motor.catalogue.cages");
  std::string first;
  for (const char* k : kCatalogueValueKeys)
    if (first.empty() && in.has(k)) first = k;
  if (first.empty()) return c;
  const std::string why = "the catalogue is given (" + first + "): all of power, omega_nominal, current, "
                          "power_factor, efficiency, starting_torque_ratio, breakdown_torque_ratio, "
                          "starting_current_ratio";
  c.power = in.requiredNumber("motor.catalogue.power", why);
  c.omega_nominal = in.requiredNumber("motor.catalogue.omega_nominal", why);
  c.current = in.requiredNumber("motor.catalogue.current", why);
  c.power_factor = in.requiredNumber("motor.catalogue.power_factor", why);
  c.efficiency = in.requiredNumber("motor.catalogue.efficiency", why);
  c.starting_torque_ratio = in.requiredNumber("motor.catalogue.starting_torque_ratio", why);
  c.breakdown_torque_ratio = in.requiredNumber("motor.catalogue.breakdown_torque_ratio", why);
  c.starting_current_ratio = in.requiredNumber("motor.catalogue.starting_current_ratio", why);
  checkCatalogue(in, c, omega0);
  return c;
}

MotorCircuit readCircuit(const Reader& in) {
  MotorCircuit c;
  std::string first;
  for (const char* k : kCircuitKeys)
    if (first.empty() && in.has(k)) first = k;
  const bool second_cage = in.has("motor.circuit.R_r2") || in.has("motor.circuit.L_sigma_r2");
  if (first.empty() && !second_cage) return c;
  if (first.empty()) first = in.has("motor.circuit.R_r2") ? "motor.circuit.R_r2" : "motor.circuit.L_sigma_r2";
  const std::string why = "the equivalent circuit is given (" + first + "): all of R_s, L_sigma_s, L_m, R_r, "
                          "L_sigma_r";
  c.R_s = in.requiredNumber("motor.circuit.R_s", why);
  c.L_sigma_s = in.requiredNumber("motor.circuit.L_sigma_s", why);
  c.L_m = in.requiredNumber("motor.circuit.L_m", why);
  c.R_r = in.requiredNumber("motor.circuit.R_r", why);
  c.L_sigma_r = in.requiredNumber("motor.circuit.L_sigma_r", why);
  if (second_cage) {
    const std::string why2 = "a second cage needs both R_r2 and L_sigma_r2";
    c.R_r2 = in.requiredNumber("motor.circuit.R_r2", why2);
    c.L_sigma_r2 = in.requiredNumber("motor.circuit.L_sigma_r2", why2);
  }
  return c;
}

const char* const kSlipWays =
    "exactly one of motor.critical_slip, motor.omega_critical, or motor.omega_nominal + motor.overload_ratio";

// The first key of each way of giving Kloss's critical slip present in the file, in schema order;
// two descriptions could disagree, so more than one is refused rather than one picked silently.
std::vector<std::string> slipWaysGiven(const Reader& in) {
  std::vector<std::string> given;
  if (in.has("motor.critical_slip")) given.push_back("motor.critical_slip");
  if (in.has("motor.omega_critical")) given.push_back("motor.omega_critical");
  if (in.has("motor.omega_nominal")) given.push_back("motor.omega_nominal");
  else if (in.has("motor.overload_ratio")) given.push_back("motor.overload_ratio");
  if (given.size() > 1) {
    // Blame the one a --set added, if any (the latest), else the second in schema order.
    const SceneDocument& doc = in.doc();
    size_t blamed = 1;
    for (size_t i = 0; i < given.size(); ++i)
      if (doc.overrideFor(given[i]) > doc.overrideFor(given[blamed])) blamed = i;
    const std::string& other = given[blamed == 0 ? 1 : 0];
    doc.fail(given[blamed], std::string(kSlipWays) + " (" + other + " is given too)",
             describeNode(doc.find(given[blamed])));
  }
  return given;
}

// s_kr = s_n·(λ + √(λ² − 1)) from the nominal speed and the overload ratio (Loveikin, Pochka,
// Romasevych (2018) eq. (37)).
double slipFromOverloadRatio(const Reader& in, double omega0) {
  const SceneDocument& doc = in.doc();
  const double w_n = in.requiredNumber("motor.omega_nominal", "required with motor.overload_ratio");
  const double lambda = in.requiredNumber("motor.overload_ratio", "required with motor.omega_nominal");
  if (w_n >= omega0)
    doc.fail("motor.omega_nominal", "a number in (0, omega_sync = " + formatNumber(omega0) + ") [rad/s]",
             formatNumber(w_n));
  const double s_n = 1.0 - w_n / omega0;
  const double s_kr = s_n * (lambda + std::sqrt(lambda * lambda - 1.0));
  if (s_kr >= 1.0)
    doc.fail("motor.overload_ratio",
             "a value giving critical slip s_kr = s_n(lambda + sqrt(lambda^2 - 1)) < 1 with s_n = " +
                 formatNumber(s_n),
             formatNumber(lambda) + " (s_kr = " + formatNumber(s_kr) + ")");
  return s_kr;
}

// Kloss's critical slip from exactly one of three equivalent descriptions, or -1 when none is
// given and the caller may derive it (from the catalogue).
double readCriticalSlip(const Reader& in, double omega0, bool may_be_absent) {
  const std::vector<std::string> given = slipWaysGiven(in);
  if (given.empty() && may_be_absent) return -1.0;
  if (given.empty()) in.doc().failMissing("motor.critical_slip", kSlipWays);
  const std::string& way = given[0];
  if (way == "motor.critical_slip") return in.number(way);  // range (0, 1) from the schema
  if (way == "motor.omega_critical") {
    const double w_kr = in.number(way);
    if (w_kr >= omega0)
      in.doc().fail(way, "a number in (0, omega_sync = " + formatNumber(omega0) + ") [rad/s]", formatNumber(w_kr));
    return 1.0 - w_kr / omega0;  // Loveikin and Pochka (2007) eq. (7)
  }
  return slipFromOverloadRatio(in, omega0);
}

// What omega_sync should be for the frequency f [Hz]: with p given, the speed it implies; without
// it, p was inferred from the wrong ω0 itself, so the speeds of the usual pole pairs are the useful hint.
std::string syncSpeedWanted(const Reader& in, double f, int p) {
  const double w1 = 2.0 * M_PI * f;
  if (in.has("motor.pole_pairs"))
    return "omega_sync = 2·pi·f_n/p (" + formatNumber(w1 / p) + " rad/s with f_n = " + formatNumber(f) +
           " Hz, p = " + std::to_string(p) + ") within 0.1 %";
  std::string want = "omega_sync = 2·pi·f_n/p within 0.1 % at f_n = " + formatNumber(f) + " Hz:";
  for (int q = 1; q <= 4; ++q)
    want += std::string(q > 1 ? "," : "") + " " + formatNumber(w1 / q) + " rad/s (p = " + std::to_string(q) + ")";
  want += ", ... (motor.pole_pairs)";
  return want;
}

// ω0 [rad/s] that disagrees with 2π·f_n/p: a --set of p or f_n is blamed for it, else ω0.
[[noreturn]] void failSyncSpeed(const Reader& in, double omega0, double f, int p) {
  const SceneDocument& doc = in.doc();
  if (in.has("motor.pole_pairs") && blameSecond(doc, "motor.omega_sync", "motor.pole_pairs"))
    doc.fail("motor.pole_pairs", "p with 2·pi·f_n/p = omega_sync = " + formatNumber(omega0) + " rad/s",
             std::to_string(p));
  if (blameSecond(doc, "motor.omega_sync", "motor.frequency"))
    doc.fail("motor.frequency", "f_n with 2·pi·f_n/p = omega_sync = " + formatNumber(omega0) + " rad/s",
             formatNumber(f));
  doc.fail("motor.omega_sync", syncSpeedWanted(in, f, p), formatNumber(omega0));
}

// Pole pairs: given, or the whole number nearest 2π·f_n/ω0. Checked against ω0 only where a law
// uses them (circuit, park, or machine data given), so Kloss scenes with any ω0 stay valid.
int readPolePairs(const Reader& in, double omega0, double f, bool checked) {
  const double w1 = 2.0 * M_PI * f;
  const int p = in.has("motor.pole_pairs") ? in.integer("motor.pole_pairs")
                                           : std::max(1, static_cast<int>(std::lround(w1 / omega0)));
  if (!checked) return p;
  const double w0_of_p = w1 / p;
  if (std::abs(w0_of_p - omega0) > kSyncSpeedTolerance * omega0) failSyncSpeed(in, omega0, f, p);
  return p;
}

// Each motor law's own keys (numbers), whichever law runs: their values or defaults into `im`.
void readLawsOwnKeys(const Reader& in, InductionMotor& im) {
  for (const MotorModelInfo& law : motorModelTable())
    for (const MotorLawKey& own : law.own_keys) {
      const KeySpec key = own.spec();
      im.*own.field = in.numberOr(key.path, key.default_number);
    }
}

// The law and the machine data it needs: a machine law (circuit, park) needs motor.catalogue or
// motor.circuit; machine data need the voltage (the current scale of the circuit and of the fit:
// I_n is at U_n) and pole pairs that agree with ω0.
void readMachine(const Reader& in, double omega0, InductionMotor& im) {
  im.model = in.choiceOf<MotorModel>("motor.model");
  readLawsOwnKeys(in, im);
  im.frequency = in.number("motor.frequency");
  im.connection = in.choiceOf<WindingConnection>("motor.connection");
  im.catalogue = readCatalogue(in, omega0);
  im.circuit = readCircuit(in);
  const bool machine_law = isMachineLaw(im.model);
  const bool machine_data = im.catalogue.given() || im.circuit.given();
  im.pole_pairs = readPolePairs(in, omega0, im.frequency, machine_law || machine_data);
  if (machine_law && !machine_data)
    in.doc().fail("motor.model", motorModelWords(true, "or") + ", or the machine as motor.circuit.* or "
                                 "motor.catalogue.* (motor.model " + toString(im.model) + " needs one)",
                  toString(im.model));
  if (!machine_law && !machine_data) {
    im.voltage = in.numberOr("motor.voltage", 0.0);
    return;
  }
  im.voltage = in.requiredNumber("motor.voltage", machine_law ? std::string("required for motor.model ") +
                                                                    toString(im.model)
                                                              : "required with motor.circuit or motor.catalogue");
}

// Kloss's M_kr and s_kr through the catalogue's breakdown point: M_kr = (M_k/M_n)·P_n/ω_n and
// s_kr = s_n(λ + √(λ² − 1)), s_n = 1 − ω_n/ω0 (Loveikin, Pochka, Romasevych (2018) eq. (37)).
void klossFromCatalogue(const Reader& in, const MotorCatalogue& c, KlossMotor& m) {
  const double lambda = c.breakdown_torque_ratio, s_n = 1.0 - c.omega_nominal / m.omega_sync;
  m.breakdown_torque = lambda * c.nominalTorque();
  m.critical_slip = s_n * (lambda + std::sqrt(lambda * lambda - 1.0));
  if (m.critical_slip >= 1.0)
    in.doc().fail("motor.catalogue.breakdown_torque_ratio",
                  "a ratio giving Kloss's critical slip s_n(lambda + sqrt(lambda^2 - 1)) < 1 with s_n = " +
                      formatNumber(s_n) + " (or give motor.breakdown_torque and the critical slip)",
                  formatNumber(lambda));
}

// Kloss's M_kr and s_kr: as given; else, with a catalogue, both through its breakdown point.
void readKlossPoint(const Reader& in, const InductionMotor& im, KlossMotor& m) {
  const SceneDocument& doc = in.doc();
  const bool derive = im.catalogue.given() && !in.has("motor.breakdown_torque");
  const double s_kr = readCriticalSlip(in, m.omega_sync, derive);
  if (derive) {
    if (s_kr > 0)
      doc.fail("motor.breakdown_torque",
               "a breakdown torque M_kr with the critical slip given (or neither: both from motor.catalogue)",
               "nothing (key missing)");
    klossFromCatalogue(in, im.catalogue, m);
    return;
  }
  if (!in.has("motor.breakdown_torque"))
    doc.failMissing("motor.breakdown_torque", describeExpected(*findSceneKey("motor.breakdown_torque")) +
                                                  " (required unless motor.catalogue is given)");
  m.breakdown_torque = in.number("motor.breakdown_torque");
  m.critical_slip = s_kr;
}

}  // namespace

void readMotor(const Reader& in, KlossMotor& m, InductionMotor& im) {
  m.enabled = in.flag("motor.enabled");
  m.omega_sync = in.number("motor.omega_sync");
  m.rotor_inertia = in.number("motor.rotor_inertia");
  readMachine(in, m.omega_sync, im);
  readKlossPoint(in, im, m);
}

}  // namespace rollerdyn::scene_detail
