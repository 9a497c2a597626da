// The timeseries columns the motor adds beyond motor_torque, in both models and in this order,
// each only where it means something (a scene that asks for none gets none, and its tables stay
// as they were):
//   stator_current          RMS line current (the equivalent star's phase current; in star,
//                           the windings' current) [A]            the law models a current
//   supply_voltage_ratio    U/U_n at the terminals, 0 when off [-] the supply switches (Supply.h)
//   supply_frequency_ratio  f/f_n [-]                              the supply switches
//   brake_torque            brake on the motor shaft, at the crank axis [N·m]   a brake is set
#pragma once

#include <string>
#include <vector>

#include "motor/MotorLaw.h"
#include "motor/Supply.h"

namespace rollerdyn {

// Whether a law models the stator current (its steady current at rest under the rated supply is a number).
bool lawHasCurrent(const MotorLaw* law);

std::vector<std::string> motorColumns(const MotorLaw* law, const Supply& supply);

// Appends this row's values of motorColumns(law, supply) to `row`.
void appendMotorColumns(const MotorLaw* law, const Supply& supply, double stator_current, const SupplyState& state,
                        double brake_torque_crank, std::vector<double>& row);

}  // namespace rollerdyn
