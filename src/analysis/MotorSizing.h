// The motor's part of the drive sizing (DriveSizing.h, MotorSizing): internal to DriveSizing.cpp.
#pragma once

#include <cstddef>

#include "analysis/DriveSizing.h"

namespace rollerdyn {

// The motor's ratings, its torques, powers and slip over the steady window (rows [b, e)) and the
// whole run (rows [0, run_end)), and the rotor's heating with the start's heat from `start_up`
// (null: not known). `revolutions`: the crank's revolutions in the window.
MotorSizing sizeMotor(const Scene& sc, const Table& ts, std::size_t b, std::size_t e, std::size_t run_end,
                      double revolutions, bool turning, const StartUp* start_up);

}  // namespace rollerdyn
