#include "analysis/Summary.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <sstream>

#include "analysis/DriveSizing.h"
#include "analysis/GuideLiftOff.h"
#include "analysis/ShaftTorsion.h"
#include "analysis/ToothContact.h"
#include "analysis/LoadWork.h"
#include "analysis/Metrics.h"
#include "analysis/SizingSummary.h"
#include "analysis/StallDetector.h"
#include "analysis/StartUpSummary.h"
#include "analysis/SteadyState.h"
#include "io/AtomicFile.h"
#include "motor/BreakdownTorque.h"
#include "motor/SharedMotorLaw.h"
#include "physics/ReducerLosses.h"

namespace rollerdyn {

namespace {

using nlohmann::json;

// Turns doubles into JSON numbers, writing null for NaN/inf and remembering which keys.
class FiniteWriter {
 public:
  json operator()(const std::string& key, double v) {
    if (std::isfinite(v)) return v;
    non_finite.push_back(key);
    return nullptr;
  }
  std::vector<std::string> non_finite;
};

std::string joined(const std::vector<std::string>& items) {
  std::string s;
  for (const auto& i : items) s += (s.empty() ? "" : ", ") + i;
  return s;
}

// What ran: the scene, the model and its integrator, the effects asked for and built.
json runIdentity(const Scene& scene, const RunResult& run) {
  json j;
  j["scene"] = scene.name;
  j["scene_path"] = scene.source_path;  // file as given, for `rollerdyn plot` (Kloss curve)
  j["model"] = run.model;
  j["integrator"] = run.integrator;
  j["effects"] = scene.effects();
  j["effects_built"] = run.effects;
  j["status"] = run.stats.status;  // amended by the summary if anything was non-finite
  j["complete"] = run.stats.complete;
  return j;
}

// The time the run's rows span [s] (0 without rows).
double simulatedTime(const Table& ts) {
  if (!ts.has("t") || ts.rows.empty()) return 0;
  const int k = ts.index("t");
  return ts.rows.back()[k] - ts.rows.front()[k];
}

// How far the crank turned over the metrics window [rad]; NaN where not known.
double crankAdvance(const Table& ts, const SteadyState& ss) {
  if (!ts.has("phi_crank") || ss.row_end < ss.row_begin + 2 || ss.row_end > ts.rows.size()) return NAN;
  const int k = ts.index("phi_crank");
  return ts.rows[ss.row_end - 1][k] - ts.rows[ss.row_begin][k];
}

// The coupling's swings over the metrics window, Loveikin, Pochka, Romasevych (2018), Table 1.
void addCouplingSwings(json& j, const WindowMetrics& m, FiniteWriter& num) {
  j["coupling_torque_swing"] = num("coupling_torque_swing", m.coupling_torque_swing);
  j["twist_swing"] = num("twist_swing", m.twist_swing);
  j["twist_rate_swing"] = num("twist_rate_swing", m.twist_rate_swing);
  j["twist_accel_swing"] = num("twist_accel_swing", m.twist_accel_swing);
  j["missing_columns"] = m.missing_columns;
}

// The crank's speed over the metrics window, its motion, and the coefficients of its unevenness.
void addCrankSpeed(json& j, const WindowMetrics& m, const std::string& crank_motion, bool steady_turning,
                   FiniteWriter& num, std::vector<std::string>& not_meaningful) {
  j["omega_crank"] = {{"min", num("omega_crank.min", m.omega_min)},
                      {"max", num("omega_crank.max", m.omega_max)},
                      {"mean", num("omega_crank.mean", m.omega_mean)},
                      {"midrange", num("omega_crank.midrange", m.omega_midrange)}};
  j["motion"] = crank_motion;
  j["crank_motion"] = crank_motion;
  j["eps_crank_abs_max"] = num("eps_crank_abs_max", m.eps_abs_max);
  j["eps_from_difference"] = m.eps_from_difference;
  // Loveikin and Pochka (2007), eq. (12)-(14): ratios to the mean speed of a turning crank; a
  // stalled or rocking crank has no such mean, so they are null there, not a huge number.
  // They are also null where no steady state was reached: a window that holds the start or a
  // drift is no revolution of the machine's running (a 4 s run of six carts read δ = 1.265).
  auto perRevolution = [&](const char* key, double v) -> json {
    if (steady_turning) return num(key, v);
    not_meaningful.push_back(key);
    return nullptr;
  };
  j["delta"] = perRevolution("delta", m.coefficients.delta);
  j["H"] = perRevolution("H", m.coefficients.H);
  j["k_p"] = perRevolution("k_p", m.coefficients.k_p);
  addCouplingSwings(j, m, num);
}

json steadyStateJson(const SteadyState& ss, const WindowMetrics& m, const std::string& crank_motion, FiniteWriter& num) {
  return {
      {"reached", ss.reached},
      {"after_revolutions", ss.after_revolutions},
      {"window_revolutions", ss.window_revolutions},
      {"revolutions", ss.revolutions_counted},
      {"relative_tolerance", ss.relative_tolerance},
      // No whole revolution → no settling time; that is not a numerical failure.
      {"t_settled", ss.after_revolutions >= 0 ? num("steady_state.t_settled", ss.t_settled)
                                              : json(nullptr)},
      {"t_begin", num("steady_state.t_begin", ss.t_begin)},
      {"t_end", num("steady_state.t_end", ss.t_end)},
      {"rows", m.rows},
      {"note", ss.note},
      // How long to run: only for a drive that turns or is still starting (a longer run does not
      // help a stalled drive, whose status says why).
      {"not_reached", ss.not_reached.empty() || (crank_motion != "turning" && crank_motion != "starting")
                          ? json(nullptr) : json(ss.not_reached)}};
}

json energyJson(const Scene& scene, const EnergyAudit& en, FiniteWriter& num) {
  return {
      {"motor_work", num("energy.motor_work", en.motor_work)},
      {"damping_dissipation", num("energy.damping_dissipation", en.damping_dissipation)},
      {"friction_dissipation", num("energy.friction_dissipation", en.friction_dissipation)},
      {"load_work", num("energy.load_work", en.load_work)},
      {"kinetic_change", num("energy.kinetic_change", en.kinetic_final - en.kinetic_initial)},
      {"potential_change",
       num("energy.potential_change", en.potential_final - en.potential_initial)},
      {"reducer_losses", num("energy.reducer_losses", en.reducer_losses)},
      {"motor_shaft_work", num("energy.motor_shaft_work", en.motorShaftWork())},
      {"reducer_loss_model", scene.motor.enabled ? json(reducerLossWords(reducerLaw(scene, motorBreakdownTorque(scene)))) : json(nullptr)},
      {"residual", num("energy.residual", en.residual())}};
}

// The O(n) reaction columns against Simbody's constrained solve, per column kind (the largest
// over the carts): absolute [N, N·m] and relative to the column's largest value.
json reactionSelfCheckJson(const Scene& scene, const RunStats& stats) {
  if (stats.reaction_self_check.empty()) return nullptr;
  json kinds = json::object();
  for (const ReactionCheck& c : stats.reaction_self_check) {
    std::string kind = c.column;
    const std::size_t us = kind.find_last_of('_');
    if (us != std::string::npos && us + 1 < kind.size() &&
        kind.find_first_not_of("0123456789", us + 1) == std::string::npos)
      kind = kind.substr(0, us);
    const double rel = c.max_value > 0 ? c.max_difference / c.max_value : c.max_difference;
    json& k = kinds[kind];
    if (k.is_null()) k = {{"max_difference", 0.0}, {"relative", 0.0}};
    k["max_difference"] = std::max(k["max_difference"].get<double>(), c.max_difference);
    k["relative"] = std::max(k["relative"].get<double>(), rel);
  }
  return {{"rows_checked", stats.self_check_rows}, {"interval_rows", scene.selfCheckInterval()}, {"columns", kinds}};
}

// How well the run kept its own books: the energy audit, the constraints, the formulations' self-checks.
void addSelfChecks(json& j, const Scene& scene, const RunResult& run, FiniteWriter& num) {
  j["energy"] = energyJson(scene, run.energy, num);
  j["energy_residual_rel"] = num("energy_residual_rel", run.energy.residualRelative());
  j["constraint_error_max"] = num("constraint_error_max", run.stats.constraint_error_max);
  j["formulation_self_check"] = run.stats.formulation_self_check >= 0  // README, "Multibody formulations"
                                    ? num("formulation_self_check", run.stats.formulation_self_check)
                                    : json(nullptr);
  j["reaction_self_check"] = reactionSelfCheckJson(scene, run.stats);
  j["guide_normal_forces"] = run.guide_normals.empty() ? json(nullptr) : json(run.guide_normals);
}

// The integrator's work and what it cost.
void addIntegratorStatistics(json& j, const RunStats& stats, double simulated_time, FiniteWriter& num) {
  j["steps"] = stats.steps;
  j["realizations"] = stats.realizations;
  j["rejected_steps"] = stats.error_test_failures >= 0 ? json(stats.error_test_failures) : json(nullptr);
  j["jacobian_evaluations"] = stats.jacobian_evaluations >= 0 ? json(stats.jacobian_evaluations) : json(nullptr);
  j["newton_convergence_failures"] =
      stats.newton_convergence_failures >= 0 ? json(stats.newton_convergence_failures) : json(nullptr);
  j["cpu_seconds"] = num("cpu_seconds", stats.cpu_seconds);
  j["real_time_factor"] = stats.cpu_seconds > 0
                              ? num("real_time_factor", simulated_time / stats.cpu_seconds)
                              : json(nullptr);  // not measured
}

json reactionsJson(const WindowMetrics& m, FiniteWriter& num) {
  json rx = json::object();
  for (const auto& [name, s] : m.reactions) {
    const std::string p = "reactions." + name + ".";
    rx[name] = {{"min", num(p + "min", s.min)},
                {"max", num(p + "max", s.max)},
                {"mean", num(p + "mean", s.mean)},
                {"abs_max", num(p + "abs_max", s.abs_max)}};
  }
  return rx;
}

// Start-up and stopping answers (StartUp.h) with the scene's motor law, told the motion so they
// agree with it; null where the scene has no motor law or its starting method cannot be built.
std::unique_ptr<StartUp> startUpAnswers(const Scene& scene, const RunResult& run, const StartLoad* start_load,
                                        const std::string& crank_motion) {
  std::shared_ptr<const MotorLaw> law;
  if (scene.motor.enabled) try {
      law = sharedMotorLaw(scene);
    } catch (const std::exception&) {
      // a law the scene cannot build: no start-up answers
    }
  std::unique_ptr<StartUp> start_up;
  if (law) try {
      start_up = std::make_unique<StartUp>(computeStartUp(scene, run, law.get(), start_load, crank_motion));
    } catch (const std::exception&) {
      // a scene the starting method cannot be built for (e.g. a test scene without loads' data)
    }
  return start_up;
}

// Where the joint loads come from, and what is missing: the reduced model computes the cart
// statics only (guide rollers, rod end), not the crank pin or the main bearing. Null without
// joint reactions.
json jointsBasis(const Scene& scene, const RunResult& run) {
  if (run.reactions.columns.empty()) return nullptr;
  if (run.model != "reduced") return "multibody model, joint reaction forces";
  return std::string(scene.reduced.guide_normals == ReducedGuideNormals::QuasiStatic
                         ? "reduced model, quasi-static cart statics (the papers': no inertial forces)"
                         : "reduced model, kinetostatic cart statics (the carts' and rods' inertial forces included)") +
         "; not computed by the reduced model: crank pin, main bearing (run the multibody model)";
}

// The load's work and the checks of the steady running that come with warnings: guide roller
// lift-off, the gear teeth's contact, the crankshaft's torsion.
void addRunningChecks(json& j, const Scene& scene, const RunResult& run, const SteadyState& ss, bool steady_turning) {
  const LoadWork load = computeLoadWork(scene, run, ss);
  j["load"] = loadWorkJson(load);
  if (!j.contains("warnings")) j["warnings"] = json::array();
  if (!load.warning.empty()) j["warnings"].push_back(load.warning);
  const GuideLiftOff lift_off = computeGuideLiftOff(run, ss, steady_turning);
  j["guide_lift_off"] = guideLiftOffJson(lift_off);
  for (const std::string& w : lift_off.warnings) j["warnings"].push_back(w);
  const ToothContactSummary teeth = computeToothContact(scene, run, ss, steady_turning);
  j["backlash"] = toothContactJson(teeth);
  for (const std::string& w : teeth.warnings) j["warnings"].push_back(w);
  const ShaftTorsionSummary torsion = computeShaftTorsion(scene, run, ss, steady_turning);
  j["crankshaft_torsion"] = shaftTorsionJson(torsion);
  for (const std::string& w : torsion.warnings) j["warnings"].push_back(w);
}

// Why a stalled drive stalled: the start-up answers' one sentence (StartUp::stall_cause), which
// the sizing's checks print too (a soft starter's current limit that held the motor is the supply
// it names), and how far the crank still travelled.
std::string stallExplanation(const Scene& scene, const RunResult& run, const StartUp* start_up) {
  std::string why = start_up && !start_up->stall_cause.empty()
                        ? start_up->stall_cause
                        : std::string(start_up ? "the load torques at the start were not evaluated"
                                               : "the scene gives no motor law to compare the loads with");
  const std::string travel = stalledCrankTravel(scene, run);
  if (!travel.empty()) why += "; " + travel;
  return why;
}

// The stall's explanation and the torques it compares.
json stallJson(const std::string& why, const StartUp* start_up, const StartLoad* start_load, FiniteWriter& num) {
  auto orNull = [&](const char* key, double v, bool known) { return known ? num(key, v) : json(nullptr); };
  const bool su = start_up != nullptr;
  return {{"explanation", why},
          {"starting_torque_crank", orNull("stall.starting_torque_crank",
                                           su ? start_up->starting_torque_held_crank : NAN, su)},
          {"starting_supply", su ? json(start_up->held_supply) : json(nullptr)},
          {"breakdown_torque_crank", orNull("stall.breakdown_torque_crank",
                                            su ? start_up->largest_torque_held_crank : NAN, su)},
          {"load_torque_start", start_load ? num("stall.load_torque_start", start_load->at_start_angle) : json(nullptr)},
          {"load_torque_mean", start_load ? num("stall.load_torque_mean", start_load->revolution_mean) : json(nullptr)}};
}

// The run's status amended by what the summary found: a crank that rocks, a stall (its
// explanation also in j["stall"]), non-finite rows.
std::string amendedStatus(json& j, const Scene& scene, const RunResult& run, const SteadyState& ss,
                          const WindowMetrics& m, const std::string& crank_motion, const StartUp* start_up,
                          const StartLoad* start_load, FiniteWriter& num) {
  std::string status = run.stats.status;
  if (crank_motion == "rocking" && StallDetector::motionOfStatus(status) != "rocking") {
    char buf[160];
    std::snprintf(buf, sizeof buf,
                  "; the crank rocks back and forth instead of turning (its speed ranges from "
                  "%.3g to %.3g rad/s in the metrics window)",
                  m.omega_min, m.omega_max);
    status += buf;
  }
  if (crank_motion == "stalled") {
    const std::string why = stallExplanation(scene, run, start_up);
    j["stall"] = stallJson(why, start_up, start_load, num);
    status += "; the drive stalled: " + why;
  }
  if (ss.finite_rows < run.timeseries.rows.size())
    status += "; timeseries has non-finite values (" + ss.note + ")";
  return status;
}

// The run read once: its steady window (the machine's running: the coast-down after a switch-off
// is no steady state, SteadyState.h), the window's metrics, and how the drive moved.
struct RunReading {
  SteadyState ss;
  WindowMetrics m;
  std::string crank_motion;  // RunMotion.h
  bool turning = false, steady_turning = false;
};

RunReading readRun(const Scene& scene, const RunResult& run) {
  RunReading r;
  r.ss = detectRunningSteadyState(run, scene.simulation.steady_window_revolutions,
                                  scene.motor.enabled ? scene.motor_stop.t_off : NAN);
  r.m = computeMetrics(run, r.ss);
  // "stalled", "rocking" (crank speed changes sign in the metrics window), "turning",
  // "at_rest", "unknown" (RunMotion.h); per-revolution metrics are null unless turning.
  r.crank_motion = classifyMotion(scene, run, r.m, crankAdvance(run.timeseries, r.ss), r.ss.reached);
  r.turning = motionIsTurning(r.crank_motion);
  r.steady_turning = r.turning && r.ss.reached;
  return r;
}

// The drive sizing, and the checks of the running that go with it.
void addSizing(json& j, const Scene& scene, const RunResult& run, const RunReading& r, const StartUp* start_up,
               const StartLoad* start_load) {
  const DriveSizing sizing = computeDriveSizing(scene, run, r.ss, r.turning,
                                                r.steady_turning ? r.m.coefficients.delta : NAN, r.crank_motion,
                                                start_up, start_load);
  j["sizing"] = sizingJson(sizing);
  j["sizing"]["flywheel"]["location"] = toString(scene.flywheel.location);
  addRunningChecks(j, scene, run, r.ss, r.steady_turning);
  if (const json basis = jointsBasis(scene, run); !basis.is_null()) j["sizing"]["joints_basis"] = basis;
}

}  // namespace

// The run's status, amended by the verdicts, and the values written as null (last: every value
// written before has been through num).
void addStatus(json& j, const Scene& scene, const RunResult& run, const RunReading& r, const StartUp* start_up,
               const StartLoad* start_load, FiniteWriter& num) {
  std::string status = amendedStatus(j, scene, run, r.ss, r.m, r.crank_motion, start_up, start_load, num);
  if (!num.non_finite.empty())
    status += "; non-finite values written as null: " + joined(num.non_finite);
  j["status"] = status;
  j["non_finite"] = num.non_finite;
}

json makeSummary(const Scene& scene, const RunResult& run, const StartLoad* start_load) {
  const RunReading r = readRun(scene, run);
  FiniteWriter num;
  json j = runIdentity(scene, run);
  const double simulated_time = simulatedTime(run.timeseries);
  j["simulated_time"] = num("simulated_time", simulated_time);
  std::vector<std::string> not_meaningful;
  addCrankSpeed(j, r.m, r.crank_motion, r.steady_turning, num, not_meaningful);
  j["steady_state"] = steadyStateJson(r.ss, r.m, r.crank_motion, num);
  addSelfChecks(j, scene, run, num);
  addIntegratorStatistics(j, run.stats, simulated_time, num);
  j["reactions"] = reactionsJson(r.m, num);
  // The sizing's heating check reads the start's heat from the start-up answers.
  const std::unique_ptr<StartUp> start_up = startUpAnswers(scene, run, start_load, r.crank_motion);
  addSizing(j, scene, run, r, start_up.get(), start_load);
  if (!r.steady_turning) {
    not_meaningful.push_back("sizing.flywheel");
    not_meaningful.push_back("sizing.motor.energy_per_revolution");
  }
  j["not_meaningful"] = not_meaningful;
  j["stall"] = nullptr;
  j["start_up"] = start_up ? startUpJson(*start_up) : nullptr;
  addStatus(j, scene, run, r, start_up.get(), start_load, num);
  return j;
}

void writeSummaryAtomic(const std::string& path, const nlohmann::json& summary) {
  writeFileAtomic(path, summary.dump(2) + "\n");
}

}  // namespace rollerdyn
