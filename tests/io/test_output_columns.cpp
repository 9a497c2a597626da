// The output column table (io/OutputColumns.h): every column with a unit, a meaning and a model
// that writes it; the units are the headers' of every earlier run; a row is filled by column,
// never by position; the outputs page shows the table as it is.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

#include "io/OutputColumns.h"
#include "io/Table.h"

using namespace rollerdyn;

TEST(OutputColumns, EveryColumnHasAUnitAMeaningAndOneEntryPerFile) {
  std::set<std::pair<int, int>> ids;
  std::set<std::pair<int, std::string>> names;
  for (const OutputColumn& c : outputColumns()) {
    EXPECT_FALSE(c.unit.empty()) << c.name;
    EXPECT_FALSE(c.meaning.empty()) << c.name;
    EXPECT_TRUE(ids.insert({int(c.file), int(c.id)}).second) << c.name << " twice in one file";
    EXPECT_TRUE(names.insert({int(c.file), c.name + (c.index == ColumnIndex::None ? "" : "_k")}).second)
        << c.name << " twice in one file";
  }
  // Every quantity has its entry.
  for (int id = 0; id < int(Column::count); ++id) {
    bool found = false;
    for (const OutputColumn& c : outputColumns()) found = found || int(c.id) == id;
    EXPECT_TRUE(found) << "quantity " << id << " has no table entry";
  }
}

TEST(OutputColumns, AColumnInBothFilesHasOneUnit) {
  for (const OutputColumn& a : outputColumns())
    for (const OutputColumn& b : outputColumns())
      if (a.name == b.name && a.index == b.index) {
        EXPECT_EQ(a.unit, b.unit) << a.name;
      }
}

// The headers' units exactly as every earlier run wrote them: a file read by a script keeps its
// column names.
TEST(OutputColumns, UnitsAreTheHeadersOfEarlierRuns) {
  const std::vector<std::pair<std::string, std::string>> single = {
      {"t", "s"}, {"phi_motor", "rad"}, {"phi_crank", "rad"}, {"omega_motor", "rad/s"}, {"omega_crank", "rad/s"},
      {"eps_crank", "rad/s^2"}, {"eps_motor", "rad/s^2"}, {"twist", "rad"}, {"twist_rate", "rad/s"},
      {"twist_accel", "rad/s^2"}, {"coupling_torque", "N*m at the crank axis"},
      {"motor_torque", "N*m at the crank axis"}, {"load_torque", "N*m at the crank axis"},
      {"reducer_loss_torque", "N*m at the crank axis"}, {"bearing_x", "N"}, {"bearing_y", "N"},
      {"stator_current", "A"}, {"supply_voltage_ratio", "-"}, {"supply_frequency_ratio", "-"},
      {"brake_torque", "N*m"}, {"tooth_contact", "1 drive flank/0 teeth apart/-1 reverse flank"}};
  for (const auto& [name, unit] : single) EXPECT_EQ(columnUnit(name), unit) << name;
  const std::vector<std::pair<std::string, std::string>> numbered = {
      {"x_cart", "m"}, {"v_cart", "m/s"}, {"a_cart", "m/s^2"}, {"N_front", "N"}, {"N_rear", "N"},
      {"F_rod", "N"}, {"friction", "N"}, {"crankpin_x", "N"}, {"crankpin_y", "N"}, {"bearing_x", "N"},
      {"bearing_y", "N"}, {"shaft_torque", "N*m"}};
  for (const auto& [name, unit] : numbered) {
    EXPECT_EQ(columnUnit(name + "_1"), unit) << name;
    EXPECT_EQ(columnUnit(name + "_12"), unit) << name;
  }
  EXPECT_EQ(columnUnit("x_cart"), "");      // a family's prefix alone is no column
  EXPECT_EQ(columnUnit("t_1"), "");         // nor a single column with a number
  EXPECT_EQ(columnUnit("M_dynamic"), "");
}

