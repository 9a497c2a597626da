// The drive-sizing check by hand (ValidationSizing.cpp's file comment), its joints: every
// per-cart joint row of summary.json (guide rollers, rod end, crank pin, main bearing) against its
// loads, speeds and lives computed from reactions.csv and timeseries.csv.
#include <cmath>
#include <string>
#include <vector>

#include "compare/SizingByHand.h"
#include "io/FieldFormat.h"

namespace rollerdyn::validation::sizing_by_hand {
namespace {

// A joint's force F and rotation speed n at every row.
struct JointRows {
  std::vector<double> F, n;
};

// dβ/dθ of cart j's rod (1-based) at crank angle φ: λ·cos θ/√(1 - λ²·sin² θ) of sin β = λ·sin θ,
// λ = r/l, θ the cart's own crank angle.
double rodSwingRatio(const Scene& sc, double phi, int j) {
  const double lam = sc.crank.radius / sc.rods.length;
  const double th = phi + sc.crankPhase(j - 1);
  return lam * std::cos(th) / std::sqrt(1 - lam * lam * std::sin(th) * std::sin(th));
}

// The force of joint kind k of cart `cart` at row i (reactions.csv).
double jointForce(const Csv& rx, const std::string& k, const std::string& cart, std::size_t i) {
  if (k == "guide_roller_front") return rx.col("N_front_" + cart)[i];
  if (k == "guide_roller_rear") return rx.col("N_rear_" + cart)[i];
  if (k == "rod_end") return rx.col("F_rod_" + cart)[i];
  if (k == "crank_pin") return std::hypot(rx.col("crankpin_x_" + cart)[i], rx.col("crankpin_y_" + cart)[i]);
  return std::hypot(rx.col("bearing_x")[i], rx.col("bearing_y")[i]);  // main_bearing
}

// The rotation speed n of joint kind k of cart j at row i (JointSizing.h): guide rollers
// |v|/(d/2), the rod end its swing |β̇| = |ω·dβ/dθ|, the crank pin |ω·(1 + σ·dβ/dθ)| relative to
// the rod, the main bearing |ω_crank|.
double jointSpeed(const Scene& sc, const RunFiles& f, const std::string& k, int j, std::size_t i) {
  const double w = f.ts.col("omega_crank")[i], phi = f.ts.col("phi_crank")[i];
  const double d = sc.carts.geometry.d;
  if (k == "guide_roller_front" || k == "guide_roller_rear")
    return d > 0 ? std::abs(f.ts.col("v_cart_" + std::to_string(j))[i]) / (0.5 * d) : 1.0;
  if (k == "rod_end") return std::abs(w * rodSwingRatio(sc, phi, j));
  if (k == "crank_pin") {
    const int side = j >= 1 && std::size_t(j - 1) < sc.carts.side.size() && sc.carts.side[j - 1] == -1 ? -1 : 1;
    return std::abs(w * (1 + side * rodSwingRatio(sc, phi, j)));
  }
  return std::abs(w);
}

// |F| and the joint's rotation speed n at every row.
JointRows jointRows(const Scene& sc, const RunFiles& f, const std::string& k, int j) {
  const std::string cart = std::to_string(j);
  JointRows r;
  for (std::size_t i = 0; i < f.ts.col("t").size(); ++i) {
    r.F.push_back(jointForce(f.rx, k, cart, i));
    r.n.push_back(jointSpeed(sc, f, k, j, i));
  }
  return r;
}

// A joint's figures by hand over the window, in summary.json's terms.
struct JointFigures {
  double mean = 0, amplitude = 0, peak = 0;  // of F [N]
  double P = 0;                              // (∫|F|³·n dt / ∫n dt)^(1/3) [N]
  double n_mean = 0;                         // [rad/s]
  double L10 = 0, L10h = 0;                  // [revolutions], [h]
};

// L10h: the rod end oscillates through 2γ = 2·asin(λ) once per crank revolution: L10·180°/(2γ)
// oscillations at f = (mean |ω_crank|)/2π a second; the others turn at n̄.
double lifeHours(const Scene& sc, const RunFiles& f, const std::string& k, double L10, double n_mean) {
  const std::vector<double>& t = f.ts.col("t");
  const std::vector<double>& w = f.ts.col("omega_crank");
  std::vector<double> w_abs(t.size());
  for (std::size_t i = 0; i < t.size(); ++i) w_abs[i] = std::abs(w[i]);
  const double frequency = integral(t, w_abs, f.b, f.e) / f.span / kTwoPi;
  const double lam = sc.crank.radius / sc.rods.length;
  return k == "rod_end" ? L10 * (kTwoPi / 2) / (2 * std::asin(lam)) / (3600.0 * frequency)
                        : L10 / (n_mean / kTwoPi * 3600.0);
}

// The figures of joint kind k of cart j, with rating C.
JointFigures jointFigures(const Scene& sc, const RunFiles& f, const std::string& k, int j, double C) {
  const std::vector<double>& t = f.ts.col("t");
  const std::size_t b = f.b, e = f.e;
  const JointRows jr = jointRows(sc, f, k, j);
  const std::vector<double>& F = jr.F;
  std::vector<double> F3n(t.size());
  for (std::size_t i = 0; i < t.size(); ++i) F3n[i] = std::pow(std::abs(F[i]), 3) * jr.n[i];
  JointFigures x;
  double lo = INFINITY, hi = -INFINITY;
  for (std::size_t i = b; i < e; ++i) {
    x.peak = std::max(x.peak, std::abs(F[i]));
    lo = std::min(lo, F[i]);
    hi = std::max(hi, F[i]);
  }
  x.mean = integral(t, F, b, e) / f.span;
  x.amplitude = 0.5 * (hi - lo);
  const double n_int = integral(t, jr.n, b, e);
  x.P = std::cbrt(integral(t, F3n, b, e) / n_int);
  x.n_mean = n_int / f.span;
  x.L10 = std::pow(C / x.P, 3.0) * 1e6;
  x.L10h = lifeHours(sc, f, k, x.L10, x.n_mean);
  return x;
}

// One joint row of summary.json (one cart's joint of one kind) against its figures by hand; the
// sentence of its life for the claim's examples.
std::string compareJoint(Comparison& jc, const Scene& sc, const RunFiles& f, const std::string& k, const json& row) {
  const int j = row.at("cart").is_number() ? row.at("cart").get<int>() : 0;
  const std::string label = k + (j ? " " + std::to_string(j) : "");
  const double C = row.at("rating").is_number() ? row.at("rating").get<double>() : kNaN;
  const JointFigures x = jointFigures(sc, f, k, j, C);
  jc.add(label + " mean", x.mean, row.at("mean"), x.peak);
  jc.add(label + " amplitude", x.amplitude, row.at("amplitude"), x.peak);
  jc.add(label + " peak", x.peak, row.at("peak"));
  jc.add(label + " P", x.P, row.at("equivalent_load"));
  jc.add(label + " mean speed", x.n_mean, row.at("mean_speed"));
  jc.add(label + " L10", x.L10, row.at("L10_revolutions"));
  jc.add(label + " L10h", x.L10h, row.at("L10_hours"));
  return label + ": P = " + g(x.P, 4) + " N, L10 = " + g(x.L10, 3) + " revolutions";
}

}  // namespace

void checkJoints(ValidationSection& s, const Scene& sc, const std::string& who, const RunFiles& f) {
  if (f.rx.col("t") != f.ts.col("t")) throw std::runtime_error(who + ": reactions.csv and timeseries.csv rows differ in time");
  Comparison jc;
  std::string lives;
  for (const char* kind : {"guide_roller_front", "guide_roller_rear", "rod_end", "crank_pin", "main_bearing"}) {
    const json& per = jsonAt(f.sz, std::string("joints.") + kind + ".per_cart");
    if (!per.is_array()) continue;
    for (const json& row : per) {
      const int j = row.at("cart").is_number() ? row.at("cart").get<int>() : 0;
      const std::string life = compareJoint(jc, sc, f, kind, row);
      if (std::string(kind) == "main_bearing" || (j == 1 && std::string(kind) == "guide_roller_front"))
        lives += (lives.empty() ? "" : "; ") + life;
    }
  }
  s.claim(jc.holds(), who + ": joint loads of every cart (mean, amplitude (max - min)/2, peak |F|, the "
                          "speed-weighted cubic mean P, mean speed n̄, L10 = (C/P)³·10⁶, L10h = L10/(n̄/2π·3600), the rod end's "
                          "L10h = L10·180°/(2γ)/(3600·f)) "
                          "from reactions.csv, e.g. " + lives + ": " + jc.sentence() + ".");
}

}  // namespace rollerdyn::validation::sizing_by_hand
