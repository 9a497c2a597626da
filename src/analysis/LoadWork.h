// What the technological load takes from the drive, per cart: the work of the compacting-roller
// forces (the shared law src/physics/RollerLoads.h, the one both models apply) over the whole
// run and over the steady window, and its mean power. The papers print roller forces of one
// direction (Loveikin, Pochka, Romasevych (2018) fig. 3): read that way the load does no net work
// over a stroke and back, so a six-cart drive "compacting" draws under 1 kW from a 22 kW motor,
// while the other reading (forces against the velocity) needs over 100 kW. Which reading a run
// uses changes every motor verdict, so the net work is always shown and a warning raised when
// the load does (almost) none of it (docs/loads.md).
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "analysis/RunResult.h"
#include "analysis/SteadyState.h"
#include "scene/Scene.h"

namespace rollerdyn {

// The net work counts as "almost none" below this fraction of the gross work ∫|P| dt [-]: a
// load that dissipates keeps net = gross; a constant-direction force gives back on the return
// stroke what it took on the way out (net/gross → 0, here ~1e-6 from the smoothing of sign(v)).
inline constexpr double kNoNetWorkFraction = 0.05;

struct CartLoadWork {
  int cart = 0;                  // 1-based
  double work_whole_run = 0;     // ∫ P dt over the whole run [J], P = -H·v' absorbed by the load
  double work_steady = 0;        // the same over the steady window [J]
  double power_mean_steady = 0;  // work_steady / window duration [W]
  double gross_steady = 0;       // ∫ |P| dt over the steady window [J]
};

struct LoadWork {
  bool available = false;        // roller loads present and the cart velocities in the run
  std::vector<CartLoadWork> carts;
  double power_mean_per_cart_steady = 0;     // mean over the carts [W]
  double power_mean_per_cart_whole_run = 0;  // [W]
  double net_over_gross_steady = 0;          // Σ work_steady / Σ gross_steady [-]
  std::string reading;                       // the direction law and μ_r in words
  std::string warning;                       // "" unless the load does (almost) no net work
  std::string consequence;                   // what that falsifies (motor verdicts, or a coasting
                                             // machine's run-out); "" without the warning
};

// From the run's v_cart_j columns (trapezoidal rule on the output rows).
LoadWork computeLoadWork(const Scene& scene, const RunResult& run, const SteadyState& window);

// summary.json "load" object.
nlohmann::json loadWorkJson(const LoadWork& w);

}  // namespace rollerdyn
