#include "analysis/CrankSpeedExtrema.h"

#include <cmath>

namespace rollerdyn {

namespace {

// ε has strictly opposite signs at a step's two ends: ω has an extremum strictly inside it.
bool changesSign(double eps0, double eps1) { return (eps0 < 0 && eps1 > 0) || (eps0 > 0 && eps1 < 0); }

// The bracket [a, b] around ε's zero, ε's values fa, fb at its ends and which end moved last
// (−1: a, +1: b), for regula falsi with the Illinois modification.
struct EpsBracket {
  double a, b, fa, fb;
  int side = 0;

  // Moves the end on ε's side of zero to c; when the same end moves twice in a row, halves the
  // other end's value (Illinois), so the iteration does not stall with one end fixed.
  void narrow(double c, double e) {
    if ((e < 0) == (fa < 0)) {
      a = c;
      fa = e;
      if (side == -1) fb *= 0.5;
      side = -1;
    } else {
      b = c;
      fb = e;
      if (side == 1) fa *= 0.5;
      side = 1;
    }
  }
};

// Where ε of the integrator's interpolant crosses zero inside the step [t0, t1]: regula falsi
// with the Illinois modification. `w`, `e` hold the interpolant's values at the last point tried.
double zeroOfEps(const CrankSpeedExtremaFinder::Dense& dense, double t0, double e0, double t1, double e1, double& w,
                 double& e) {
  EpsBracket br{t0, t1, e0, e1};
  for (int it = 0; it < 60 && br.b - br.a > 1e-12 * (t1 - t0); ++it) {
    const double c = (br.a * br.fb - br.b * br.fa) / (br.fb - br.fa);
    dense(c, w, e);
    if (!std::isfinite(e)) break;
    br.narrow(c, e);
    if (e == 0.0) {
      br.a = br.b = c;
      break;
    }
  }
  return 0.5 * (br.a + br.b);
}

// Where, as s = (t − t0)/h ∈ [0, 1], the cubic Hermite interpolant of ω over a step has its
// extremum, from ω's change D = ω1 − ω0 and the end slopes p = h·ε0, q = h·ε1 (rad/s).
// ω(s) = h00·ω0 + h10·h·ε0 + h01·ω1 + h11·h·ε1. Its derivative in s is the quadratic
// a·s² + b·s + c with c = h·ε0 and a + b + c = h·ε1; the remaining coefficient comes from the
// cubic's end values: dω/ds = 6(s − s²)(ω1 − ω0) + h·ε0·(1 − 4s + 3s²) + h·ε1·(3s² − 2s).
double hermiteExtremum(double D, double p, double q) {
  const double a = -6.0 * D + 3.0 * p + 3.0 * q, b = 6.0 * D - 4.0 * p - 2.0 * q, c = p;
  // The derivative changes sign on (0, 1), so it has exactly one root there (or three counted with a
  // double root, which a quadratic cannot have with opposite signs at the ends): bracket and refine.
  double s;
  if (std::abs(a) < 1e-14 * (std::abs(b) + std::abs(c))) {
    s = -c / b;
  } else {
    const double disc = std::sqrt(std::max(0.0, b * b - 4.0 * a * c));
    // Cancellation-free roots of the quadratic; take the one inside (0, 1).
    const double qq = -0.5 * (b + std::copysign(disc, b));
    const double r1 = qq / a, r2 = qq != 0.0 ? c / qq : r1;
    s = (r1 > 0.0 && r1 < 1.0) ? r1 : r2;
  }
  if (!(s > 0.0 && s < 1.0)) s = std::fmin(1.0, std::fmax(0.0, s));
  return s;
}

// The cubic Hermite interpolant's ω (rad/s) at s ∈ [0, 1] from the end values and slopes p, q.
double hermiteOmega(double s, double w0, double p, double w1, double q) {
  const double s2 = s * s, s3 = s2 * s;
  const double h00 = 2 * s3 - 3 * s2 + 1, h10 = s3 - 2 * s2 + s, h01 = -2 * s3 + 3 * s2, h11 = s3 - s2;
  return h00 * w0 + h10 * p + h01 * w1 + h11 * q;
}

}  // namespace

void CrankSpeedExtremaFinder::step(double t0, double w0, double e0, double t1, double w1, double e1) {
  const double h = t1 - t0;
  if (!(h > 0) || !std::isfinite(w0) || !std::isfinite(w1) || !std::isfinite(e0) || !std::isfinite(e1)) return;
  if (!changesSign(e0, e1)) return;
  const double D = w1 - w0, p = h * e0, q = h * e1;
  const double s = hermiteExtremum(D, p, q);
  extrema_.push_back({t0 + s * h, hermiteOmega(s, w0, p, w1, q)});
}

void CrankSpeedExtremaFinder::restart(double t, double omega, double eps) {
  have_last_ = true;
  t_ = t;
  omega_ = omega;
  eps_ = eps;
}

void CrankSpeedExtremaFinder::stepTo(double t, double omega, double eps, const Dense& dense) {
  if (have_last_ && t > t_) {
    if (dense && changesSign(eps_, eps)) {
      double w = omega, e = eps;
      const double tx = zeroOfEps(dense, t_, eps_, t, eps, w, e);
      dense(tx, w, e);
      if (std::isfinite(w)) extrema_.push_back({tx, w});
      else step(t_, omega_, eps_, t, omega, eps);
    } else {
      step(t_, omega_, eps_, t, omega, eps);
    }
  }
  restart(t, omega, eps);
}

void CrankSpeedExtremaFinder::dropAfter(double t) {
  while (!extrema_.empty() && !(extrema_.back().t <= t)) extrema_.pop_back();
}

std::vector<CrankSpeedExtremum> CrankSpeedExtremaFinder::takeUpTo(double t_last) {
  dropAfter(t_last);
  return std::move(extrema_);
}

Table crankSpeedExtremaTable(const std::vector<CrankSpeedExtremum>& extrema) {
  Table t;
  t.columns = {"t", "omega_crank"};
  t.rows.reserve(extrema.size());
  for (const CrankSpeedExtremum& x : extrema) t.rows.push_back({x.t, x.omega});
  return t;
}

}  // namespace rollerdyn
