// What a run's user must be told about the guide friction and the guide normal forces
// (docs/friction-and-reactions.md): which normal force the friction and the reactions use, how
// close the carts come to self-locking and the rods to dead centre (physics/SelfLocking.h), and,
// for the reduced model with the papers' quasi-static normal forces, how far its friction work is
// from what the kinetostatic normal forces give on the same run.
//
// Thresholds (each argued in docs/friction-and-reactions.md, "Warnings"):
//   - self-locking index κ > kLockingIndexWarning = 0.1: the friction loop amplifies the friction
//     by more than 1/(1 - κ) = 11 % over its open-loop value, an effect of the same order as the
//     uncertainty of f itself is no longer small; κ >= 1: the cart locks where g >= 1;
//   - transmission angle μ_min < kTransmissionAngleWarning = 40°: the limit of mechanism-design
//     practice for linkages that must run freely (rod force up to 1/cos β_max = 1.56x the cart's
//     horizontal load there); below it the rod force and the guide reactions grow as 1/cos β and a
//     rod a little shorter than designed may not pass the dead centre;
//   - quasi-static friction work off the kinetostatic one by more than kFrictionWorkWarning = 5 %.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "analysis/RunResult.h"
#include "scene/Scene.h"

namespace rollerdyn {

inline constexpr double kLockingIndexWarning = 0.1;        // κ [-]
inline constexpr double kTransmissionAngleWarning = 40.0;  // μ_min [deg]
inline constexpr double kFrictionWorkWarning = 0.05;       // |W_qs/W_kin - 1| [-]

// The normal force of the guide friction (and, for the reduced model, of its reactions) in words,
// for every result (RunResult::guide_normals): the multibody model's law (empty without guide
// friction) or the reduced model's statics.
std::string guideNormalsDescription(const Scene& scene, bool reduced_model);

// Scene-level warnings (self-locking, dead centre), for `check` and every run's summary.
std::vector<std::string> lockingWarnings(const Scene& scene);

// The friction-work check of a reduced run with quasi-static normal forces: |W_qs/W_kin - 1|,
// NaN where it does not apply (no friction work, another normal-force law).
double frictionWorkDeviation(const RunResult& run);

// Puts summary["guide_friction"] = {normal_forces, self_locking_index, transmission_angle_min_deg,
// rod_force_factor, friction_work, friction_work_kinetostatic, friction_work_deviation} and
// appends the warnings to summary["warnings"] (created if absent). Returns the warnings added (to
// print on the terminal).
std::vector<std::string> addFrictionWarnings(const Scene& scene, const RunResult& run, nlohmann::json& summary);

// Lines for `rollerdyn check`: the margins (the warnings are lockingWarnings).
std::string lockingReport(const Scene& scene);

}  // namespace rollerdyn
