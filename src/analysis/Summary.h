// summary.json of one run: what was simulated (scene, model, integrator, effects), how the run
// went (status, steps, CPU time, energy audit, constraint error) and the steady-state metrics
// (SteadyState.h, Metrics.h). Numbers that are NaN or infinite are written as null (JSON has no
// NaN), listed under "non_finite", and "status" says so, so a broken run never looks clean.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "analysis/RunMotion.h"
#include "analysis/RunResult.h"
#include "scene/Scene.h"

namespace rollerdyn {

// Keys (all always present; values null when not computable):
//   scene, scene_path (Scene::source_path: the file as given), model, integrator, effects
//   (scene.effects()), effects_built (run.effects), status,
//   complete, simulated_time, omega_crank {min, max, mean, midrange}, eps_crank_abs_max,
//   eps_from_difference, delta, H, k_p, coupling_torque_swing, twist_swing, twist_rate_swing,
//   twist_accel_swing, missing_columns, steady_state {reached, after_revolutions,
//   window_revolutions, revolutions, relative_tolerance, t_settled, t_begin, t_end, rows, note},
//   energy {motor_work (after the reducer), damping_dissipation, friction_dissipation, load_work,
//   kinetic_change, potential_change, reducer_losses, motor_shaft_work (= motor_work +
//   reducer_losses), reducer_loss_model (the loss law in words; null without a motor), residual}, energy_residual_rel, constraint_error_max, steps, realizations,
//   cpu_seconds, real_time_factor (simulated time / cpu_seconds; null when cpu_seconds <= 0,
//   i.e. not measured, which is not flagged), reactions {column: {min, max, mean, abs_max}},
//   non_finite (list of keys written as null because the value was NaN/inf),
//   motion (= crank_motion: stalled, rocking, starting, turning, at_rest, unknown; RunMotion.h),
//   not_meaningful (keys written as null because the motion is not turning), stall (why a
//   stalled run stalled, or null), sizing (SizingSummary.h: both windows and the checks),
//   load (LoadWork.h: the technological load's work and mean power per cart), warnings (list of
//   sentences: the load's no-work warning and the guide lift-off warnings here; callers append
//   resonance and plausibility ones), guide_lift_off (GuideLiftOff.h: verdict, reason, t_begin,
//   t_end, guides_checked, lifting [{cart, guide, prevailing, time_fraction, worst_reaction,
//   prevailing_extreme}]).
// `start_load`: the load torques at the start (RunMotion.h) that explain a stall; may be null.
nlohmann::json makeSummary(const Scene& scene, const RunResult& run,
                           const StartLoad* start_load = nullptr);

// Pretty-printed (2-space indent) JSON written through writeFileAtomic.
void writeSummaryAtomic(const std::string& path, const nlohmann::json& summary);

// About ten lines for the terminal: scene, model, status, mean crank speed and δ, coupling torque
// swing, energy residual, constraint error, steps, CPU time and real-time factor.
std::string summaryText(const nlohmann::json& summary);

}  // namespace rollerdyn
