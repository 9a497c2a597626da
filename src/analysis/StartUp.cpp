#include "analysis/StartUp.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "analysis/StallDetector.h"
#include "analysis/StartJointPeaks.h"
#include "analysis/StartUpCurrentLimit.h"
#include "analysis/StartUpRows.h"
#include "motor/BreakdownTorque.h"
#include "motor/Supply.h"
#include "scene/MotorModels.h"
#include "io/FieldFormat.h"

namespace rollerdyn {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kRunUpFraction = 0.95;  // of the steady mean crank speed

const char* methodWords(StartMethod m) {
  switch (m) {
    case StartMethod::DirectOnLine: return "direct on line";
    case StartMethod::StarDelta: return "star-delta";
    case StartMethod::SoftStarter: return "soft starter";
    case StartMethod::FrequencyConverter: return "frequency converter (V/f ramp)";
  }
  return "?";
}

// Kloss's torque at standstill against the catalogue's, for the notes.
std::string startingTorqueComparison(const Scene& sc, double kloss_start_rotor) {
  const MotorCatalogue& c = sc.induction.catalogue;
  if (c.given() && c.starting_torque_ratio > 0) {
    const double M_s = c.starting_torque_ratio * c.nominalTorque();
    return "Kloss's formula gives " + printfNumber("%.4g", kloss_start_rotor) + " N·m at standstill against the catalogue's M_s = " +
           printfNumber("%.4g", M_s) + " N·m (" + printfNumber("%.2g", M_s / kloss_start_rotor) +
           "x; motor.catalogue.starting_torque_ratio)";
  }
  return "Kloss's formula gives " + printfNumber("%.4g", kloss_start_rotor) +
         " N·m at standstill, typically about a third of a catalogue motor's starting torque (the rotor's deep-bar "
         "effect, which Kloss fitted to the rated and breakdown points leaves out)";
}

// What a start-up with the scene's law cannot show (the motor-law table's words); a law on the
// Kloss curve also compares its starting torque with the catalogue's and advises a catalogue law.
void addLawNotes(const Scene& sc, const MotorLaw& law, StartUp& r) {
  const MotorModelInfo& info = motorModelInfo(sc.induction.model);
  const std::string limit = info.start_up_limit;
  if (info.kloss_curve) {
    const std::string advice =
        "For start-up answers use the catalogue model: motor.model: park (the space-phasor machine, with the "
        "switching transient) or circuit (quasi-static), with the motor.catalogue keys (docs/startup.md).";
    r.notes.push_back(limit + startingTorqueComparison(sc, law.steadyTorque(SupplyState{}, 0.0)) + ". " + advice);
  } else if (!limit.empty()) {
    r.notes.push_back(limit);
  }
  // The switching transient oscillates at the supply frequency: integrals over coarse rows miss it.
  const double dt = sc.simulation.output_step;
  if (info.switching_transient && dt > 1e-3)
    r.notes.push_back("I²t, the current RMS and the rotor loss are integrated over the output rows (Δt = " +
                      printfNumber("%.3g", dt * 1e3) +
                      " ms); the switching transient oscillates at the supply frequency: set "
                      "simulation.output_step to 1 ms or less for these integrals and the transient's peaks.");
}

// The supply the starting method holds while the rotor stands still: the supply at switch-on with
// every time-triggered step of the start applied up to the switch-off (a star-delta changeover by
// speed, or any step triggered by speed, never comes at standstill).
SupplyState heldAtStandstill(const Supply& supply) {
  SupplyPhase p = supply.initialPhase();
  SupplyState held = supply.atSwitchOn();
  for (int step = 0; step < 8; ++step) {
    const double t_event = supply.nextEventTime(p);
    if (!std::isfinite(t_event) || t_event >= supply.stop().t_off) break;
    SupplyPhase q = p;
    if (!supply.applyDueEvents(q, t_event, 0.0, false, nullptr, nullptr)) break;
    p = q;
    // A ramp is read at its end; a stage without a timed end at any later time.
    const double t_next = supply.nextEventTime(p);
    const SupplyState s = supply.state(p, std::isfinite(t_next) ? t_next : t_event + 1e9, 0.0);
    if (s.connected) held = s;
  }
  return held;
}

bool isRatedSupply(const SupplyState& s) {
  return s.line_current_factor >= 1.0 && s.voltage >= 1.0 - 1e-12 && s.frequency >= 1.0 - 1e-12;
}

std::string supplyWords(const SupplyState& s) {
  if (s.line_current_factor < 1.0) return "in star, U_n/√3 on each winding";
  if (isRatedSupply(s)) return "at the rated supply";
  char buf[96];
  if (s.frequency < 1.0 - 1e-12)
    std::snprintf(buf, sizeof buf, "at U = %.3g·U_n and f = %.3g·f_n", s.voltage, s.frequency);
  else
    std::snprintf(buf, sizeof buf, "at U = %.3g·U_n", s.voltage);
  return buf;
}

// Why the motor cannot break away: its starting torque under the held supply against the load at
// the start angle; "" when it can.
std::string breakAwayFailure(const Scene& sc, const StartUp& r, const std::string& held) {
  if (r.starting_torque_held_crank > r.load_torque_start) return "";
  std::string cause = "the motor's starting torque " + printfNumber("%.4g", r.starting_torque_held_crank) + " N·m at the crank (" +
                      r.method + held + ", the law's torque at standstill × u·η) is below the load torque " +
                      printfNumber("%.4g", r.load_torque_start) + " N·m at the start angle " +
                      printfNumber("%.4g", sc.initial.crank_angle * 180 / M_PI) + " deg, so it cannot turn the crank forwards";
  if (r.starting_torque_rated_crank > r.load_torque_start)
    cause += " (at the rated supply it would give " + printfNumber("%.4g", r.starting_torque_rated_crank) + " N·m)";
  return cause;
}

// Why the motor cannot run the machine up: its largest torque under the held supply against the
// load averaged over a revolution; "" when it can. `first`: no cause precedes this one.
std::string runUpFailure(const StartUp& r, const std::string& held, bool first) {
  if (r.largest_torque_held_crank > r.load_torque_mean) return "";
  return std::string(first ? "the motor's" : "; and its") + " largest torque " +
         printfNumber("%.4g", r.largest_torque_held_crank) + " N·m at the crank (" + r.method + held +
         ") is below the load averaged over a revolution, " + printfNumber("%.4g", r.load_torque_mean) +
         " N·m, so it cannot run the machine up" +
         (r.largest_torque_crank <= r.load_torque_mean ? std::string(": no steady running is possible")
                                                       : " (at the rated supply it would give " +
                                                             printfNumber("%.4g", r.largest_torque_crank) + " N·m)");
}

// Whether the torques allow a start from rest, and the one sentence that says why a drive does not
// start or run (StartUp::stall_cause).
void judgeStartFromTorques(const Scene& sc, StartUp& r) {
  if (!std::isfinite(r.load_torque_start) || !std::isfinite(r.load_torque_mean)) {
    r.can_start_from_rest = -1;
    r.start_load_ratio = kNaN;
    return;
  }
  r.start_load_ratio = std::max(r.load_torque_start / r.starting_torque_held_crank,
                                r.load_torque_mean / r.largest_torque_held_crank);
  const std::string held = r.held_supply_is_rated ? "" : " " + r.held_supply;
  // Every reason that holds, the one that ends the start first (breaking away) first.
  std::string cause = breakAwayFailure(sc, r, held);
  cause += runUpFailure(r, held, cause.empty());
  r.can_start_from_rest = cause.empty() ? 1 : 0;
  r.stall_cause = !cause.empty() ? cause
                                 : "the motor can break away (" + printfNumber("%.4g", r.starting_torque_held_crank) +
                                       " N·m against " + printfNumber("%.4g", r.load_torque_start) +
                                       " N·m at the start angle) and carry the mean load (" +
                                       printfNumber("%.4g", r.largest_torque_held_crank) + " N·m against " +
                                       printfNumber("%.4g", r.load_torque_mean) +
                                       " N·m), so the load peaks near a dead centre together with the inertia hold "
                                       "the crank back";
}

// The largest path any cart travels over rows [begin, end) [m].
double largestCartPath(const Table& ts, const std::vector<double>& t, std::size_t begin, std::size_t end) {
  double path = 0;
  for (int j = 1; ts.has("v_cart_" + std::to_string(j)); ++j) {
    const std::vector<double> v = ts.column("v_cart_" + std::to_string(j));
    path = std::max(path, integrate(t, begin, end, [&](std::size_t i) { return std::abs(v[i]); }));
  }
  return path;
}

// The run-out's last row after the switch-off at row i_off: the first whose crank speed is within
// the stall rule's band `limit` [rad/s] (its time after t_off is the stopping time), else the last
// before the restart at t_restart or the run's end (the stopping time stays unknown).
std::size_t runOutEnd(const std::vector<double>& t, const std::vector<double>& w, std::size_t i_off, double limit,
                      double t_restart, StartUp& r) {
  std::size_t i_stop = t.size() - 1;
  for (std::size_t i = i_off; i < t.size() && t[i] < t_restart; ++i) {
    i_stop = i;
    if (std::abs(w[i]) <= limit) {
      r.stopping_time = t[i] - r.t_off;
      break;
    }
  }
  return i_stop;
}

// After a switch-off within the run: the stopping time and the run-out of the crank and the carts.
void addStopping(const Scene& sc, const Table& ts, StartUp& r) {
  const std::vector<double> t = ts.column("t"), w = ts.column("omega_crank");
  r.stopping_time = r.run_out_revolutions = r.run_out_cart_path = kNaN;
  if (!(std::isfinite(r.t_off) && r.t_off <= t.back())) return;
  const double limit = StallDetector::kSpeedFraction * sc.motor.omega_sync / sc.reducer.ratio;
  const std::size_t i_off = firstRowAtOrAfter(t, r.t_off);
  const double t_restart = sc.motor_stop.t_restart;
  const std::size_t i_stop = runOutEnd(t, w, i_off, limit, t_restart, r);
  if (ts.has("phi_crank")) {
    const std::vector<double> phi = ts.column("phi_crank");
    r.run_out_revolutions = std::abs(phi[i_stop] - phi[i_off]) / (2 * M_PI);
  }
  r.run_out_cart_path = largestCartPath(ts, t, i_off, i_stop + 1);
  if (std::isnan(r.stopping_time))
    r.notes.push_back(std::isfinite(t_restart) && t_restart <= t.back()
                          ? "The motor was switched on again at t = " + printfNumber("%.4g", t_restart) +
                                " s before the machine came to rest (a restart at speed); the run-out is counted up to then."
                          : "The machine had not come to rest when the run ended; the run-out is counted up to the end.");
}

// A star-delta changeover by speed that the motor never reached: its keys changed nothing in this
// run, which stayed in star (a user raising the changeover speed of a drive that stalls in star
// saw the same figures and no word why). `rotor_top`: the rotor's largest speed in the run [rad/s].
void addChangeoverNotReached(const Scene& sc, double rotor_top, StartUp& r) {
  const std::string why = "the motor never reached the changeover speed " + printfNumber("%.4g", sc.motor_start.changeover_speed) +
                          " rad/s (its largest speed " + printfNumber("%.4g", rotor_top) + " rad/s), so the run stayed in star";
  for (const char* key : {"motor.start.changeover_speed", "motor.start.changeover_gap"})
    if (std::find(sc.given_keys.begin(), sc.given_keys.end(), key) != sc.given_keys.end())
      r.keys_not_reached.push_back(std::string(key) + " has no effect on this run: " + why);
}

// The motor's torques at the crank at switch-on, at the rated supply and under the supply the
// starting method holds at standstill, the load's torques, and whether they allow a start.
void addTorquesAtStandstill(const Scene& sc, const MotorLaw& law, const Supply& supply, const StartLoad* load,
                            StartUp& r) {
  const double u = sc.reducer.ratio, eta = sc.reducer.efficiency;
  r.starting_torque_crank = law.steadyTorque(supply.atSwitchOn(), 0.0) * u * eta;
  r.starting_torque_rated_crank = law.steadyTorque(SupplyState{}, 0.0) * u * eta;
  const bool kloss_curve = hasKlossCurve(sc.induction.model);
  r.largest_torque_crank = motorBreakdownTorque(sc, &law) * u * eta;
  const SupplyState held = heldAtStandstill(supply);
  r.held_supply = supplyWords(held);
  r.held_supply_is_rated = isRatedSupply(held);
  r.starting_torque_held_crank = law.steadyTorque(held, 0.0) * u * eta;
  r.largest_torque_held_crank =
      (kloss_curve ? sc.motor.breakdown_torque * held.voltage * held.voltage / (held.frequency * held.frequency)
                   : largestSteadyTorque(law, held)) * u * eta;
  r.load_torque_start = load ? load->at_start_angle : kNaN;
  r.load_torque_mean = load ? load->revolution_mean : kNaN;
  judgeStartFromTorques(sc, r);
}

// Whether the crank turns in the steady window, and the run-up: the first crossing of 95 % of the
// steady mean after the switch-on. Sets r.run_up_time, r.still_starting and r.starts.
bool judgeRunUp(const Scene& sc, const std::string& motion, const std::vector<double>& t, const std::vector<double>& w,
                const SteadyWindow& window, StartUp& r) {
  const std::size_t i_on = firstRowAtOrAfter(t, r.t_on);
  r.run_up_time = kNaN;
  // Turning: the crank turns one way in the window, faster than the stall rule's creep limit
  // (StallDetector.h: 1 % of the synchronous crank speed ω0/u).
  const double creep = StallDetector::kSpeedFraction * sc.motor.omega_sync / sc.reducer.ratio;
  bool turning = std::isfinite(r.steady_mean_speed) && r.steady_mean_speed > creep && window.lowest_speed > 0;
  // The run's motion, where known, decides (RunMotion.h): a turning crank may dip backwards at a
  // dead centre; a stalled, rocking or still starting one does not turn.
  if (motion == "turning") turning = std::isfinite(r.steady_mean_speed) && r.steady_mean_speed > creep;
  else if (!motion.empty() && motion != "unknown") turning = false;
  r.still_starting = motion == "starting";
  if (turning) {
    const double target = kRunUpFraction * r.steady_mean_speed;
    for (std::size_t i = std::max<std::size_t>(i_on, 1); i < window.n_running; ++i)
      if (w[i] >= target) {
        const double a = w[i] > w[i - 1] && i > i_on ? (target - w[i - 1]) / (w[i] - w[i - 1]) : 1.0;
        r.run_up_time = t[i - 1] + std::clamp(a, 0.0, 1.0) * (t[i] - t[i - 1]) - r.t_on;
        break;
      }
  }
  r.starts = turning && std::isfinite(r.run_up_time);
  return turning;
}

// The motor's and the coupling's torque peaks over the start and over the steady window.
void addTorquePeaks(const Table& ts, RowSpan start, RowSpan steady, StartUp& r) {
  const std::vector<double> M = columnOr(ts, "motor_torque"), C = columnOr(ts, "coupling_torque");
  r.motor_torque_peak = extremeOf(M, start, Extreme::Largest);
  r.motor_torque_min = extremeOf(M, start, Extreme::Smallest);
  r.motor_torque_steady_peak = extremeOf(M, steady, Extreme::LargestMagnitude);
  r.coupling_torque_peak = extremeOf(C, start, Extreme::LargestMagnitude);
  r.coupling_torque_steady_peak = extremeOf(C, steady, Extreme::LargestMagnitude);
}

// The stator current over the start: its peak, I²t and RMS, and its RMS over the steady window.
void addStatorCurrent(const Table& ts, const std::vector<double>& t, RowSpan start, const SteadyWindow& window,
                      StartUp& r) {
  const std::vector<double> I = columnOr(ts, "stator_current");
  r.current_peak = r.current_rms = r.current_i2t = r.current_steady_rms = kNaN;
  if (I.empty()) return;
  const std::size_t s0 = start.begin, s1c = start.end;
  r.current_peak = extremeOf(I, start, Extreme::LargestMagnitude);
  r.current_i2t = integrate(t, s0, s1c, [&](std::size_t i) { return I[i] * I[i]; });
  const double T = t[s1c - 1] - t[s0];
  r.current_rms = T > 0 ? std::sqrt(r.current_i2t / T) : kNaN;
  if (window.duration > 0)
    r.current_steady_rms = std::sqrt(
        integrate(t, window.rows.begin, window.rows.end, [&](std::size_t i) { return I[i] * I[i]; }) / window.duration);
}

// The rotor's energy loss over the start: slip power M·(ω0·f/f_n - ω_r) while connected.
void addRotorLoss(const Scene& sc, const Table& ts, const std::vector<double>& t, RowSpan start, StartUp& r) {
  const std::vector<double> M = columnOr(ts, "motor_torque"), wm = columnOr(ts, "omega_motor"),
                            F = columnOr(ts, "supply_frequency_ratio"), U = columnOr(ts, "supply_voltage_ratio");
  r.rotor_energy_loss = kNaN;
  if (M.empty() || wm.empty()) return;
  const double u = sc.reducer.ratio, eta = sc.reducer.efficiency, w0_sync = sc.motor.omega_sync;
  r.rotor_energy_loss = integrate(t, start.begin, start.end, [&](std::size_t i) {
    const bool connected = U.empty() ? true : U[i] > 0;
    if (!connected) return 0.0;
    const double f = F.empty() ? 1.0 : F[i];
    return M[i] / (u * eta) * (w0_sync * f - wm[i] * u);
  });
}

// Whether a star-delta changeover by speed was never reached: the rotor never came up to it (no
// motor speed column: not known, taken as not reached, as the verdict has always done). Adds the
// changeover keys' note where the rotor's top speed is known.
bool changeoverMissed(const Scene& sc, const Table& ts, StartUp& r) {
  const bool changeover_by_speed =
      sc.motor_start.method == StartMethod::StarDelta && std::isfinite(sc.motor_start.changeover_speed);
  const std::vector<double> wm = columnOr(ts, "omega_motor");
  const double rotor_top = wm.empty() ? kNaN : extremeOf(wm, {0, wm.size()}, Extreme::Largest) * sc.reducer.ratio;
  const bool missed = changeover_by_speed && (wm.empty() || rotor_top < sc.motor_start.changeover_speed);
  if (missed && !wm.empty()) addChangeoverNotReached(sc, rotor_top, r);
  return missed;
}

// The verdict of a drive that does not run up: the cause is the one
// sentence judgeStartFromTorques wrote (or the missed changeover's), so the run status and the
// sizing say the same.
std::string notRunningUpVerdict(const Scene& sc, const RunResult& run, bool changeover_missed, StartUp& r) {
  if (r.can_start_from_rest == 1 && changeover_missed) {
    r.stall_cause = "the changeover speed " + printfNumber("%.4g", sc.motor_start.changeover_speed) +
                    " rad/s was never reached in star (the star torque is a third of the delta torque): the load and "
                    "the inertia hold the motor below it";
    return "the drive does not run up: " + r.stall_cause;
  }
  if (r.stall_cause.empty())
    return "the drive does not reach a steady turning motion within the run (the load torques were not evaluated)";
  std::string verdict = (r.can_start_from_rest == 0 ? "the drive does not start: "
                                                    : "the drive does not reach a steady turning motion within the run: ") +
                        r.stall_cause;
  const std::string travel = stalledCrankTravel(sc, run);
  if (!travel.empty()) verdict += "; " + travel;
  return verdict;
}

// The start's verdict (r.verdict).
void judgeStart(const Scene& sc, const RunResult& run, bool turning, bool changeover_missed, StartUp& r) {
  if (r.starts)
    r.verdict = "the drive starts: the crank reaches 95 % of its steady mean speed " + printfNumber("%.4g", r.steady_mean_speed) +
                " rad/s " + printfNumber("%.3g", r.run_up_time) + " s after switch-on";
  else if (r.still_starting)
    r.verdict = kStillStartingWords;
  else if (!turning || (r.can_start_from_rest == 1 && changeover_missed))
    r.verdict = notRunningUpVerdict(sc, run, changeover_missed, r);
  else
    r.verdict = "the crank does not reach 95 % of its steady mean speed after switch-on within the run";
}

// A run that begins with the machine already turning has no start: a run-up "0.005 s after
// switch-on", start peaks and a start's rotor loss of a machine that began at speed read as answers
// about a start (the second trial). What can be answered stays: the motor's torques against the
// loads, and the stop.
void withdrawStartAnswers(const Scene& sc, StartUp& r) {
  r.verdict = "no start from rest in this run: it begins with the machine already turning (initial.crank_speed = " +
              printfNumber("%.4g", sc.initial.crank_speed) + " rad/s) and the motor running; set initial.crank_speed: 0 for "
              "the start-up answers";
  // Whether it could start from rest is still known from the torques: say it where the start is asked.
  if (r.can_start_from_rest == 0)
    r.verdict += ". From rest it would not start: " + r.stall_cause;
  else if (r.can_start_from_rest == 1)
    r.verdict += ". From rest the torques at standstill allow a start (the start itself is not simulated)";
  r.starts = false;
  r.run_up_time = kNaN;
  r.start_end = r.t_on;
  r.motor_torque_peak = r.motor_torque_min = r.coupling_torque_peak = kNaN;
  for (StartJointPeak& p : r.joints) p.start_peak = p.ratio = kNaN;
  r.current_peak = r.current_rms = r.current_i2t = r.rotor_energy_loss = kNaN;
}

// What the start is: the starting method, the motor law and whether the supply switches.
void describeStart(const Scene& sc, const MotorLaw& law, const Supply& supply, StartUp& r) {
  r.applicable = true;
  r.supply_switches = !supply.constant();
  r.method = methodWords(sc.motor_start.method);
  r.motor_law = law.description();
  r.model_word = toString(sc.induction.model);
}

// The start's peaks and integrals against the steady window's: the motor and coupling torques, the
// joints (when the reactions table shares the timeseries' output grid), the stator current and the
// rotor's energy loss.
void addStartPeaks(const Scene& sc, const RunResult& run, const std::vector<double>& t, RowSpan start,
                   const SteadyWindow& window, StartUp& r) {
  const Table& ts = run.timeseries;
  addTorquePeaks(ts, start, window.rows, r);
  if (run.reactions.rows.size() == ts.rows.size()) addStartJointPeaks(run.reactions, start, window.rows, r);
  addStatorCurrent(ts, t, start, window, r);
  addRotorLoss(sc, ts, t, start, r);
}

}  // namespace

