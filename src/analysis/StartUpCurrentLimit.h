// The soft starter's current limit in the start-up answers (StartUp.h): internal to StartUp.cpp.
#pragma once

#include "analysis/StartUp.h"
#include "motor/Supply.h"

namespace rollerdyn {

// Fills r.current_limit for a current-limited soft start from rest (nothing otherwise), from the
// run's rows (supply_voltage_ratio, stator_current, omega_motor) and its status line (a trip,
// Supply::tripStatus). Where the limit is why the drive did not start (the starter tripped, or it
// still holds a drive at rest when the run ends) it says so in r.starts and r.verdict; where the
// drive turns but the limit still holds when the run ends, the verdict says that too. Call after
// the rest of the answers (the verdict, r.from_rest) are computed.
void addCurrentLimit(const Scene& scene, const RunResult& run, const MotorLaw& law, const Supply& supply, StartUp& r);

}  // namespace rollerdyn
