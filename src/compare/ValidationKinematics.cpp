// Validation item: every cart's position and velocity columns against the slider-crank closed
// form at the angle of its own crank, in both models, on scenes with carts on both sides of the
// shaft. Cart j (1-based) has its crank at θ_j = φ_crank + (j − 1)·Δφ (crank.offset_deg) and runs
// on side σ_j = +1 (same) or −1 (opposite, carts.sides); with λ = r/l,
//   x_j = r·cos θ_j + σ_j·l·√(1 − λ²·sin²θ_j),
//   v_j = ω_crank·(−r·sin θ_j − σ_j·r·λ·sin θ_j·cos θ_j / √(1 − λ²·sin²θ_j))
// (Loveikin, Pochka, Romasevych (2018) eq. (40)-(47); Loveikin and Pochka (2007) eq. (6) for the
// opposite side), written out here from the scene's r, l, Δφ and sides. Tolerance: 1e-9 m and
// 1e-9 m/s per metre of crank radius times the largest crank speed. The reduced model places the
// carts by this closed form and the multibody model's minimal formulation by its own closed
// form of the same loop, each to round-off (~1e-14 m at these crank angles); a wrong crank offset
// or side moves a cart by up to 2r = 0.4 m.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "compare/ValidationItems.h"
#include "multibody/MultibodySimulation.h"
#include "reduced/ReducedModel.h"
#include "io/FieldFormat.h"
#include "compare/RunModel.h"

namespace rollerdyn::validation {
namespace {

constexpr double kTolerance = 1e-9;  // file comment

// How far one run's cart columns lie from the closed form, over every row and cart.
struct ClosedFormGap {
  double dx = 0, dv = 0;  // largest |x − closed form| [m], |v − closed form| [m/s]
  double w_max = 0;       // largest |ω_crank| [rad/s]
  std::string sides;      // σ_j of every cart, "+1,−1,..."
  std::size_t rows = 0;
};

ClosedFormGap closedFormGap(const Scene& sc, const Table& t) {
  const double r = sc.crank.radius, l = sc.rods.length, lam = r / l, dphi = sc.crank.offset;
  const std::vector<double> phi = t.column("phi_crank"), w = t.column("omega_crank");
  ClosedFormGap gap;
  gap.rows = phi.size();
  for (int j = 0; j < sc.carts.count; ++j) {
    const double sg = sc.carts.side[j];
    gap.sides += (j ? "," : "") + std::string(sg > 0 ? "+1" : "−1");
    const std::vector<double> x = t.column("x_cart_" + std::to_string(j + 1)),
                              v = t.column("v_cart_" + std::to_string(j + 1));
    for (std::size_t i = 0; i < phi.size(); ++i) {
      const double th = phi[i] + j * dphi, S = std::sin(th), C = std::cos(th), root = std::sqrt(1 - lam * lam * S * S);
      gap.dx = std::max(gap.dx, std::abs(x[i] - (r * C + sg * l * root)));
      gap.dv = std::max(gap.dv, std::abs(v[i] - w[i] * (-r * S - sg * r * lam * S * C / root)));
      gap.w_max = std::max(gap.w_max, std::abs(w[i]));
    }
  }
  return gap;
}

struct KinematicsCase {
  std::string file;
  std::vector<std::string> sets;
};

// One model on one scene: its cart columns against the closed form, a claim.
void kinematicsClaim(ValidationSection& s, const ItemContext& ctx, const KinematicsCase& c, const Scene& sc,
                     bool multibody) {
  const RunResult run = runModel(sc, multibody ? "multibody" : "reduced");
  const ClosedFormGap gap = closedFormGap(sc, run.timeseries);
  const double v_tol = kTolerance * sc.crank.radius * std::max(gap.w_max, 1.0);
  s.claim(run.stats.complete && gap.dx <= kTolerance && gap.dv <= v_tol,
          std::string(multibody ? "multibody model" : "reduced model") + " on `" + ctx.command("simulate", c.file, c.sets) +
              "` (" + std::to_string(sc.carts.count) + " carts, sides " + gap.sides + ", Δφ = " +
              significant(sc.crank.offset * 180 / M_PI) + "°, " + std::to_string(gap.rows) + " rows): largest |x − closed form| " +
              significant(gap.dx, 2) + " m (at most " + significant(kTolerance) + "), |v − closed form| " + significant(gap.dv, 2) + " m/s (at most " +
              significant(v_tol, 2) + ")" + (run.stats.complete ? "" : "; the run ended early: " + run.stats.status) + ".");
}

}  // namespace

ValidationSection kinematicsChecks(const ItemContext& ctx) {
  ValidationSection s("kinematics", "Cart positions and velocities against the slider-crank closed form");
  // Opposite sides at Δφ = 90° (the recuperative drive), and four carts on alternating sides at
  // an offset that is not a symmetry of the layout (70°, started at the nominal crank speed: from
  // rest this layout stalls), 3 s each.
  const std::vector<KinematicsCase> cases = {{"recuperative-2cart.yaml", {"simulation.t_end=3"}},
                                   {"balanced-4cart.yaml", {"carts.sides=alternate", "crank.offset_deg=70", "initial.crank_speed=10.42", "simulation.t_end=3"}}};
  s.text() << "Cart j (1-based) runs on side σ_j = ±1 (carts.sides) with its crank at θ_j = φ_crank + (j − 1)·Δφ "
              "(crank.offset_deg); with r the crank radius, l the rod length and λ = r/l: x_j = r·cos θ_j + "
              "σ_j·l·√(1 − λ²·sin²θ_j) and v_j = ω_crank·(−r·sin θ_j − σ_j·r·λ·sin θ_j·cos θ_j/√(1 − λ²·sin²θ_j)) "
              "(Loveikin, Pochka, Romasevych (2018), eq. (40)-(47)). Every row of both models' x_cart_j and v_cart_j "
              "columns against these, from the same row's φ_crank and ω_crank. Tolerance 1e-9 m (round-off is "
              "~1e-14 m; a wrong offset or side moves a cart by up to 2r).\n\n";
  for (const KinematicsCase& c : cases) {
    const Scene sc = ctx.load(c.file, c.sets);
    for (const bool multibody : {true, false}) {
      if (ctx.interrupted()) return s;
      kinematicsClaim(s, ctx, c, sc, multibody);
    }
  }
  return s;
}

}  // namespace rollerdyn::validation
