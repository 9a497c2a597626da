// Fatigue damage per start and per hour of steady running, by Miner's rule over rainflow cycles
// (Rainflow.h, ASTM E1049-85) against an S-N curve given in the scene (sizing.fatigue.*).
//
// S-N curve (SnCurve, amplitudes S_a of the signal itself): N(S_a) = N_D·(S_D/S_a)^m for S_a >= S_D;
// below the knee S_D either Haibach's extension, N = N_D·(S_D/S_a)^(2m-1) (Haibach, "Betriebsfestigkeit",
// the "modified Miner rule", sizing.fatigue.below_knee: haibach, the default: under varying loads
// the large cycles lower the endurance limit, so small cycles still damage), or the plain Basquin
// cut-off: no damage below S_D (below_knee: cutoff).
// Mean correction: Goodman's line with the ultimate value S_u (sizing.fatigue.<signal>.ultimate):
// the equivalent fully reversed amplitude S_ar = S_a/(1 - |S_m|/S_u) (|S_m|: a reversing torque or
// a rod force is equally harmful either way); |S_m| >= S_u counts the cycle as a failure by itself.
// Without S_u: no mean correction (S_ar = S_a).
// Miner: D = Σ n_i/N(S_ar,i) over the rainflow cycles (n_i = 1 or 0.5).
//
// Windows: the start, from the switch-on t_on to the start's end as the start-up answers define it
// (StartUp::start_end, where the crank speed settles), gives the damage of one start; the steady
// window (SteadyState.h) gives the damage of steady running, scaled to one hour by 3600 s / its
// length. Starts to failure 1/D_start, hours to failure 1/D_hour.
#pragma once

#include <string>
#include <vector>

#include "analysis/Rainflow.h"
#include "analysis/SteadyState.h"
#include "scene/SizingInputs.h"

namespace rollerdyn {

struct Scene;
struct RunResult;
struct StartUp;

// Cycles to failure at an (equivalent fully reversed) amplitude S_a [-]; +inf below a cut-off knee
// or for S_a = 0.
double cyclesToFailure(const SnCurve& curve, bool haibach, double amplitude);
// Goodman's equivalent fully reversed amplitude; +inf when |mean| >= S_u; the amplitude itself
// without S_u (curve.ultimate = 0).
double goodmanAmplitude(const SnCurve& curve, double amplitude, double mean);

struct DamagingCycle {
  double range = 0, mean = 0, count = 0;  // the rainflow cycle [signal's unit], [-]
  double amplitude_equivalent = 0;        // S_ar after the mean correction [signal's unit]
  double damage = 0;                      // count/N(S_ar) [-]
};

struct MinerResult {
  double damage = 0;                  // Σ n/N [-]
  double cycles = 0;                  // Σ n [-]
  std::vector<DamagingCycle> top;     // the three cycles of largest damage, largest first
};

// Miner's sum over rainflow cycles.
MinerResult minerDamage(const std::vector<RainflowCycle>& cycles, const SnCurve& curve, bool haibach);

// One window's damage of one signal.
struct WindowDamage {
  bool applies = false;       // the window exists and the curve is given
  std::string not_applicable; // why not, and what to do; "" when it applies
  double t_begin = 0, t_end = 0;  // [s]
  double damage = 0;          // D over the window [-]
  double cycles = 0;          // rainflow cycles counted [-]
  std::string where;          // which column decided (rod force: the cart with the largest D)
  std::vector<DamagingCycle> top;
};

struct SignalFatigue {
  std::string signal;         // coupling_torque | rod_force
  std::string what;           // in words
  std::string unit;           // N·m | N
  std::string key;            // the scene keys of its curve, e.g. "sizing.fatigue.coupling_torque.*"
  bool curve_given = false;
  SnCurve curve;
  WindowDamage start;         // one start
  WindowDamage steady;        // the steady window
  double damage_per_start = 0;   // [-]; NaN: not applicable
  double damage_per_hour = 0;    // steady D·3600 s/window [1/h]; NaN: not applicable
  double starts_to_failure = 0;  // 1/damage_per_start [-]; +inf: no damage
  double hours_to_failure = 0;   // 1/damage_per_hour [h]
};

struct FatigueSizing {
  bool requested = false;        // any S-N curve or requirement given
  std::string below_knee;        // in words: Haibach's 2m - 1 or the cut-off
  std::string mean_correction;   // in words
  double required_starts = 0;    // NaN when not given
  double required_hours = 0;     // NaN when not given
  std::vector<SignalFatigue> signals;  // those with a curve given (or all when only a requirement is)
};

// `start_up`: the run's start-up answers (null: no start window known).
FatigueSizing computeFatigue(const Scene& scene, const RunResult& run, const SteadyState& window,
                             const StartUp* start_up);

}  // namespace rollerdyn
