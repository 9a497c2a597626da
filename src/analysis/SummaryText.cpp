// The run's lines for the terminal (summaryText, Summary.h), read from a summary.json object: what
// ran, the motion and status, the crank speed, the steady state, load, coupling, energy, guides,
// backlash, shaft torsion, and how the integration went.
#include <cstdio>
#include <sstream>
#include <string>

#include "analysis/RunMotion.h"
#include "analysis/ShaftTorsion.h"
#include "analysis/Summary.h"
#include "analysis/ToothContact.h"

namespace rollerdyn {

using nlohmann::json;

namespace {

// printf-style formatting of a JSON number, "n/a" for null or absent.
std::string formatted(const json& v, const char* fmt) {
  if (!v.is_number()) return "n/a";
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, v.get<double>());
  return buf;
}

std::string jsonText(const json& v) { return v.is_string() ? v.get<std::string>() : v.dump(); }

// What the run's motion means, after its name on the motion line.
std::string motionExplanation(const std::string& motion) {
  return motion == "turning"    ? "  (the crank turns one way)"
         : motion == "rocking"  ? "  (the crank swings back and forth instead of turning)"
         : motion == "stalled"  ? "  (the motor stalled; why: see status)"
         : motion == "at_rest"  ? "  (the machine is at rest: with the motor off, friction and loads hold it)"
         : motion == "coasting" ? "  (the motor is off and the machine slows down: the run ended before it came to rest; "
                                  "its speed swing is the deceleration, not an unevenness, so δ, H and k_p do not apply; "
                                  "run longer, simulation.t_end, for the run-out)"
         : motion == "starting" ? "  (" + std::string(kStillStartingWords) + "; no sizing verdict applies yet)"
                                : "";
}

// The metrics window's line (after the steady-state line): which revolutions, and when.
std::string metricsWindowLine(const json& st) {
  std::ostringstream o;
  const int window_revs = st.value("window_revolutions", 0);
  o << "\n             metrics window: "
    << (window_revs > 0 ? "the last " + std::to_string(window_revs) + " revolutions"
                        : std::string("the last 20 % of the run (it holds no whole crank revolution)"))
    << (st.value("reached", false) ? "" : " (no steady state: the window may hold the start)")
    << ", t = " << formatted(st.value("t_begin", json(nullptr)), "%.4g") << " ... " << formatted(st.value("t_end", json(nullptr)), "%.4g")
    << " s\n";
  return o.str();
}

// The steady-state lines: whether the speed settled, from which revolution, and the metrics window.
std::string steadyStateText(const json& st) {
  if (!st.is_object()) return "";
  std::ostringstream o;
  // after_revolutions is the 0-based index of the first settled revolution: the speed repeats
  // from the start of revolution after_revolutions + 1 (counted from 1) on.
  o << "steady state " << (st.value("reached", false) ? "reached" : "NOT reached");
  if (st.value("not_reached", json(nullptr)).is_string()) {
    // The sentence begins "steady state not reached": the line has said so already.
    const std::string why = jsonText(st.value("not_reached", json("")));
    const std::string lead = "steady state not reached";
    o << (why.rfind(lead, 0) == 0 ? why.substr(lead.size()) : ": " + why)
      << "; δ, H, k_p and the steady window's checks do not apply";
  }
  if (st.value("reached", false) && st.value("after_revolutions", -1) >= 0)
    o << ": the crank speed repeats from revolution " << st.value("after_revolutions", -1) + 1 << " on (t = "
      << formatted(st.value("t_settled", json(nullptr)), "%.4g") << " s), of " << st.value("revolutions", 0)
      << " whole revolutions in the run";
  o << metricsWindowLine(st);
  return o.str();
}

// The load line: the net power per cart, and a warning when the load does almost no net work.
std::string loadText(const json& ld) {
  if (!ld.is_object() || !ld.value("available", false)) return "";
  std::ostringstream o;
  o << "load         " << formatted(ld.value("power_mean_per_cart_steady", json(nullptr)), "%.4g")
    << " W per cart net in the metrics window, " << formatted(ld.value("power_mean_per_cart_whole_run", json(nullptr)), "%.4g")
    << " W per cart over the whole run (" << jsonText(ld.value("reading", json(""))) << ")\n";
  if (ld.value("warning", json(nullptr)).is_string())
    o << "             WARNING: the load does almost no net work: " << jsonText(ld.value("warning_consequence", json("")))
      << " (warning on stderr, docs/loads.md)\n";
  return o.str();
}

// Member a of the summary, or its member b; null where absent.
json memberAt(const json& s, const char* a, const char* b = nullptr) {
  if (!s.contains(a)) return nullptr;
  if (!b) return s.at(a);
  return s.at(a).contains(b) ? s.at(a).at(b) : json(nullptr);
}

// What ran, how the drive moved, and how the run ended.
std::string runText(const json& s) {
  std::ostringstream o;
  o << "scene        " << jsonText(memberAt(s, "scene")) << "  (model " << jsonText(memberAt(s, "model")) << ", integrator "
    << jsonText(memberAt(s, "integrator")) << ")\n";
  const std::string motion = jsonText(memberAt(s, "motion"));
  o << "motion       " << motion << motionExplanation(motion) << "\n";
  o << "status       " << jsonText(memberAt(s, "status")) << "\n";
  return o.str();
}

// The crank speed over the metrics window and the coefficients of its unevenness.
std::string crankSpeedText(const json& s) {
  std::ostringstream o;
  o << "crank speed  mean " << formatted(memberAt(s, "omega_crank", "mean"), "%.4g") << " rad/s, min "
    << formatted(memberAt(s, "omega_crank", "min"), "%.4g") << ", max " << formatted(memberAt(s, "omega_crank", "max"), "%.4g")
    << "\n             δ (unevenness) " << formatted(memberAt(s, "delta"), "%.4g") << ", H (dynamics) "
    << formatted(memberAt(s, "H"), "%.4g") << ", k_p (generalised) " << formatted(memberAt(s, "k_p"), "%.4g")
    << "  (Loveikin and Pochka (2007) eq. (12)-(14))\n";
  return o.str();
}

// The energy audit's residual, and the reducer's losses where a loss model ran.
std::string energyText(const json& s) {
  std::ostringstream o;
  o << "energy       residual " << formatted(memberAt(s, "energy", "residual"), "%.3g") << " J (relative "
    << formatted(memberAt(s, "energy_residual_rel"), "%.2e") << ")";
  if (memberAt(s, "energy", "reducer_loss_model").is_string())
    o << "; reducer losses " << formatted(memberAt(s, "energy", "reducer_losses"), "%.4g") << " J of the motor's shaft work "
      << formatted(memberAt(s, "energy", "motor_shaft_work"), "%.4g") << " J, " << jsonText(memberAt(s, "energy", "reducer_loss_model"));
  o << "\n";
  return o.str();
}

// Only a lift-off gets a line (the verdict and a not-applicable reason are in summary.json).
std::string liftOffText(const json& lo) {
  if (!(lo.is_object() && jsonText(lo.value("verdict", json(""))) == "lifts off")) return "";
  std::ostringstream o;
  o << "guides       LIFT-OFF: " << lo["lifting"].size()
    << " guide reaction(s) change sign in the steady window: those rollers need a counter-roller (warnings "
       "on stderr; summary.json guide_lift_off)\n";
  return o.str();
}

// How the integration went: the constraints' error, the guide normal forces, the steps and the CPU time.
std::string integrationText(const json& s) {
  std::ostringstream o;
  o << "constraints  max error " << formatted(memberAt(s, "constraint_error_max"), "%.2e") << "\n";
  if (memberAt(s, "guide_normal_forces").is_string())
    o << "guide normal forces  " << jsonText(memberAt(s, "guide_normal_forces")) << "\n";
  o << "steps        " << jsonText(memberAt(s, "steps")) << " steps"
    << (memberAt(s, "rejected_steps").is_number() ? " (" + jsonText(memberAt(s, "rejected_steps")) + " rejected by the error test)" : "")
    << ", " << jsonText(memberAt(s, "realizations")) << " right-hand-side evaluations\n";
  o << "cpu          " << formatted(memberAt(s, "cpu_seconds"), "%.3g") << " s for "
    << formatted(memberAt(s, "simulated_time"), "%.4g") << " s simulated, real-time factor "
    << formatted(memberAt(s, "real_time_factor"), "%.3g") << "\n";
  return o.str();
}

}  // namespace

std::string summaryText(const nlohmann::json& s) {
  std::ostringstream o;
  o << runText(s) << crankSpeedText(s);
  o << steadyStateText(memberAt(s, "steady_state"));
  o << loadText(memberAt(s, "load"));
  o << "coupling     torque swing " << formatted(memberAt(s, "coupling_torque_swing"), "%.4g")
    << " N·m, twist swing " << formatted(memberAt(s, "twist_swing"), "%.3g") << " rad\n";
  o << energyText(s);
  o << liftOffText(memberAt(s, "guide_lift_off"));
  o << toothContactText(memberAt(s, "backlash"));
  o << shaftTorsionText(memberAt(s, "crankshaft_torsion"));
  o << integrationText(s);
  return o.str();
}

}  // namespace rollerdyn
