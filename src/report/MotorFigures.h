// The motor's figures of one output folder (part of planRunFigures(), RunFigures.h):
//   motor_operating_point         the Kloss curve M(ω) reduced to the crank axis (scene motor data,
//                                 Loveikin, Pochka, Romasevych (2018) eq. (37)), the start-up as a thin
//                                 line, the steady-window operating points as red markers, and the
//                                 nominal (M_n) and breakdown (M_kr) points marked
//   motor_operating_point_steady  the same zoomed on the operating range, with the nominal and
//                                 breakdown torque as horizontal lines
//   motor_torque_vs_time, motor_torque_vs_angle  motor torque at the rotor against time (whole
//                                 run) and against the crank angle (steady window), with M_n, M_kr
//   motor_power_vs_time, motor_power_vs_angle    shaft power M·ω_r likewise, with the nominal power
// M_n and M_kr come from summary.json (sizing.motor) when present, else from the scene.
#pragma once

#include <string>
#include <vector>

#include "report/OutputFolder.h"
#include "report/RunFigures.h"
#include "scene/Scene.h"

namespace rollerdyn {

void planMotorFigures(const OutputFolder& out, const Scene* scene, const TimeWindow& window,
                      const std::string& scene_label, std::vector<FigurePlan>& plans,
                      std::vector<std::string>& notes);

}  // namespace rollerdyn
