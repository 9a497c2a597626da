// The "Start-up and stopping" section of the HTML report, from summary.json's start_up
// (analysis/StartUp.h): whether the drive starts and why not, the run-up time, the start's peaks
// of motor torque, coupling torque and joint reactions against the steady state's, the stator
// current, the rotor energy loss, the stopping time and run-out, and what the motor law cannot
// show (with the static Kloss law: the switching transient and the catalogue starting torque).
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace rollerdyn {

// HTML (h2, a status line, tables, notes), every text escaped; a short paragraph when the summary
// has no start-up answers.
std::string startUpSectionHtml(const nlohmann::json& summary);

}  // namespace rollerdyn
