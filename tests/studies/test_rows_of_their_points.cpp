// Every sweep row and every optimization evaluation belongs to its point: its metrics equal those
// of the same point run on its own (the scene file with the point's --set values, parsed, run and
// summarised here without the sweep or the optimizer), and the point's values stand in its row of
// sweep.csv. Points are chosen with clearly different metrics (δ differs by more than 10 % between
// any two), so a row paired with another point's run cannot pass. The same run twice gives the
// same numbers to the last bit (deterministic integrators, nothing shared): compared exactly,
// up to the CSV's 12 significant digits for the file.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "analysis/Summary.h"
#include "cli/CliTestSupport.h"
#include "reduced/ReducedModel.h"
#include "scene/SceneParser.h"
#include "studies/Optimizer.h"
#include "studies/Sweep.h"

namespace rollerdyn {
namespace {

const std::string kScene = std::string(ROLLERDYN_SOURCE_DIR) + "/model/recuperative-2cart.yaml";
const std::vector<std::string> kBase = {"simulation.t_end=8"};

nlohmann::json ownRun(const std::string& key, const std::string& value) {
  std::vector<std::string> sets = kBase;
  sets.push_back(key + "=" + value);
  const Scene sc = parseSceneFile(kScene, sets);
  return makeSummary(sc, runReducedModel(sc));
}

void expectSameMetrics(const SweepPoint& row, const nlohmann::json& own, const std::string& what) {
  const std::vector<std::pair<std::string, double>> m = {
      {"delta", own["delta"].get<double>()},
      {"H", own["H"].get<double>()},
      {"k_p", own["k_p"].get<double>()},
      {"omega_crank_mean", own["omega_crank"]["mean"].get<double>()},
      {"omega_crank_max", own["omega_crank"]["max"].get<double>()},
      {"eps_crank_abs_max", own["eps_crank_abs_max"].get<double>()},
      {"motor_torque_rotor_rms", own["sizing"]["motor"]["torque_shaft"]["rms"].get<double>()}};
  for (const auto& [name, value] : m) EXPECT_EQ(row.metric(name), value) << what << ": " << name;
}

TEST(Sweep, RowsAreTheirPointsRunAlone) {
  SweepOptions o;
  o.scene_path = kScene;
  o.base_overrides = kBase;
  o.params = {parseSweepValues("crank.offset_deg", "0,60,90,150")};
  o.model = "reduced";
  o.threads = 2;
  const SweepResult r = runSweep(o);
  ASSERT_EQ(r.points.size(), 4u);
  for (std::size_t i = 0; i < r.points.size(); ++i) {
    expectSameMetrics(r.points[i], ownRun("crank.offset_deg", r.points[i].texts[0]), "point " + r.points[i].texts[0]);
    for (std::size_t k = 0; k < i; ++k)
      EXPECT_GT(std::abs(r.points[i].metric("delta") / r.points[k].metric("delta") - 1.0), 0.1) << "points too alike";
  }
  // sweep.csv as written: each row's offset beside its own point's δ.
  test::TempDir out("rows-of-points");
  writeSweepOutputs(o, r, out.str());
  std::ifstream in(out.str() + "/sweep.csv");
  std::string header, line;
  std::getline(in, header);
  std::vector<std::string> names;
  for (std::stringstream hs(header); std::getline(hs, line, ',');) names.push_back(line.substr(0, line.find('[')));
  const auto col = [&](const std::string& n) { return std::size_t(std::find(names.begin(), names.end(), n) - names.begin()); };
  ASSERT_LT(col("delta"), names.size());
  int rows = 0;
  while (std::getline(in, line)) {
    std::vector<std::string> f;
    for (std::stringstream ls(line); std::getline(ls, header, ',');) f.push_back(header);
    const nlohmann::json own = ownRun("crank.offset_deg", f.at(col("crank.offset_deg")));
    EXPECT_NEAR(std::stod(f.at(col("delta"))), own["delta"].get<double>(), 1e-11 * own["delta"].get<double>())
        << "sweep.csv row " << rows + 1;
    ++rows;
  }
  EXPECT_EQ(rows, 4);
}

TEST(Optimize, EvaluationsAreTheirPointsRunAlone) {
  OptimizeOptions p;
  p.scene_path = kScene;
  p.base_overrides = kBase;
  p.params = {{"crank.offset_deg", 60.0, 120.0}};
  p.model = "reduced";
  p.minimize = "delta";
  p.method = "bobyqa";
  p.max_evals = 6;
  p.threads = 1;
  const OptimizeResult q = runOptimize(p);
  ASSERT_GE(q.history.size(), 3u);
  for (const OptimizeEvaluation& e : q.history) {
    const nlohmann::json own = ownRun("crank.offset_deg", e.texts.at(0));
    expectSameMetrics(e.point, own, "evaluation at " + e.texts.at(0));
    EXPECT_EQ(e.objective, own["delta"].get<double>()) << "evaluation at " + e.texts.at(0);
  }
}

}  // namespace
}  // namespace rollerdyn
