#include "motor/MotorColumns.h"

#include <cmath>

namespace rollerdyn {

bool lawHasCurrent(const MotorLaw* law) { return law && std::isfinite(law->steadyCurrent(SupplyState{}, 0.0)); }

std::vector<std::string> motorColumns(const MotorLaw* law, const Supply& supply) {
  std::vector<std::string> c;
  if (lawHasCurrent(law)) c.push_back("stator_current");
  if (!supply.constant()) {
    c.push_back("supply_voltage_ratio");
    c.push_back("supply_frequency_ratio");
  }
  if (supply.hasBrake()) c.push_back("brake_torque");
  return c;
}

void appendMotorColumns(const MotorLaw* law, const Supply& supply, double stator_current, const SupplyState& state,
                        double brake_torque_crank, std::vector<double>& row) {
  if (lawHasCurrent(law)) row.push_back(stator_current * state.line_current_factor);  // the line current
  if (!supply.constant()) {
    row.push_back(state.connected ? state.voltage : 0.0);
    row.push_back(state.frequency);
  }
  if (supply.hasBrake()) row.push_back(brake_torque_crank);
}

}  // namespace rollerdyn
