// The "Motion and drive sizing" section of the HTML report: the motion of the crank (stalled,
// rocking, turning) and why a drive stalled, then the sizing answers of summary.json's `sizing`
// (analysis/SizingSummary.h): motor torques against nominal and breakdown torque with pass/fail,
// powers, slip, energy per revolution, the flywheel for a target δ, the coupling torque against its
// rating, and the bearing loads and L10 lives of every joint.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace rollerdyn {

// HTML (h2, paragraphs, tables), every text escaped; a short paragraph when `summary` has no sizing.
std::string sizingSectionHtml(const nlohmann::json& summary);

// The fatigue and coupling-selection tables from summary.json's `sizing` (SignOffSection.cpp); "" when
// neither was asked for.
std::string signOffSectionHtml(const nlohmann::json& sizing);
// The gear load spectrum after ISO 6336-6 and the motor's starts after IEC 60034-1 from summary.json's
// `sizing` (DutySection.cpp); "" when neither was asked for.
std::string dutySectionHtml(const nlohmann::json& sizing);

}  // namespace rollerdyn
