// The output columns of a run, in one table: every column of timeseries.csv and reactions.csv
// (or every family of columns numbered by cart, main bearing or crankshaft segment) with its
// unit, its meaning, the models that write it and when, in the order the files hold them.
// Everything else that names a column reads it from here: the CSV headers' units (io/Table.h
// columnUnit), both models' column lists and the positions their rows are filled at
// (ColumnLayout: a value is written by its column, never by its place in a list), and the
// column tables of the outputs page (outputColumnsMarkdown).
//
// What the table's meanings cannot say in a line, and the models' code relies on:
//  * signs: N_* > 0 when the guide presses the cart's guide roller down (Loveikin, Pochka,
//    Romasevych (2018) fig. 3); F_rod > 0 in tension, the rod's force on the cart at B along
//    B -> A (eq. (14)): a rod with mass also pushes across its axis, and the reduced model's
//    quasi-static statics report eq. (14)'s axial force, which differs from it by half the rod
//    weight times sin β;
//  * the guide normal forces and the friction: the multibody model's are the constraint reactions
//    (friction by loads.guide_friction.normal_force), the reduced model's the cart statics of
//    reduced.guide_normals (kinetostatic: with inertial forces; quasi_static: the papers');
//  * a model that cannot compute a column leaves it out (the reduced model has no crank-pin or
//    bearing forces); the motor's angle and speed are reduced to the crank axis (rotor / u).
#pragma once

#include <string>
#include <vector>

namespace rollerdyn {

enum class OutputFile { Timeseries, Reactions };

// A quantity a run writes; a family (x_cart_j, ...) is one quantity.
enum class Column {
  t, phi_motor, phi_crank, omega_motor, omega_crank, eps_crank, eps_motor,
  twist, twist_rate, twist_accel, coupling_torque, motor_torque, load_torque,
  x_cart, v_cart, a_cart,
  stator_current, supply_voltage_ratio, supply_frequency_ratio, brake_torque,
  reducer_loss_torque, tooth_contact, shaft_torque,
  N_front, N_rear, F_rod, friction, crankpin_x, crankpin_y,
  bearing_x, bearing_y, main_bearing_x, main_bearing_y,
  count  // the number of quantities, not a column
};

enum class ColumnModels { Both, Multibody, Reduced };

// When a model that writes a column writes it.
enum class ColumnCondition {
  Always,
  MotorCurrent,    // the motor law models the stator current
  SupplySwitches,  // the supply switches (a starting method, a switch-off)
  Brake,           // a brake on the motor shaft
  ReducerLosses,   // the reducer's losses by the direction of the power flow
  Backlash,        // an elastic coupling with backlash in the reducer
  TorsionalChain,  // the crankshaft as a torsional chain
  MainBearings,    // the throws and main bearings placed along the crankshaft
};

// What numbers a family's columns: nothing (a single column), the cart j = 1..n, the main
// bearing k = 1..m along the shaft, the crankshaft segment k = 1..n-1 from the coupling.
enum class ColumnIndex { None, Cart, MainBearing, ShaftSegment };

struct OutputColumn {
  OutputFile file;
  Column id;
  std::string name;     // the bare name; a family's prefix (name_<j>)
  std::string unit;     // as in the CSV header name[unit], ASCII
  std::string meaning;  // one line, the engineer's words
  ColumnModels models;
  ColumnCondition when;
  ColumnIndex index;
};

// Every output column, timeseries.csv's then reactions.csv's, each file's in its column order.
// Consecutive families of one index are written interleaved: x_cart_1, v_cart_1, a_cart_1,
// x_cart_2, ...
const std::vector<OutputColumn>& outputColumns();

// What decides which columns a run writes, as the model that runs knows it.
struct WrittenColumns {
  bool multibody = true;  // which model writes (else the reduced model)
  int carts = 0;
  bool motor_current = false;
  bool supply_switches = false;
  bool brake = false;
  bool reducer_losses = false;
  bool backlash = false;
  int shaft_segments = 0;  // segments of a torsional chain (0: a rigid crankshaft)
  int main_bearings = 0;   // main bearings placed along the shaft (0: only their resultant)
};

// The columns of one file a run writes, in order, and where each value of a row goes.
class ColumnLayout {
 public:
  ColumnLayout() = default;
  ColumnLayout(OutputFile file, const WrittenColumns& written);

  const std::vector<std::string>& names() const { return names_; }
  std::size_t size() const { return names_.size(); }
  bool has(Column c) const { return first_[static_cast<int>(c)] >= 0; }
  // Makes `row` a row of this layout, every value NaN until set (keeps its storage).
  void reset(std::vector<double>& row) const;
  // Sets a column's value in `row`; `number` is the family's j or k (1-based). Setting a column
  // the layout does not hold is a programming error (std::logic_error).
  void set(std::vector<double>& row, Column c, double value) const { row[position(c, 1)] = value; }
  void set(std::vector<double>& row, Column c, int number, double value) const { row[position(c, number)] = value; }
  // A column's value in `row` (same positions as set()).
  double get(const std::vector<double>& row, Column c, int number = 1) const { return row[position(c, number)]; }

 private:
  std::size_t position(Column c, int number) const;
  // Appends one group's columns, numbered 1..numbers, interleaved by number (x_1, v_1, x_2, v_2…).
  void addGroup(const std::vector<const OutputColumn*>& members, int numbers);
  std::vector<std::string> names_;
  std::vector<int> first_ = std::vector<int>(static_cast<int>(Column::count), -1);  // of number 1
  std::vector<int> stride_ = std::vector<int>(static_cast<int>(Column::count), 0);   // from j to j+1
  std::vector<int> numbers_ = std::vector<int>(static_cast<int>(Column::count), 0);  // family size
};

// A family member's name: "x_cart" and 3 give "x_cart_3".
std::string numberedColumnName(Column c, int number);

// The unit of a bare column name of a run ("" when the name is none of the table's):
// single columns by name, families by prefix and a numeric suffix.
std::string outputColumnUnit(const std::string& name);

// The column tables of the outputs page: per file a Markdown table column, unit, meaning,
// written by (which model, when).
std::string outputColumnsMarkdown();

}  // namespace rollerdyn
