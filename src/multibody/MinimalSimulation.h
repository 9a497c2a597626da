// The multibody model's minimal formulation (simulation.formulation = minimal): CVODE's Adams
// method integrates only the independent coordinates (MinimalCoordinates.h), their speeds and
// the force elements' auxiliary states (energy audit, guide-friction normal-force lags); the
// accelerations come from the projected equations of motion (MinimalDynamics.h). Same model
// (the MultibodyModel's bodies, constraints and force elements), same tables, statistics,
// stall rule and energy audit as the constrained formulation (MultibodySimulation.h).
//
// Output rows: the state at the row's time is set exactly from the closed forms and Simbody
// then does its full constrained solve (realize to Acceleration), so every reaction column
// means what it means in the constrained formulation. At every row the constrained
// accelerations u̇ and guide normal forces are compared with the projected ones;
// RunStats::formulation_self_check is the largest relative difference (round-off when the two
// formulations describe the same mechanics).
#pragma once

#include "multibody/MultibodySimulation.h"

namespace rollerdyn {

// Integrates `model` over the scene's time span in the minimal formulation. Never throws for a
// physical outcome (like simulateMultibody).
RunResult simulateMinimal(const MultibodyModel& model, const RunControl& control = {});

}  // namespace rollerdyn
