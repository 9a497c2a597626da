// Validation item: the motor torque of both models' runs against Kloss's formula written out
// from the catalogue data of the scene file (Loveikin, Pochka, Romasevych (2018) eq. (37)):
//   s_n = 1 - ω_n/ω0,  s_kr = s_n·(λ + √(λ² - 1)),  s = 1 - u·ω_motor/ω0,
//   M = 2·M_kr / (s/s_kr + s_kr/s)  at the rotor,  M·u·η at the crank axis (the motor_torque column),
// from motor.omega_sync, motor.omega_nominal, motor.overload_ratio, motor.breakdown_torque,
// reducer.ratio and reducer.efficiency as given, not from the critical slip the scene parser
// derives. Every row of the run is compared. Tolerance 1e-9 of the breakdown torque at the crank
// M_kr·u·η: the two sides differ by the rounding of s (the run's ω_motor, a double, ~1e-16) and
// the order of operations (~1e-15 of M_kr); a 1 % error in s_kr moves the torque by ~1 % of its
// value near synchronous speed (M ≈ 2·M_kr·s/s_kr), i.e. by ~1e-4 of M_kr·u·η or more at the slips
// of these runs.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "compare/ValidationItems.h"
#include "multibody/MultibodySimulation.h"
#include "reduced/ReducedModel.h"
#include "io/FieldFormat.h"
#include "compare/RunModel.h"

namespace rollerdyn::validation {
namespace {

constexpr double kRelativeToBreakdown = 1e-9;  // file comment

// Kloss's formula from the catalogue data as the scene file gives them.
struct KlossFromCatalogue {
  double w0, wn, lam, Mkr, u, eta;  // ω0, ω_n [rad/s], λ, M_kr [N·m], reducer u, η
  double s_n, s_kr;

  explicit KlossFromCatalogue(const Scene& sc)
      : w0(sc.motor.omega_sync), wn(sc.sizing.motor_omega_nominal), lam(sc.sizing.motor_overload_ratio),
        Mkr(sc.motor.breakdown_torque), u(sc.reducer.ratio), eta(sc.reducer.efficiency) {
    if (!(wn > 0) || !(lam > 1)) throw std::runtime_error("the scene gives no motor.omega_nominal and motor.overload_ratio");
    s_n = 1.0 - wn / w0;
    s_kr = s_n * (lam + std::sqrt(lam * lam - 1.0));
  }
  // The torque at the crank axis at rotor slip `slip`.
  double torque(double slip) const { return slip == 0.0 ? 0.0 : 2.0 * Mkr / (slip / s_kr + s_kr / slip) * u * eta; }
};

// The catalogue data, the slips derived from them, and what is compared.
void motorLawIntroduction(std::ostream& text, const ItemContext& ctx, const std::string& file, const KlossFromCatalogue& k) {
  text << "The scene `model/" << file << "` as shipped (`" << ctx.command("simulate", file)
       << "`, both models). Catalogue data as given in the file: ω0 = " << significant(k.w0, 5) << " rad/s, ω_n = " << significant(k.wn, 5)
       << " rad/s, λ = " << significant(k.lam) << ", M_kr = " << significant(k.Mkr, 5) << " N·m; reducer u = " << significant(k.u) << ", η = " << significant(k.eta)
       << ". Hence s_n = 1 − ω_n/ω0 = " << significant(k.s_n, 5) << " and s_kr = s_n·(λ + √(λ² − 1)) = " << significant(k.s_kr, 5)
       << " (Loveikin, Pochka, Romasevych (2018), eq. (37)). At every output row the motor_torque column (at the "
          "crank axis) is compared with 2·M_kr/(s/s_kr + s_kr/s)·u·η at s = 1 − u·ω_motor/ω0 from the same row. "
          "Tolerance 1e-9 of M_kr·u·η (round-off of s and of the order of operations is ~1e-15 of it).\n\n";
}

// One model's run: every row's motor torque against the formula, a claim.
void motorLawClaim(ValidationSection& s, const Scene& sc, const KlossFromCatalogue& k, bool multibody) {
  const RunResult run = runModel(sc, multibody ? "multibody" : "reduced");
  const Table& t = run.timeseries;
  const std::vector<double> M = t.column("motor_torque"), w = t.column("omega_motor");
  double worst = 0, s_lo = INFINITY, s_hi = -INFINITY;
  for (std::size_t i = 0; i < M.size(); ++i) {
    const double slip = 1.0 - k.u * w[i] / k.w0;
    worst = std::max(worst, std::abs(M[i] - k.torque(slip)));
    s_lo = std::min(s_lo, slip);
    s_hi = std::max(s_hi, slip);
  }
  const double scale = k.Mkr * k.u * k.eta;
  s.claim(!M.empty() && worst <= kRelativeToBreakdown * scale,
          std::string(multibody ? "multibody model" : "reduced model") + ": " + std::to_string(M.size()) +
              " rows, slip from " + significant(s_lo, 3) + " to " + significant(s_hi, 3) + "; largest |motor_torque − Kloss| = " + significant(worst, 2) +
              " N·m = " + significant(worst / scale, 2) + " of M_kr·u·η = " + significant(scale, 5) + " N·m (at most " +
              significant(kRelativeToBreakdown) + ").");
}

}  // namespace

ValidationSection motorLawChecks(const ItemContext& ctx) {
  ValidationSection s("motor", "Motor torque against Kloss's formula from the catalogue data");
  const std::string file = "balanced-4cart.yaml";
  const Scene sc = ctx.load(file);
  const KlossFromCatalogue k(sc);
  motorLawIntroduction(s.text(), ctx, file, k);
  for (const bool multibody : {true, false}) {
    if (ctx.interrupted()) break;
    motorLawClaim(s, sc, k, multibody);
  }
  return s;
}

}  // namespace rollerdyn::validation
