#include "io/OutputColumns.h"

#include <cctype>
#include <limits>
#include <stdexcept>

namespace rollerdyn {

namespace {

using F = OutputFile;
using C = Column;
using M = ColumnModels;
using W = ColumnCondition;
using I = ColumnIndex;

constexpr const char* kAtCrank = "N*m at the crank axis";

// timeseries.csv: time, the motor's and the crank's motion, the coupling twist and the torques on
// the crank axis.
std::vector<OutputColumn> timeseriesDriveColumns() {
  return {
      {F::Timeseries, C::t, "t", "s", "time", M::Both, W::Always, I::None},
      {F::Timeseries, C::phi_motor, "phi_motor", "rad", "motor angle reduced to the crank axis (rotor angle / u)",
       M::Both, W::Always, I::None},
      {F::Timeseries, C::phi_crank, "phi_crank", "rad",
       "crank angle φ of cart 1's crank (with `crankshaft.torsional_stiffness`: of the throw at the coupling end, "
       "whose frame gives cart 1's crank angle were the shaft rigid)",
       M::Both, W::Always, I::None},
      {F::Timeseries, C::omega_motor, "omega_motor", "rad/s", "motor speed reduced to the crank axis (rotor speed / u)",
       M::Both, W::Always, I::None},
      {F::Timeseries, C::omega_crank, "omega_crank", "rad/s", "crank speed dφ/dt", M::Both, W::Always, I::None},
      {F::Timeseries, C::eps_crank, "eps_crank", "rad/s^2", "crank acceleration d²φ/dt²", M::Both, W::Always,
       I::None},
      {F::Timeseries, C::eps_motor, "eps_motor", "rad/s^2", "motor acceleration reduced to the crank axis", M::Both,
       W::Always, I::None},
      {F::Timeseries, C::twist, "twist", "rad", "coupling twist φ_motor − φ_crank (0 for a rigid coupling)",
       M::Both, W::Always, I::None},
      {F::Timeseries, C::twist_rate, "twist_rate", "rad/s", "rate of the coupling twist (0 for a rigid coupling)",
       M::Both, W::Always, I::None},
      {F::Timeseries, C::twist_accel, "twist_accel", "rad/s^2",
       "acceleration of the coupling twist (0 for a rigid coupling)", M::Both, W::Always, I::None},
      {F::Timeseries, C::coupling_torque, "coupling_torque", kAtCrank,
       "elastic plus damping torque the coupling transmits to the crank (a rigid coupling: the torque the motor "
       "side passes on)",
       M::Both, W::Always, I::None},
      {F::Timeseries, C::motor_torque, "motor_torque", kAtCrank,
       "motor torque (of `motor.model`) passed on by the reducer: M·u·η under `reducer.losses: papers`, M·u − L "
       "under `power_flow`; 0 without a motor",
       M::Both, W::Always, I::None},
      {F::Timeseries, C::load_torque, "load_torque", kAtCrank,
       "resisting torque of the loads reduced to the crank axis", M::Reduced, W::Always, I::None},
  };
}

// timeseries.csv: each cart's motion.
std::vector<OutputColumn> timeseriesCartColumns() {
  return {
      {F::Timeseries, C::x_cart, "x_cart", "m", "position of cart j's hinge B along x", M::Both, W::Always, I::Cart},
      {F::Timeseries, C::v_cart, "v_cart", "m/s", "velocity of cart j's hinge B along x", M::Both, W::Always, I::Cart},
      {F::Timeseries, C::a_cart, "a_cart", "m/s^2", "acceleration of cart j's hinge B along x", M::Both, W::Always,
       I::Cart},
  };
}

// timeseries.csv: the columns written only when the scene has what they describe (motor current, a
// switching supply, a brake, reducer losses, backlash, a torsional crankshaft).
std::vector<OutputColumn> timeseriesOptionalColumns() {
  return {
      {F::Timeseries, C::stator_current, "stator_current", "A",
       "RMS line current of the motor (the equivalent star's phase current; in star, the windings' current)",
       M::Both, W::MotorCurrent, I::None},
      {F::Timeseries, C::supply_voltage_ratio, "supply_voltage_ratio", "-",
       "voltage at the motor's terminals over the rated voltage, U/U_n; 0 while switched off", M::Both,
       W::SupplySwitches, I::None},
      {F::Timeseries, C::supply_frequency_ratio, "supply_frequency_ratio", "-",
       "supply frequency over the rated frequency, f/f_n", M::Both, W::SupplySwitches, I::None},
      {F::Timeseries, C::brake_torque, "brake_torque", "N*m",
       "torque of the brake on the motor shaft, at the crank axis", M::Both, W::Brake, I::None},
      {F::Timeseries, C::reducer_loss_torque, "reducer_loss_torque", kAtCrank,
       "the reducer's loss torque L on the motor torque; the loss power L·ω_motor ≥ 0", M::Both, W::ReducerLosses,
       I::None},
      {F::Timeseries, C::tooth_contact, "tooth_contact", "1 drive flank/0 teeth apart/-1 reverse flank",
       "which flank of the reducer's teeth is in contact: 1 the drive flank (twist > b, the motor side drives), 0 "
       "teeth apart (|twist| ≤ b, no torque), −1 the reverse flank (twist < −b); b = backlash/2",
       M::Both, W::Backlash, I::None},
      {F::Timeseries, C::shaft_torque, "shaft_torque", "N*m",
       "torque T_k = c_k·(θ_k − θ_(k+1)) the crankshaft's segment k carries between the k-th and (k+1)-th throw "
       "counted from the coupling (throws in z order), c_k = G·I_p/Δz; > 0 while the drive side leads "
       "([models.md](models.md#the-crankshaft-as-a-torsional-chain))",
       M::Multibody, W::TorsionalChain, I::ShaftSegment},
  };
}

// reactions.csv: time and the forces on each cart.
std::vector<OutputColumn> reactionsCartColumns() {
  return {
      {F::Reactions, C::t, "t", "s", "time", M::Both, W::Always, I::None},
      {F::Reactions, C::N_front, "N_front", "N",
       "guide reaction at cart j's front guide roller, > 0 when the guide presses the roller down", M::Both,
       W::Always, I::Cart},
      {F::Reactions, C::N_rear, "N_rear", "N",
       "guide reaction at cart j's rear guide roller, > 0 when the guide presses the roller down", M::Both,
       W::Always, I::Cart},
      {F::Reactions, C::F_rod, "F_rod", "N",
       "rod force on cart j, > 0 in tension (a cam drive: the cam's force on the cart)", M::Both, W::Always,
       I::Cart},
      {F::Reactions, C::friction, "friction", "N", "guide friction force on cart j along x", M::Both, W::Always,
       I::Cart},
  };
}

// reactions.csv: the forces on the crankshaft (crank pins, main bearings) and the coupling
// torque.
std::vector<OutputColumn> reactionsCrankshaftColumns() {
  return {
      {F::Reactions, C::crankpin_x, "crankpin_x", "N",
       "force of the rod on crank pin j along x, world frame (a cam drive: of the pusher on the cam)", M::Multibody,
       W::Always, I::Cart},
      {F::Reactions, C::crankpin_y, "crankpin_y", "N", "force of the rod on crank pin j along y, world frame",
       M::Multibody, W::Always, I::Cart},
      {F::Reactions, C::bearing_x, "bearing_x", "N",
       "resultant force of the main bearings (all together) on the crankshaft along x, world frame", M::Multibody,
       W::Always, I::None},
      {F::Reactions, C::bearing_y, "bearing_y", "N",
       "resultant force of the main bearings (all together) on the crankshaft along y, world frame", M::Multibody,
       W::Always, I::None},
      {F::Reactions, C::coupling_torque, "coupling_torque", kAtCrank, "as in timeseries.csv", M::Both, W::Always,
       I::None},
      {F::Reactions, C::main_bearing_x, "bearing_x", "N",
       "force of main bearing k (k = 1 … m along z) on the crankshaft along x, from the shaft's beam statics "
       "([friction-and-reactions.md](friction-and-reactions.md#main-bearings-along-the-crankshaft)); Σ_k = "
       "`bearing_x`",
       M::Multibody, W::MainBearings, I::MainBearing},
      {F::Reactions, C::main_bearing_y, "bearing_y", "N",
       "force of main bearing k on the crankshaft along y; Σ_k = `bearing_y`", M::Multibody, W::MainBearings,
       I::MainBearing},
  };
}

}  // namespace

const std::vector<OutputColumn>& outputColumns() {
  // By file, then by family, in the files' column order.
  static const std::vector<OutputColumn> table = [] {
    std::vector<OutputColumn> t;
    for (auto family : {timeseriesDriveColumns, timeseriesCartColumns, timeseriesOptionalColumns,
                        reactionsCartColumns, reactionsCrankshaftColumns}) {
      const std::vector<OutputColumn> columns = family();
      t.insert(t.end(), columns.begin(), columns.end());
    }
    return t;
  }();
  return table;
}

namespace {

bool writes(const OutputColumn& c, const WrittenColumns& w) {
  if (c.models == ColumnModels::Multibody && !w.multibody) return false;
  if (c.models == ColumnModels::Reduced && w.multibody) return false;
  switch (c.when) {
    case ColumnCondition::Always: return true;
    case ColumnCondition::MotorCurrent: return w.motor_current;
    case ColumnCondition::SupplySwitches: return w.supply_switches;
    case ColumnCondition::Brake: return w.brake;
    case ColumnCondition::ReducerLosses: return w.reducer_losses;
    case ColumnCondition::Backlash: return w.backlash;
    case ColumnCondition::TorsionalChain: return w.shaft_segments > 0;
    case ColumnCondition::MainBearings: return w.main_bearings > 0;
  }
  return false;
}

int familySize(ColumnIndex index, const WrittenColumns& w) {
  switch (index) {
    case ColumnIndex::None: return 1;
    case ColumnIndex::Cart: return w.carts;
    case ColumnIndex::MainBearing: return w.main_bearings;
    case ColumnIndex::ShaftSegment: return w.shaft_segments;
  }
  return 0;
}

const OutputColumn& entryOf(Column c) {
  for (const OutputColumn& e : outputColumns())
    if (e.id == c) return e;
  throw std::logic_error("output column without a table entry");
}

// The end of the group that starts at entry i: the consecutive entries of one index in one file,
// written interleaved by number (an entry without an index is a group of its own).
std::size_t groupEnd(const std::vector<OutputColumn>& all, std::size_t i) {
  std::size_t end = i + 1;
  if (all[i].index != ColumnIndex::None)
    while (end < all.size() && all[end].file == all[i].file && all[end].index == all[i].index) ++end;
  return end;
}

}  // namespace

void ColumnLayout::addGroup(const std::vector<const OutputColumn*>& members, int numbers) {
  for (std::size_t m = 0; m < members.size(); ++m) {
    const int id = static_cast<int>(members[m]->id);
    first_[id] = static_cast<int>(names_.size() + m);
    stride_[id] = static_cast<int>(members.size());
    numbers_[id] = numbers;
  }
  for (int n = 1; n <= numbers; ++n)
    for (const OutputColumn* c : members)
      names_.push_back(c->index == ColumnIndex::None ? c->name : c->name + "_" + std::to_string(n));
}

ColumnLayout::ColumnLayout(OutputFile file, const WrittenColumns& written) {
  const std::vector<OutputColumn>& all = outputColumns();
  for (std::size_t i = 0; i < all.size();) {
    if (all[i].file != file) {
      ++i;
      continue;
    }
    const std::size_t end = groupEnd(all, i);
    std::vector<const OutputColumn*> members;
    for (std::size_t k = i; k < end; ++k)
      if (writes(all[k], written)) members.push_back(&all[k]);
    addGroup(members, familySize(all[i].index, written));
    i = end;
  }
}

void ColumnLayout::reset(std::vector<double>& row) const {
  row.assign(names_.size(), std::numeric_limits<double>::quiet_NaN());
}

std::size_t ColumnLayout::position(Column c, int number) const {
  const int id = static_cast<int>(c);
  if (first_[id] < 0 || number < 1 || number > numbers_[id])
    throw std::logic_error("a run set the output column '" + numberedColumnName(c, number) +
                           "', which its table does not hold");
  return static_cast<std::size_t>(first_[id] + (number - 1) * stride_[id]);
}

std::string numberedColumnName(Column c, int number) {
  const OutputColumn& e = entryOf(c);
  return e.index == ColumnIndex::None ? e.name : e.name + "_" + std::to_string(number);
}

std::string outputColumnUnit(const std::string& name) {
  for (const OutputColumn& c : outputColumns())
    if (c.index == ColumnIndex::None && c.name == name) return c.unit;
  const std::size_t us = name.rfind('_');
  if (us == std::string::npos || us + 1 == name.size()) return "";
  for (std::size_t i = us + 1; i < name.size(); ++i)
    if (!std::isdigit(static_cast<unsigned char>(name[i]))) return "";
  const std::string prefix = name.substr(0, us);
  for (const OutputColumn& c : outputColumns())
    if (c.index != ColumnIndex::None && c.name == prefix) return c.unit;
  return "";
}

namespace {

std::string displayName(const OutputColumn& c) {
  switch (c.index) {
    case ColumnIndex::None: return c.name;
    case ColumnIndex::Cart: return c.name + "_j";
    case ColumnIndex::MainBearing:
    case ColumnIndex::ShaftSegment: return c.name + "_k";
  }
  return c.name;
}

std::string writtenBy(const OutputColumn& c) {
  std::string who = c.models == ColumnModels::Both        ? "both models"
                    : c.models == ColumnModels::Multibody ? "multibody model"
                                                          : "reduced model";
  switch (c.when) {
    case ColumnCondition::Always: return who;
    case ColumnCondition::MotorCurrent:
      return who + ", with a motor law that models the current (`motor.model`: `circuit`, `park`)";
    case ColumnCondition::SupplySwitches:
      return who + ", with a supply that switches (a starting method other than direct on line, a delayed "
                   "switch-on, a switch-off: `motor.start`, `motor.stop`)";
    case ColumnCondition::Brake: return who + ", with a brake (`motor.stop.brake_torque`)";
    case ColumnCondition::ReducerLosses: return who + ", with `reducer.losses: power_flow`";
    case ColumnCondition::Backlash: return who + ", with an elastic coupling and `reducer.backlash` > 0";
    case ColumnCondition::TorsionalChain: return who + ", with `crankshaft.torsional_stiffness`";
    case ColumnCondition::MainBearings:
      return who + ", with `crankshaft.throw_positions` and `crankshaft.bearing_positions`";
  }
  return who;
}

// A table cell: a '|' would end the cell.
std::string cell(const std::string& text) {
  std::string out;
  for (char ch : text) {
    if (ch == '|') out += '\\';
    out += ch;
  }
  return out;
}

std::string fileTable(OutputFile file) {
  std::string md = "| column | unit | meaning | written by |\n|---|---|---|---|\n";
  for (const OutputColumn& c : outputColumns())
    if (c.file == file)
      md += "| `" + displayName(c) + "` | " + cell(c.unit) + " | " + cell(c.meaning) + " | " + cell(writtenBy(c)) +
            " |\n";
  return md;
}

}  // namespace

std::string outputColumnsMarkdown() {
  return "**timeseries.csv**, one row per output step (`simulation.output_step`); the unit is the one in the "
         "header, `name[unit]`:\n\n" +
         fileTable(OutputFile::Timeseries) +
         "\n**reactions.csv** (left out with `simulation.reactions: false`), one row per output step:\n\n" +
         fileTable(OutputFile::Reactions);
}

}  // namespace rollerdyn
