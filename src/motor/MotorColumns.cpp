#include "motor/MotorColumns.h"

#include <cmath>

namespace rollerdyn {

bool lawHasCurrent(const MotorLaw* law) { return law && std::isfinite(law->steadyCurrent(SupplyState{}, 0.0)); }

void addMotorColumns(const MotorLaw* law, const Supply& supply, WrittenColumns& written) {
  written.motor_current = lawHasCurrent(law);
  written.supply_switches = !supply.constant();
  written.brake = supply.hasBrake();
}

void setMotorColumns(const ColumnLayout& layout, double stator_current, const SupplyState& state,
                     double brake_torque_crank, std::vector<double>& row) {
  if (layout.has(Column::stator_current))
    layout.set(row, Column::stator_current, stator_current * state.line_current_factor);  // the line current
  if (layout.has(Column::supply_voltage_ratio))
    layout.set(row, Column::supply_voltage_ratio, state.connected ? state.voltage : 0.0);
  if (layout.has(Column::supply_frequency_ratio)) layout.set(row, Column::supply_frequency_ratio, state.frequency);
  if (layout.has(Column::brake_torque)) layout.set(row, Column::brake_torque, brake_torque_crank);
}

}  // namespace rollerdyn
