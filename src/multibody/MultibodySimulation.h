// Runs the multibody model of a scene from its initial state to simulation.t_end and collects
// the output tables, statistics and energy audit (src/analysis/RunResult.h).
#pragma once

#include "analysis/RunControl.h"
#include "analysis/RunResult.h"
#include "scene/Scene.h"

namespace rollerdyn {

// Declared only: most callers run a scene and never see the model, and its header brings in all
// of Simbody's (seconds of compile time in every file that includes it). Callers that build a
// model include multibody/MultibodyModel.h.
class MultibodyModel;

// Integrates `model` over the scene's time span. Never throws for a physical outcome: a stalled
// motor, a NaN or an integrator failure ends the run with complete = false and a status line.
RunResult simulateMultibody(const MultibodyModel& model, const RunControl& control = {});

// Convenience: build the model from the scene and run it.
RunResult runMultibodyModel(const Scene& scene, const RunControl& control = {});

}  // namespace rollerdyn
