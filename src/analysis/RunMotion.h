// How the drive moved, named once for every output (console, summary.json, report, sweep):
//   "stalled"  the drive is held at rest by its load or driven backwards (StallDetector.h); the
//              run ended early,
//   "rocking"  the crank swings back and forth instead of turning: in the metrics window, or with
//              swings that stopped growing (StallDetector.h; the run then ended early): loads that
//              the motor cannot lift over a dead centre, Loveikin, Pochka, Romasevych (2018) at
//              small crank offsets. A crank that rocks with growing swings and then turns is
//              "turning" once it turns in the metrics window,
//   "starting" the crank got over its dead centres and turns, but the run ended before it settled
//              (its speed still changes sign in the metrics window, or it turns one way and is
//              still gaining speed revolution after revolution), or it rocks with swings that
//              still grow when the run ends (it may yet get over its dead centre): run longer,
//   "turning"  the crank turns one way: per-revolution metrics (δ, H, k_p, energy per revolution,
//              the flywheel size) have a meaning,
//   "at_rest"  no motor, and friction and loads have brought the machine to rest (RestDetector.h:
//              the run ended early), or the crank never moved,
//   "coasting" no motor, the crank still turns but has not settled: it is slowing down and the run
//              ended before it came to rest; per-revolution metrics do not apply,
//   "unknown"  no finite crank speed in the window.
// Why a stalled drive stalls is the start-up answers' one sentence (StartUp.h, stall_cause).
#pragma once

#include <limits>
#include <string>

#include "analysis/Metrics.h"
#include "analysis/RunResult.h"
#include "scene/Scene.h"

namespace rollerdyn {

// `window_advance`: how far the crank turned over the metrics window [rad] (NaN: not known). A
// crank whose speed changes sign in the window but that advanced a whole revolution or more
// turns (with dips backwards, or with the start-up inside a short run's window), it does not rock.
// `steady_reached`: whether the run settled (SteadyState.h); a crank that turns through the window
// with its speed changing sign, in a run that never settled, is still "starting" (the window holds
// its rocking start): per-revolution figures and sizing verdicts do not apply, the run is too short.
std::string classifyMotion(const Scene& scene, const RunResult& run, const WindowMetrics& window,
                           double window_advance = std::numeric_limits<double>::quiet_NaN(),
                           bool steady_reached = true);

// What every output says of a drive "starting" when its run ended (the one sentence the status,
// the start-up answers, the sizing and the resonance check print): why nothing steady can be
// judged yet and what to do.
inline const char* kStillStartingWords =
    "the drive is still starting when the run ends: the crank has not settled (its speed still changes sign within "
    "a revolution, still grows or falls from one revolution to the next, or it rocks with swings that still grow), "
    "so nothing steady can be judged yet: run longer (simulation.t_end)";

// Whether per-revolution metrics mean anything for this motion.
inline bool motionIsTurning(const std::string& motion) { return motion == "turning"; }

// Load torques at the crank from the load laws of the scene (computed by the caller, which can
// evaluate them: src/studies/StartLoad.h); NaN when not known.
struct StartLoad {
  double at_start_angle;  // resisting torque at initial.crank_angle_deg as the carts begin to
                          // move forwards (crank speed → 0+) [N·m at the crank]
  double revolution_mean; // the same averaged over one crank revolution [N·m at the crank]
  // The excess work of one revolution at constant crank speed (the flywheel's design quantity,
  // StartLoad.h): the largest swing of ∫(Q̄ - Q(φ))dφ, Q the load torque plus the carts' and rods'
  // inertia torque ½·J_n2'(φ)·ω² at that speed [J]; NaN when not known.
  double excess_work = std::numeric_limits<double>::quiet_NaN();
  double excess_work_speed = std::numeric_limits<double>::quiet_NaN();  // that crank speed [rad/s]
};

// For a drive that did not start: how far its crank moved from the start angle before it was
// held (a load that drives it backwards, swings), one sentence; "" when it stayed within 5° of it.
std::string stalledCrankTravel(const Scene& scene, const RunResult& run);

}  // namespace rollerdyn