TEST(OutputColumns, EveryColumnIsWrittenBySomeModel) {
  // With every condition met, each entry is in the multibody or the reduced model's layout.
  WrittenColumns all;
  all.carts = 2;
  all.motor_current = all.supply_switches = all.brake = all.reducer_losses = all.backlash = true;
  all.shaft_segments = 1;
  all.main_bearings = 2;
  WrittenColumns reduced = all;
  reduced.multibody = false;
  std::set<std::string> written;
  for (OutputFile f : {OutputFile::Timeseries, OutputFile::Reactions})
    for (const WrittenColumns& w : {all, reduced}) {
      const ColumnLayout layout(f, w);
      for (const std::string& n : layout.names()) written.insert(std::to_string(int(f)) + n);
    }
  for (const OutputColumn& c : outputColumns())
    EXPECT_TRUE(written.count(std::to_string(int(c.file)) + numberedColumnName(c.id, 1))) << c.name;
}

TEST(OutputColumns, FamiliesOfOneIndexAreInterleavedByNumber) {
  WrittenColumns w;
  w.multibody = false;
  w.carts = 2;
  const ColumnLayout reactions(OutputFile::Reactions, w);
  EXPECT_EQ(reactions.names(), (std::vector<std::string>{"t", "N_front_1", "N_rear_1", "F_rod_1", "friction_1",
                                                         "N_front_2", "N_rear_2", "F_rod_2", "friction_2",
                                                         "coupling_torque"}));
  w.multibody = true;
  w.main_bearings = 2;
  const ColumnLayout multibody(OutputFile::Reactions, w);
  const std::vector<std::string>& n = multibody.names();
  ASSERT_EQ(n.size(), 1u + 2 * 6 + 3 + 4);
  EXPECT_EQ(n[6], "crankpin_y_1");
  EXPECT_EQ(n[13], "bearing_x");
  EXPECT_EQ((std::vector<std::string>(n.end() - 4, n.end())),
            (std::vector<std::string>{"bearing_x_1", "bearing_y_1", "bearing_x_2", "bearing_y_2"}));
}

TEST(OutputColumns, ARowIsFilledByColumnNotByPosition) {
  WrittenColumns w;
  w.carts = 3;
  const ColumnLayout L(OutputFile::Timeseries, w);
  std::vector<double> row;
  L.reset(row);
  ASSERT_EQ(row.size(), L.size());
  L.set(row, Column::v_cart, 2, 7.0);
  L.set(row, Column::omega_crank, 3.0);
  for (std::size_t i = 0; i < L.size(); ++i) {
    if (L.names()[i] == "v_cart_2") {
      EXPECT_EQ(row[i], 7.0);
    } else if (L.names()[i] == "omega_crank") {
      EXPECT_EQ(row[i], 3.0);
    } else {
      EXPECT_TRUE(std::isnan(row[i])) << L.names()[i];
    }
  }
  // A column this run does not write, or a cart it does not have, is a programming error.
  EXPECT_THROW(L.set(row, Column::tooth_contact, 1.0), std::logic_error);
  EXPECT_THROW(L.set(row, Column::load_torque, 1.0), std::logic_error);  // the reduced model's
  EXPECT_THROW(L.set(row, Column::x_cart, 4, 1.0), std::logic_error);
}

TEST(OutputColumns, CommittedOutputsPageShowsTheTable) {
  // The column tables of docs/outputs.md are generated from the table: after changing it, put
  // the output of `rollerdyn schema --columns` in their place.
  std::ifstream in(std::string(ROLLERDYN_SOURCE_DIR) + "/docs/outputs.md");
  std::stringstream page;
  page << in.rdbuf();
  ASSERT_FALSE(page.str().empty()) << "docs/outputs.md is missing";
  EXPECT_NE(page.str().find(outputColumnsMarkdown()), std::string::npos)
      << "docs/outputs.md's column tables differ from the output column table: replace them by the output of\n"
         "  ./build/rollerdyn schema --columns\n";
}
