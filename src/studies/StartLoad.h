// The load torques that say why a drive stalls (analysis/RunMotion.h), from the reduced model's
// load law M_load(φ, φ̇) (Loveikin, Pochka, Romasevych (2018) eq. (30), Loveikin and Pochka (2007)
// eq. (5)), which both models share: the multibody model applies the same forces.
#pragma once

#include "analysis/RunMotion.h"
#include "scene/Scene.h"

namespace rollerdyn {

// Load torque at the crank at the scene's start angle and averaged over 360 crank angles, with
// the carts moving forwards at a crank speed so small that inertia is nil but the smoothed
// sign(v) = tanh(v/v_s) is ±1 (φ̇ = 50·v_s/r): the breakaway (static) load. NaN fields when the
// reduced model cannot be built for the scene. With a motor (and the crank drive) also the excess
// work of one revolution at the steady crank speed the motor's static curve gives against the mean
// load (the flywheel's design quantity, DriveSizing.h).
StartLoad startLoadOf(const Scene& scene);

}  // namespace rollerdyn
