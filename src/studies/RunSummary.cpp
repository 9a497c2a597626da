#include "studies/RunSummary.h"

#include <filesystem>

#include "analysis/Summary.h"
#include "report/OutputFolder.h"
#include "studies/ResonanceCheck.h"
#include "studies/StartLoad.h"

namespace rollerdyn {

nlohmann::json summarizeRun(const Scene& scene, const RunResult& run, const std::string& scene_file,
                            std::vector<std::string>* warnings) {
  const StartLoad start_load = startLoadOf(scene);  // explains a stall
  nlohmann::json summary = makeSummary(scene, run, &start_load);
  summary["scene_path"] = scene_file.empty()
                              ? nlohmann::json(nullptr)
                              : nlohmann::json(std::filesystem::absolute(scene_file).lexically_normal().string());
  const std::vector<std::string> added = addResonanceWarnings(scene, summary);
  if (warnings) warnings->insert(warnings->end(), added.begin(), added.end());
  return summary;
}

void writeRunFiles(const std::string& out_dir, const RunResult& run, const nlohmann::json& summary) {
  writeRunTables(out_dir, run);
  writeSummaryAtomic(out_dir + "/summary.json", summary);
}

}  // namespace rollerdyn
