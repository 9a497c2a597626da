#include "studies/FlywheelByRuns.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "analysis/Summary.h"
#include "compare/RunModel.h"
#include "io/FieldFormat.h"

namespace rollerdyn {

namespace {

// δ of a steady run with this flywheel; NaN when the run does not turn steadily. A heavier
// flywheel slows the settling of the drive's torsional motion, so a run that turns but has not yet
// repeated its revolutions (mean and extremes, analysis/SteadyState.h) is run again twice as long,
// up to kFlywheelRunLengthening times the scene's t_end.
double deltaWith(const Scene& base, const std::string& model, double inertia, double omega_mean) {
  Scene s = base;
  s.flywheel.inertia = inertia;
  s.initial.crank_speed = omega_mean;
  s.sizing.target_delta = 0;  // the runs answer δ; they do not size again
  for (double factor = 1.0; factor <= kFlywheelRunLengthening; factor *= 2.0) {
    s.simulation.t_end = base.simulation.t_end * factor;
    const RunResult run = runModel(s, model);
    const nlohmann::json j = makeSummary(s, run, nullptr);
    if (j.value("motion", "") != "turning") break;
    if (j["delta"].is_number() && j["steady_state"].value("reached", false)) return j["delta"].get<double>();
  }
  return std::nan("");
}

// The flywheel counts at the crank once on the crankshaft, u² times on the motor shaft: δ follows
// the drive's whole inertia at the crank, J_0 (without the flywheel) plus that.
struct InertiaAtCrank {
  double J0, k;
  double total(double J) const { return J0 + k * J; }
};

// One run with flywheel J into r.tried; false (with r.note why) when it cannot be made or does
// not turn steadily.
bool runWithFlywheel(const Scene& scene, const std::string& model, double J, double omega_mean, FlywheelByRuns& r,
                     double* d) {
  *d = std::nan("");
  try {
    *d = deltaWith(scene, model, J, omega_mean);
  } catch (const std::invalid_argument& e) {  // a flywheel the model refuses (physics/CrankInertia.h)
    r.note = "the run with flywheel.inertia = " + significant(J, 4) + " kg·m² cannot be made: " + e.what();
    return false;
  }
  r.tried.push_back({J, *d});
  if (std::isfinite(*d)) return true;
  r.note = "the run with flywheel.inertia = " + significant(J, 4) + " kg·m² did not turn steadily within " +
           significant(kFlywheelRunLengthening, 2) + " times simulation.t_end";
  return false;
}

// The next flywheel to run after J gave δ = d.
double nextInertia(const InertiaAtCrank& c, const FlywheelByRuns& r, double J, double d, double target) {
  // δ ∝ J_total^(-p): p = 1 (the energy method) until two runs give their own slope.
  double p = 1.0;
  if (r.tried.size() >= 2) {
    const auto& [Ja, da] = r.tried[r.tried.size() - 2];
    if (std::isfinite(da) && da > 0 && d > 0 && std::abs(std::log(c.total(J) / c.total(Ja))) > 1e-9)
      p = std::clamp(-std::log(d / da) / std::log(c.total(J) / c.total(Ja)), 0.2, 5.0);
  }
  // Aim a little below δ* (the middle of the accepted band) so the next run lands inside it.
  const double aim = 0.5 * (1.0 + kFlywheelAccept) * target;
  const double next_total = c.total(J) * std::pow(d / aim, 1.0 / p);
  return std::max(0.0, (next_total - c.J0) / c.k);
}

// The search's outcome in words where it found none or may have found too large a flywheel.
void concludeSearch(FlywheelByRuns& r, double target) {
  if (!r.found) {
    if (r.note.empty())
      r.note = "no run of " + std::to_string(kFlywheelMaxRuns) + " met δ* (the last gave δ = " +
               significant(r.tried.back().second, 4) + ")";
    if (!r.tried.empty()) r.inertia = r.tried.back().first, r.delta = r.tried.back().second;
  } else if (!(r.delta >= kFlywheelAccept * target)) {
    r.note = "the smallest flywheel that met δ* in " + std::to_string(r.tried.size()) +
             " runs gives δ below the accepted band: a smaller one may do";
  }
}

}  // namespace

FlywheelByRuns flywheelByRuns(const Scene& scene, const std::string& model, double first_guess, double omega_mean,
                              double target, double inertia_now) {
  FlywheelByRuns r;
  const double k = scene.flywheel.location == FlywheelLocation::MotorShaft ? scene.reducer.ratio * scene.reducer.ratio : 1.0;
  const InertiaAtCrank crank{std::max(inertia_now - k * scene.flywheel.inertia, 1e-9), k};
  double J = std::max(first_guess, 0.0);
  for (int i = 0; i < kFlywheelMaxRuns; ++i) {
    double d = std::nan("");
    if (!runWithFlywheel(scene, model, J, omega_mean, r, &d)) break;
    const bool met = d <= target && d >= kFlywheelAccept * target;
    if (d <= target && (!r.found || J < r.inertia)) r.found = true, r.inertia = J, r.delta = d;
    if (met) break;
    J = nextInertia(crank, r, J, d, target);
  }
  concludeSearch(r, target);
  return r;
}

nlohmann::json toJson(const FlywheelByRuns& f) {
  nlohmann::json j;
  j["found"] = f.found;
  j["inertia"] = f.inertia;
  j["delta"] = std::isfinite(f.delta) ? nlohmann::json(f.delta) : nlohmann::json(nullptr);
  j["runs"] = nlohmann::json::array();
  for (const auto& [J, d] : f.tried)
    j["runs"].push_back({{"inertia", J}, {"delta", std::isfinite(d) ? nlohmann::json(d) : nlohmann::json(nullptr)}});
  j["note"] = f.note.empty() ? nlohmann::json(nullptr) : nlohmann::json(f.note);
  return j;
}

}  // namespace rollerdyn
