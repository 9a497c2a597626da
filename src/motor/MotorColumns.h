// The timeseries columns the motor adds beyond motor_torque (stator_current, the supply's
// voltage and frequency ratios, brake_torque: their units, meanings and order in the output
// column table, io/OutputColumns.h), each only where it means something: a scene that asks for
// none gets none, and its tables stay as they were. Both models decide them and fill them here.
#pragma once

#include <vector>

#include "io/OutputColumns.h"
#include "motor/MotorLaw.h"
#include "motor/Supply.h"

namespace rollerdyn {

// Whether a law models the stator current (its steady current at rest under the rated supply is a number).
bool lawHasCurrent(const MotorLaw* law);

// Marks in `written` the motor columns this law and supply give.
void addMotorColumns(const MotorLaw* law, const Supply& supply, WrittenColumns& written);

// Sets this row's values of the motor columns `layout` holds.
void setMotorColumns(const ColumnLayout& layout, double stator_current, const SupplyState& state,
                     double brake_torque_crank, std::vector<double>& row);

}  // namespace rollerdyn
