// sizing.*: the ratings and data the drive sizing and the sign-off read (SizingInputs.h): the
// motor's nominal point, the bearings', the coupling's and the reducer's ratings, the fatigue
// curves, the gear application factor after ISO 6336-6 and the motor's starts after IEC 60034-1
// (analysis/ reads them).
#include "scene/SceneReader.h"

namespace rollerdyn::scene_detail {

namespace {

void readGearAndDutyRatings(const Reader& in, SizingInputs& z) {
  ReducerRatings& r = z.reducer;
  r.application_factor = in.number("sizing.reducer.application_factor");
  r.rated_torque = in.number("sizing.reducer.rated_torque");
  r.max_torque = in.number("sizing.reducer.max_torque");
  r.sn_exponent = in.number("sizing.reducer.sn_exponent");
  MotorDutyRatings& m = z.motor;
  m.locked_rotor_time = in.number("sizing.motor.locked_rotor_time");
  m.no_load_starts = in.number("sizing.motor.no_load_starts");
}

SnCurve readSnCurve(const Reader& in, const std::string& prefix) {
  SnCurve c;
  c.endurance_amplitude = in.number(prefix + ".endurance_amplitude");
  c.knee_cycles = in.number(prefix + ".knee_cycles");
  c.slope = in.number(prefix + ".slope");
  c.ultimate = in.number(prefix + ".ultimate");
  const bool any = c.endurance_amplitude > 0 || c.knee_cycles > 0 || c.slope > 0 || c.ultimate > 0;
  for (const char* k : {".endurance_amplitude", ".knee_cycles", ".slope"})
    if (any && !in.has(prefix + k))
      in.doc().fail(prefix + k,
                    "all three of " + prefix + ".endurance_amplitude, .knee_cycles and .slope (an S-N curve needs "
                    "its knee S_D at N_D cycles and its slope m)",
                    "not given");
  return c;
}

FatigueInputs readFatigue(const Reader& in) {
  FatigueInputs f;
  f.coupling_torque = readSnCurve(in, "sizing.fatigue.coupling_torque");
  f.rod_force = readSnCurve(in, "sizing.fatigue.rod_force");
  f.haibach = in.choice("sizing.fatigue.below_knee") != "cutoff";
  f.required_starts = in.number("sizing.fatigue.required_starts");
  f.required_hours = in.number("sizing.fatigue.required_hours");
  return f;
}

CouplingRatings readCouplingRatings(const Reader& in) {
  CouplingRatings c;
  c.rated_torque = in.number("sizing.coupling.rated_torque");
  c.max_torque = in.number("sizing.coupling.max_torque");
  c.vibratory_torque = in.number("sizing.coupling.vibratory_torque");
  c.damping_power = in.number("sizing.coupling.damping_power");
  c.temperature_factor = in.number("sizing.coupling.temperature_factor");
  c.start_factor = in.number("sizing.coupling.start_factor");
  c.shock_factor = in.number("sizing.coupling.shock_factor");
  return c;
}

// Ratings and targets of the sizing answers (SizingInputs.h); absent keys stay 0 = not given.
// Ratings that could contradict each other are refused.
void checkSizingRatings(const Reader& in, const SizingInputs& z) {
  // One rated torque of the coupling: the single rating against the run's largest peak, or the
  // makers' T_KN and T_Kmax against the steady and the start's peaks (two verdicts from two
  // ratings of the same coupling could contradict each other).
  if (z.coupling_rated_torque > 0 && (z.coupling.rated_torque > 0 || z.coupling.max_torque > 0))
    in.doc().fail("sizing.coupling_rated_torque",
                  "either sizing.coupling_rated_torque (one rating against the run's largest peak) or the makers' "
                  "sizing.coupling.rated_torque / max_torque (T_KN against the steady peak, T_Kmax against the "
                  "start's, DIN 740-2), not both (they could disagree)",
                  formatNumber(z.coupling_rated_torque));
  if (z.motor_nominal_torque > 0 && z.motor_nominal_power > 0)
    in.doc().fail("sizing.motor_nominal_power",
                  "at most one of sizing.motor_nominal_torque and sizing.motor_nominal_power "
                  "(they could disagree)",
                  formatNumber(z.motor_nominal_power));
  if (z.motor_nominal_power > 0 && !(z.motor_omega_nominal > 0))
    in.doc().fail("sizing.motor_nominal_power",
                  "a nominal power together with motor.omega_nominal (M_n = P_n/omega_n)",
                  formatNumber(z.motor_nominal_power) + " without motor.omega_nominal");
}

}  // namespace

SizingInputs readSizing(const Reader& in) {
  SizingInputs z;
  z.motor_nominal_torque = in.number("sizing.motor_nominal_torque");
  z.motor_nominal_power = in.number("sizing.motor_nominal_power");
  z.motor_efficiency = in.number("sizing.motor_efficiency");
  z.starts_per_hour = in.number("sizing.starts_per_hour");
  z.target_delta = in.number("sizing.target_delta");
  z.coupling_rated_torque = in.number("sizing.coupling_rated_torque");
  z.rating_guide_roller = in.number("sizing.bearing_rating.guide_roller");
  z.rating_rod_end = in.number("sizing.bearing_rating.rod_end");
  z.rating_crank_pin = in.number("sizing.bearing_rating.crank_pin");
  z.rating_main_bearing = in.number("sizing.bearing_rating.main_bearing");
  z.fatigue = readFatigue(in);
  z.coupling = readCouplingRatings(in);
  readGearAndDutyRatings(in, z);
  if (in.has("motor.omega_nominal")) z.motor_omega_nominal = in.number("motor.omega_nominal");
  if (in.has("motor.overload_ratio")) z.motor_overload_ratio = in.number("motor.overload_ratio");
  checkSizingRatings(in, z);
  return z;
}

}  // namespace rollerdyn::scene_detail
