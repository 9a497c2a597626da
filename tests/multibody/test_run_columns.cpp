// The columns both models write, against the output column table (io/OutputColumns.h), on the
// shipped scenes and on scenes that switch on every optional column (a motor law with its
// current, a supply that switches and a brake, the reducer's losses, backlash, a torsional chain,
// the main bearings placed): every column a run writes is in the table with a unit, every value of
// every row is set, and every column of the table is written by the model(s) it names.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "io/OutputColumns.h"
#include "io/Table.h"
#include "multibody/MultibodySimulation.h"
#include "reduced/ReducedModel.h"
#include "scene/SceneParser.h"

namespace rollerdyn {
namespace {

struct SceneCase {
  const char* file;
  std::vector<std::string> sets;
};

std::vector<SceneCase> cases() {
  return {
      {"balanced-4cart", {}},
      {"recuperative-2cart", {}},
      {"energy-balanced-3cart", {}},
      {"cam-drive", {}},
      {"cam-drive", {"simulation.formulation=constrained"}},
      {"balanced-4cart", {"simulation.formulation=constrained"}},
      {"balanced-4cart", {"motor.model=park", "reducer.backlash=0.0017453"}},
      {"recuperative-2cart", {"reducer.losses=power_flow", "reducer.efficiency_reverse=0.8"}},
      {"balanced-4cart",
       {"motor.model=circuit", "motor.start.method=star_delta", "motor.start.changeover_time=0.01",
        "motor.stop.t_off=0.02", "motor.stop.brake_torque=100"}},
      {"balanced-4cart",
       {"crankshaft.throw_positions=[0.2, 0.4, 0.6, 0.8]", "crankshaft.bearing_positions=[0, 0.5, 1.0]",
        "crankshaft.torsional_stiffness=1e6", "simulation.formulation=constrained",
        "loads.guide_friction.normal_force=lagged"}},
      {"balanced-4cart",
       {"crankshaft.throw_positions=[0.2, 0.4, 0.6, 0.8]", "crankshaft.bearing_positions=[0, 0.5, 1.0]"}},
  };
}

Scene sceneOf(const SceneCase& c) {
  std::vector<std::string> sets = c.sets;
  sets.push_back("simulation.t_end=0.04");
  return parseSceneFile(std::string(ROLLERDYN_SOURCE_DIR) + "/model/" + c.file + ".yaml", sets);
}

// "<file>:<model>:<column>" of every column a run wrote.
void collect(const Table& t, const std::string& file, const std::string& model, const std::string& what,
             std::set<std::string>& written) {
  for (const std::string& c : t.columns) {
    EXPECT_FALSE(columnUnit(c).empty()) << what << ": " << file << " column " << c << " has no unit";
    written.insert(file + ":" + model + ":" + c);
  }
  for (const std::vector<double>& row : t.rows) {
    ASSERT_EQ(row.size(), t.columns.size()) << what;
    for (std::size_t i = 0; i < row.size(); ++i)
      ASSERT_FALSE(std::isnan(row[i])) << what << ": " << file << " column " << t.columns[i] << " left unset";
  }
}

TEST(RunColumns, EveryColumnOfEitherModelIsInTheTableAndEveryTableColumnIsWritten) {
  std::set<std::string> written;
  for (const SceneCase& c : cases()) {
    const Scene sc = sceneOf(c);
    std::string what = c.file;
    for (const std::string& s : c.sets) what += " " + s;
    const RunResult mb = runMultibodyModel(sc);
    const RunResult red = runReducedModel(sc);
    ASSERT_FALSE(mb.timeseries.rows.empty()) << what;
    ASSERT_FALSE(red.timeseries.rows.empty()) << what;
    collect(mb.timeseries, "timeseries", "multibody", what, written);
    collect(mb.reactions, "reactions", "multibody", what, written);
    collect(red.timeseries, "timeseries", "reduced", what, written);
    collect(red.reactions, "reactions", "reduced", what, written);
  }
  for (const OutputColumn& c : outputColumns()) {
    const std::string file = c.file == OutputFile::Timeseries ? "timeseries" : "reactions";
    const std::string name = numberedColumnName(c.id, 1);
    const bool multibody = written.count(file + ":multibody:" + name) > 0;
    const bool reduced = written.count(file + ":reduced:" + name) > 0;
    EXPECT_EQ(multibody, c.models != ColumnModels::Reduced) << file << " " << name << " in the multibody model";
    EXPECT_EQ(reduced, c.models != ColumnModels::Multibody) << file << " " << name << " in the reduced model";
  }
}

}  // namespace
}  // namespace rollerdyn
