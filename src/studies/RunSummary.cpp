#include "studies/RunSummary.h"

#include <algorithm>
#include <exception>
#include <filesystem>
#include <optional>
#include <utility>
#include <vector>

#include "analysis/FrictionChecks.h"
#include "analysis/SizingSummary.h"
#include "analysis/Summary.h"
#include "io/FieldFormat.h"
#include "motor/MotorLawFactory.h"
#include "report/OutputFolder.h"
#include "scene/KeyEffects.h"
#include "scene/Plausibility.h"
#include "studies/FlywheelByRuns.h"
#include "studies/ResonanceCheck.h"
#include "studies/StartLoad.h"

namespace rollerdyn {

namespace {

// "motor.catalogue.current, motor.catalogue.efficiency" as "motor.catalogue.{current, efficiency}":
// keys under one section together, in the order of their sections' first key.
std::string groupedKeyNames(const std::vector<std::string>& keys) {
  std::vector<std::pair<std::string, std::vector<std::string>>> sections;
  for (const std::string& k : keys) {
    const std::size_t dot = k.rfind('.');
    const std::string parent = dot == std::string::npos ? "" : k.substr(0, dot);
    auto it = std::find_if(sections.begin(), sections.end(), [&](const auto& p) { return p.first == parent; });
    if (it == sections.end()) it = sections.insert(sections.end(), {parent, {}});
    it->second.push_back(dot == std::string::npos ? k : k.substr(dot + 1));
  }
  std::string out;
  for (const auto& [parent, leaves] : sections) {
    std::string part;
    if (leaves.size() == 1) {
      part = parent.empty() ? leaves[0] : parent + "." + leaves[0];
    } else {
      for (const std::string& l : leaves) part += (part.empty() ? "" : ", ") + l;
      part = parent + ".{" + part + "}";
    }
    out += (out.empty() ? "" : ", ") + part;
  }
  return out;
}

// The flywheel that meets δ* from runs, beside the estimate (FlywheelByRuns.h), started as the
// estimate's check runs are (at this run's mean crank speed unless the user set the speed).
void addFlywheelByRuns(const Scene& scene, const std::string& model, nlohmann::json& summary) {
  nlohmann::json& f = summary["sizing"]["flywheel"];
  const nlohmann::json& check = f["check_by_runs"];
  if (!check.is_object() || !check.contains("flywheel_inertia") || !check["flywheel_inertia"].is_number() ||
      !f["target_delta"].is_number() || !f["inertia_effective"].is_number())
    return;
  const bool at_speed = check.value("started_at_speed", false);
  const nlohmann::json& w = summary["omega_crank"]["mean"];
  if (at_speed && !w.is_number()) return;
  const double omega = at_speed ? w.get<double>() : scene.initial.crank_speed;
  f["by_runs"] = toJson(flywheelByRuns(scene, model, check["flywheel_inertia"].get<double>(), omega,
                                       f["target_delta"].get<double>(), f["inertia_effective"].get<double>()));
  f["by_runs"]["started_at_crank_speed"] = omega;
  f["by_runs"]["location"] = check.value("location", "");  // the check's words: crankshaft | motor shaft
}

// Where the circuit of the run's motor law came from when it is fitted to the catalogue
// (FitOrigin, CatalogueFit.h: the one place that says it); null when no fit is behind the law.
nlohmann::json motorFitJson(const Scene& scene) {
  std::optional<FitOrigin> origin;
  if (scene.motor.enabled) try {
      origin = sceneFitOrigin(scene);  // the fit the run's law was built from: kept in this process
    } catch (const std::exception&) {
      // a catalogue that cannot be fitted: the run could not build the law and said so
    }
  if (!origin) return nullptr;
  return {{"from_cache", origin->from_cache},
          {"cache_file", origin->cache_file.empty() ? nlohmann::json(nullptr) : nlohmann::json(origin->cache_file)},
          {"fitted_on", origin->fitted_on},
          {"fit_seconds", origin->fit_seconds},
          {"text", origin->describe()}};
}

// A run that a rule ended early (the drive stalled, rocked without gaining, or came to rest)
// never reached its t_end, and a longer one ends at the same moment: the rules look only back.
// The sentence that says so ("" when t_end had its effect or was not given).
std::string tEndWithoutEffect(const Scene& scene, const RunResult& run, const std::string& motion) {
  const bool given_t_end =
      std::find(scene.given_keys.begin(), scene.given_keys.end(), "simulation.t_end") != scene.given_keys.end();
  if (!(given_t_end && !run.stats.complete && (motion == "stalled" || motion == "rocking" || motion == "at_rest") &&
        run.timeseries.has("t") && !run.timeseries.rows.empty()))
    return "";
  const double t_last = run.timeseries.rows.back()[run.timeseries.index("t")];
  if (!(t_last < scene.simulation.t_end - 0.5 * scene.simulation.output_step)) return "";
  return "simulation.t_end has no effect on this run: it ended at t = " + significant(t_last, 4) + " s, when the " +
         (motion == "at_rest" ? std::string("machine came to rest")
          : motion == "rocking" ? std::string("crank rocked without gaining")
                                : std::string("drive stalled")) +
         " (see status), and a longer run ends there too";
}

// Keys the scene gives that this model's run does not read: said, never silently dropped.
// One warning line names them; summary.json keys_without_effect says why for each.
void addKeysWithoutEffect(const Scene& scene, const RunResult& run, nlohmann::json& summary) {
  summary["keys_without_effect"] = nlohmann::json::array();
  std::vector<std::string> keys;
  std::vector<std::string> without = keysWithoutEffect(scene, run.model);
  // And those whose event the run never reached (the start-up answers find them).
  if (summary.contains("start_up") && summary["start_up"].is_object() &&
      summary["start_up"].contains("keys_not_reached"))
    for (const auto& k : summary["start_up"]["keys_not_reached"]) without.push_back(k.get<std::string>());
  const std::string t_end = tEndWithoutEffect(scene, run, summary.value("motion", ""));
  if (!t_end.empty()) without.push_back(t_end);
  for (const std::string& w : without) {
    summary["keys_without_effect"].push_back(w);
    keys.push_back(w.substr(0, w.find(' ')));
  }
  const std::string names = groupedKeyNames(keys);
  if (!names.empty())
    summary["warnings"].push_back("scene keys without effect on this " + run.model + " model's run: " + names +
                                  " (why for each: summary.json keys_without_effect)");
}

// The runs that check the flywheel's estimate, and with `by_runs` the flywheel sized by runs.
void addFlywheelChecks(const Scene& scene, const std::string& model, bool by_runs, nlohmann::json& summary) {
  if (!(summary.contains("sizing") && summary["sizing"].is_object() && summary["sizing"]["flywheel"].is_object()))
    return;
  summary["sizing"]["flywheel"]["check_by_runs"] = flywheelChecks(summary);  // the runs that check its estimate
  if (by_runs) addFlywheelByRuns(scene, model, summary);
}

// The console's share of the summary: the run's warnings (the first run_warnings) apart from the
// resonance warnings, and the verdict's lines.
void passMessages(const nlohmann::json& summary, std::size_t run_warnings, const RunResonance& verdict,
                  RunMessages& messages) {
  for (std::size_t i = 0; i < summary["warnings"].size(); ++i)
    if (summary["warnings"][i].is_string())
      (i < run_warnings ? messages.run_warnings : messages.resonance_warnings)
          .push_back(summary["warnings"][i].get<std::string>());
  messages.resonance_verdict = verdict.verdict_line;
  messages.first_estimate = verdict.first_estimate.sentences;
}

}  // namespace

nlohmann::json summarizeRun(const Scene& scene, const RunResult& run, const RunSummaryOptions& options,
                            RunMessages* messages) {
  const StartLoad start_load = startLoadOf(scene);  // explains a stall
  nlohmann::json summary = makeSummary(scene, run, &start_load);
  summary["scene_path"] =
      options.scene_file.empty()
          ? nlohmann::json(nullptr)
          : nlohmann::json(std::filesystem::absolute(options.scene_file).lexically_normal().string());
  summary["overrides"] = options.overrides;
  summary["motor_fit"] = motorFitJson(scene);
  addFlywheelChecks(scene, run.model, options.flywheel_by_runs, summary);
  if (!summary.contains("warnings") || !summary["warnings"].is_array()) summary["warnings"] = nlohmann::json::array();
  for (const std::string& w : plausibilityWarnings(scene)) summary["warnings"].push_back(w);
  addKeysWithoutEffect(scene, run, summary);
  // summary["guide_friction"] and its warnings: self-locking, dead centre, quasi-static friction work.
  addFrictionWarnings(scene, run, summary);
  const std::size_t run_warnings = summary["warnings"].size();
  // The resonance and stability verdict, made once (ResonanceCheck.h): at the run's steady mean crank
  // speed, the modal analysis deciding, the two-mass first estimate beside it.
  const RunResonance verdict = judgeRunResonance(scene, runStateOf(summary), options.modal ? &options.modal->report : nullptr);
  putRunResonance(verdict, summary);
  if (options.modal) modes::addRunModes(*options.modal, summary);
  if (messages) passMessages(summary, run_warnings, verdict, *messages);
  return summary;
}

void writeRunFiles(const std::string& out_dir, const RunResult& run, const nlohmann::json& summary,
                   const modes::RunModal* modal) {
  writeRunTables(out_dir, run);
  if (modal) modes::writeRunModesFiles(out_dir, *modal, summary.value("modes", nlohmann::json::object()));
  writeSummaryAtomic(out_dir + "/summary.json", summary);
}

}  // namespace rollerdyn