StartUp computeStartUp(const Scene& sc, const RunResult& run, const MotorLaw* law, const StartLoad* load,
                       const std::string& motion) {
  StartUp r;
  const Table& ts = run.timeseries;
  if (!sc.motor.enabled || !law || !ts.has("t") || !ts.has("omega_crank") || ts.rows.size() < 2) return r;
  const Supply supply = makeSupply(sc, law);
  const std::vector<double> t = ts.column("t"), w = ts.column("omega_crank");
  r.t_on = sc.motor_start.t_on;
  if (r.t_on > t.back()) return r;  // switched on after the end of the run
  describeStart(sc, *law, supply, r);
  addTorquesAtStandstill(sc, *law, supply, load, r);
  const SteadyWindow window = findSteadyWindow(sc, run, t, w, r);
  const bool turning = judgeRunUp(sc, motion, t, w, window, r);
  const RowSpan start = findStartRows(t, window, r);
  addStartPeaks(sc, run, t, start, window, r);
  addStopping(sc, ts, r);
  judgeStart(sc, run, turning, changeoverMissed(sc, ts, r), r);
  r.from_rest = !(r.t_on <= 0 && sc.initial.crank_speed != 0);
  if (!r.from_rest) withdrawStartAnswers(sc, r);
  addCurrentLimit(sc, run, *law, supply, r);
  addLawNotes(sc, *law, r);
  return r;
}

}  // namespace rollerdyn
