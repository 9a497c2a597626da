// The flywheel part of the drive sizing's console table (sizingText, SizingSummary.cpp) and the
// runs that check its proposal (sizing.flywheel.check_by_runs), both from summary.json only.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "analysis/SizingSummary.h"
#include "io/FieldFormat.h"

namespace rollerdyn {

using nlohmann::json;

namespace {


// A command-line word, quoted for the shell where it needs it.
std::string shellWord(const std::string& a) {
  if (!a.empty() && a.find_first_of(" '\"$`\\*?;&|<>()") == std::string::npos) return a;
  std::string q = "'";
  for (char c : a) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

// The flywheel found by runs (studies/FlywheelByRuns.h): every run tried, then the answer.
std::string flywheelByRunsText(const json& f, const std::string& pad) {
  const json& b = jsonMember(f, "by_runs");
  if (!b.is_object()) return "";
  std::ostringstream o;
  const std::string where = jsonText(jsonMember(b, "location"), "n/a");
  o << pad << "by runs started at " << jsonNumberText(jsonMember(b, "started_at_crank_speed"), "%.4g") << " rad/s (" << where << "):";
  for (const json& r : jsonMember(b, "runs"))
    o << " " << jsonNumberText(jsonMember(r, "inertia"), "%.4g") << " kg·m² gives δ " << jsonNumberText(jsonMember(r, "delta"), "%.4g") << ";";
  o << "\n";
  const bool found = jsonFlag(b, "found");
  if (found)
    o << pad << "a flywheel of " << jsonNumberText(jsonMember(b, "inertia"), "%.4g") << " kg·m² on the " << where << " meets δ* = "
      << jsonNumberText(jsonMember(f, "target_delta"), "%.4g") << " in a run (δ = " << jsonNumberText(jsonMember(b, "delta"), "%.4g") << ")\n";
  if (jsonMember(b, "note").is_string()) o << pad << jsonMember(b, "note").get<std::string>() << "\n";
  return o.str();
}

// No proposal: δ* met only by the run's measured δ, never by an estimate.
std::string metByTheRunText(const json& f, const std::string& pad) {
  const json& basis = jsonMember(f, "basis");
  if (!basis.is_string()) return "";
  return pad + "for δ* = " + jsonNumberText(jsonMember(f, "target_delta"), "%.4g") + ": " + basis.get<std::string>() +
         " (δ = " + jsonNumberText(jsonMember(f, "delta"), "%.4g") + ")\n";
}

// The whole flywheel at each place, and what that adds to the present one (the third trial read
// "flywheel 1317 kg·m²" as the amount to add to the 1103 already fitted).
std::string proposalText(const json& f, const std::string& pad) {
  std::ostringstream o;
  o << pad << "for δ* = " << jsonNumberText(jsonMember(f, "target_delta"), "%.4g") << ", by estimate: a flywheel of "
    << jsonNumberText(jsonMember(f, "flywheel_crankshaft"), "%.4g") << " kg·m² in all on the crankshaft ("
    << jsonNumberText(jsonMember(f, "added_inertia_crankshaft"), "%.4g") << " more than now) or "
    << jsonNumberText(jsonMember(f, "flywheel_motor_shaft"), "%.4g") << " kg·m² in all on the motor shaft\n";
  return o.str();
}

// The two estimates of what to add (by the excess work, by the run's δ·J), or the energy method's one.
std::string estimatesText(const json& f, const std::string& pad) {
  const json& J_req = jsonMember(f, "inertia_required");
  if (!J_req.is_number())
    return pad + "(energy method, J·δ constant; the motor's slip and the carts' inertia vary over a turn)\n";
  const double J_now = jsonDouble(jsonMember(f, "inertia_effective"));
  std::ostringstream o;
  o << pad << "(the larger of two estimates of what to add: by the excess work ΔA "
    << jsonNumberText(jsonMember(f, "excess_work"), "%.4g") << " J of a revolution\n"
    << pad << "at constant speed, J* = ΔA/(δ*·ω̄²) = " << jsonNumberText(J_req, "%.4g")
    << " kg·m² at the crank less the present J " << jsonNumberText(jsonMember(f, "inertia_effective"), "%.4g") << ": "
    << (J_req.get<double>() > J_now ? jsonNumberText(json(J_req.get<double>() - J_now), "%.4g") + " kg·m²" : std::string("nothing"))
    << ";\n"
    << pad << "by the run's own δ·J held constant, " << jsonNumberText(jsonMember(f, "added_inertia_energy_method"), "%.4g")
    << " kg·m² (short where the run's δ is large);\n"
    << pad << "motor slip and coupling elasticity neglected)\n";
  return o.str();
}

// The commands that check the estimate by runs (flywheelChecks), as the console prints them.
std::string checkByRunsText(const json& f, const std::string& pad) {
  const json& check = jsonMember(f, "check_by_runs");
  if (!check.is_object()) return "";
  std::ostringstream o;
  const std::string speed = jsonFlag(check, "started_at_speed")
                                ? " started at this run's mean crank speed (whether the drive starts from rest with "
                                  "it is a separate run)"
                                : "";
  const json& run = jsonMember(check, "run_at_proposal");
  const json& smallest = jsonMember(check, "smallest_from_runs");
  if (run.is_string())
    o << pad << "check the estimate: δ of a run with flywheel.inertia = " << jsonNumberText(jsonMember(check, "flywheel_inertia"), "%.4g")
      << " kg·m² (" << jsonText(jsonMember(check, "location"), "n/a") << ")" << speed << ":\n      " << run.get<std::string>() << "\n";
  if (smallest.is_string())
    o << pad << "the smallest flywheel (" << jsonText(jsonMember(check, "location"), "n/a") << ") that meets δ* in steady running, from runs:\n      "
      << smallest.get<std::string>() << "\n";
  if (jsonMember(check, "note").is_string()) o << pad << jsonMember(check, "note").get<std::string>() << "\n";
  return o.str();
}

}  // namespace

std::string flywheelText(const json& summary) {
  std::ostringstream o;
  const json& f = jsonMember(jsonMember(summary, "sizing"), "flywheel");
  const std::string pad = "                                    ";
  o << "  flywheel                          kinetic-energy swing ΔT " << jsonNumberText(jsonMember(f, "kinetic_energy_swing"), "%.4g")
    << " J per revolution; drive inertia at the crank J " << jsonNumberText(jsonMember(f, "inertia_effective"), "%.4g")
    << " kg·m²; δ " << jsonNumberText(jsonMember(f, "delta"), "%.4g") << "\n";
  if (!jsonMember(f, "target_delta").is_number()) {
    o << pad << "target δ* not given (sizing.target_delta)\n";
    return o.str();
  }
  if (!jsonFlag(f, "estimate")) return o.str() + metByTheRunText(f, pad);
  o << proposalText(f, pad) << estimatesText(f, pad);
  const json& basis = jsonMember(f, "basis");
  if (basis.is_string()) o << pad << basis.get<std::string>() << "\n";
  o << flywheelByRunsText(f, pad) << checkByRunsText(f, pad);
  return o.str();
}

namespace {

// The user's --set options, as command-line words; whether one of them sets the start speed.
struct UserOverrides {
  std::string sets;
  bool sets_speed = false;
};

UserOverrides userOverrides(const json& summary) {
  UserOverrides u;
  if (jsonMember(summary, "overrides").is_array())
    for (const json& ov : jsonMember(summary, "overrides"))
      if (ov.is_string()) {
        u.sets += " --set " + shellWord(ov.get<std::string>());
        u.sets_speed = u.sets_speed || ov.get<std::string>().rfind("initial.crank_speed=", 0) == 0;
      }
  return u;
}

// The same model as this run (simulate and optimize run the multibody model unless told otherwise).
std::string modelOption(const json& summary) {
  const bool reduced = jsonMember(summary, "model").is_string() && jsonMember(summary, "model").get<std::string>() == "reduced";
  return reduced ? " --model reduced" : "";
}

// The two commands: a run with the proposal, and the smallest flywheel that meets δ* by runs.
void addCheckCommands(json& c, const std::string& head, const std::string& value, double proposal,
                      const json& target_delta) {
  c["run_at_proposal"] = "rollerdyn simulate " + head + " --set flywheel.inertia=" + value;
  // A range that holds the estimate with room to spare.
  const double upper = std::max(10.0, 3.0 * proposal);
  c["smallest_from_runs"] = "rollerdyn optimize " + head + " --param flywheel.inertia --range 0:" + jsonNumberText(json(upper), "%.0f") +
                            " --minimize flywheel.inertia --constraint 'delta<=" + jsonNumberText(target_delta, "%.4g") + "'";
}

// A scene that is not a file has no command to run: the values to run by hand (`start_speed`
// "" when the run starts as the scene says).
std::string notAFileNote(const std::string& value, const std::string& start_speed) {
  return "the scene is not a file: check the estimate by a run with flywheel.inertia = " + value + " kg·m²" +
         (!start_speed.empty() ? " and initial.crank_speed = " + start_speed + " rad/s" : std::string());
}

// The crank speed [rad/s] the check runs start at, as printed ("" when they start as the scene
// says: the user's --set gives one, or the run did not turn). The flywheel is sized for steady
// running, so each run starts at this run's mean crank speed: a heavy flywheel's slow start from
// rest (which may not settle within t_end) would not make every design look unusable.
std::string checkRunStartSpeed(const json& summary, const UserOverrides& u) {
  const json& w_mean = jsonMember(jsonMember(summary, "omega_crank"), "mean");
  const bool start_at_speed = !u.sets_speed && w_mean.is_number() && w_mean.get<double>() > 0;
  return start_at_speed ? jsonNumberText(w_mean, "%.4g") : std::string();
}

}  // namespace

json flywheelChecks(const json& summary) {
  const json& f = jsonMember(jsonMember(summary, "sizing"), "flywheel");
  if (!jsonFlag(f, "estimate") || !jsonMember(f, "target_delta").is_number()) return nullptr;
  const bool motor_shaft = jsonMember(f, "location").is_string() && jsonMember(f, "location").get<std::string>() == "motor_shaft";
  const json& proposal = jsonMember(f, motor_shaft ? "flywheel_motor_shaft" : "flywheel_crankshaft");
  if (!proposal.is_number()) return nullptr;
  // The flywheel as the console prints it, so the run checks exactly the printed value.
  const std::string value = jsonNumberText(proposal, "%.4g");
  json c = {{"flywheel_inertia", std::stod(value)}, {"location", motor_shaft ? "motor shaft" : "crankshaft"}};
  // The user's --set options, and the start at speed.
  UserOverrides u = userOverrides(summary);
  const std::string start_speed = checkRunStartSpeed(summary, u);
  if (!start_speed.empty()) u.sets += " --set initial.crank_speed=" + start_speed;
  c["started_at_speed"] = !start_speed.empty();
  const json& scene = jsonMember(summary, "scene_path");
  if (!scene.is_string()) {
    c["run_at_proposal"] = c["smallest_from_runs"] = nullptr;
    c["note"] = notAFileNote(value, start_speed);
    return c;
  }
  addCheckCommands(c, shellWord(scene.get<std::string>()) + u.sets + modelOption(summary), value,
                   proposal.get<double>(), jsonMember(f, "target_delta"));
  return c;
}

}  // namespace rollerdyn
