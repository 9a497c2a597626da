#include "physics/TwoRotorClosedForm.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rollerdyn {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr int kHarmonics[4] = {1, 2, 3, 5};

// Sin and cos coefficients A_n, B_n of M(t) − mean, eq. (8)·J1: M = Σ A_n sin nωt + B_n cos nωt.
void forcing(const TwoRotorParameters& p, double A[4], double B[4]) {
  const double f = p.M1 / M_PI, al = p.alpha;
  A[0] = 2 * f;      B[0] = f * std::sin(al);
  A[1] = 0;          B[1] = -f * std::sin(2 * al) / 2;
  A[2] = 2 * f / 3;  B[2] = f * std::sin(3 * al) / 3;
  A[3] = 2 * f / 5;  B[3] = 0;
}

// Exact steady harmonics ψ*(t) − Φ0 and their rate ψ̇*(t).
void steadyExact(const TwoRotorParameters& p, double t, double* psi, double* rate) {
  double A[4], B[4];
  forcing(p, A, B);
  const double p0 = naturalFrequency(p), d1 = dampingRate(p);
  double y = 0, v = 0;
  for (int i = 0; i < 4; ++i) {
    const double nw = kHarmonics[i] * p.omega;
    const double re = p0 * p0 - nw * nw, im = 2 * d1 * nw;
    const double D = p.J1 * std::hypot(re, im), xi = std::atan2(im, re);
    const double th = nw * t - xi;
    y += (A[i] * std::sin(th) + B[i] * std::cos(th)) / D;
    v += nw * (A[i] * std::cos(th) - B[i] * std::sin(th)) / D;
  }
  *psi = y;
  if (rate) *rate = v;
}

// The printed partial terms before the harmonics of one order combine: amplitudes of the sin and
// cos parts, eq. (16)-(21), and phases, eq. (22)-(25) (arctg as printed: atan).
struct PartialTerms {
  double Psi11, Psi31, Psi51, Psi12, Psi2, Psi32, xi11, xi2, xi31, xi5;
};
PartialTerms partialTerms(const TwoRotorParameters& p) {
  const double w = p.omega, dl = dampingRate(p), p0 = naturalFrequency(p), p02 = p0 * p0, M1 = p.M1, J1 = p.J1,
               al = p.alpha;
  auto den = [&](double n) { return std::sqrt(std::pow(p02 - n * n * w * w, 2) + 4 * dl * dl * n * n * w * w); };
  PartialTerms t;
  t.Psi11 = 2 * M1 / (M_PI * J1 * den(1));                 // (16)
  t.Psi31 = 2 * M1 / (M_PI * J1 * den(3));                 // (17)
  t.Psi51 = 2 * M1 / (M_PI * J1 * den(5));                 // (18)
  t.Psi12 = M1 * std::sin(al) / (M_PI * J1 * den(1));      // (19)
  t.Psi2 = M1 * std::sin(2 * al) / (M_PI * J1 * den(2));   // (20)
  t.Psi32 = M1 * std::sin(3 * al) / (M_PI * J1 * den(3));  // (21)
  t.xi11 = std::atan(2 * dl * w / (p02 - w * w));          // (22)
  t.xi2 = std::atan(4 * dl * w / (p02 - 4 * w * w));       // (23)
  t.xi31 = std::atan(6 * dl * w / (p02 - 9 * w * w));      // (24)
  t.xi5 = std::atan(10 * dl * w / (p02 - 25 * w * w));     // (25)
  return t;
}

// One order's amplitude from its two partial terms a, b and the phase xi, eq. (27), (28).
double combinedAmplitude(double a, double b, double xi) {
  return std::sqrt(std::max(0.0, a * a + b * b - 2 * a * b * std::sin(2 * xi)));
}

// One order's phase from its two partial terms a, b and the phase xi, eq. (29), (30).
double combinedPhase(double a, double b, double xi) {
  return std::atan((a * std::sin(xi) - b * std::cos(xi)) / (a * std::cos(xi) - b * std::sin(xi)));
}

// The printed amplitudes and phases, eq. (16)-(25), (27)-(30) (arctg as printed: atan).
struct Printed {
  double Psi1, Psi2, Psi3, Psi5, xi1, xi2, xi3, xi5;
};
Printed printedTerms(const TwoRotorParameters& p) {
  const PartialTerms t = partialTerms(p);
  Printed r;
  r.Psi1 = combinedAmplitude(t.Psi11, t.Psi12, t.xi11);  // (27)
  r.Psi3 = combinedAmplitude(t.Psi31, t.Psi32, t.xi31);  // (28)
  r.xi1 = combinedPhase(t.Psi11, t.Psi12, t.xi11);       // (29)
  r.xi3 = combinedPhase(t.Psi31, t.Psi32, t.xi31);       // (30)
  r.Psi2 = t.Psi2;
  r.Psi5 = t.Psi51;
  r.xi2 = t.xi2;
  r.xi5 = t.xi5;
  return r;
}

}  // namespace

double naturalFrequency(const TwoRotorParameters& p) { return std::sqrt(p.k * (p.J1 + p.J2) / (p.J1 * p.J2)); }
double dampingRate(const TwoRotorParameters& p) { return p.b * (p.J1 + p.J2) / (2.0 * p.J1 * p.J2); }
double dampedFrequency(const TwoRotorParameters& p) {
  const double p0 = naturalFrequency(p), d = dampingRate(p);
  return d < p0 ? std::sqrt(p0 * p0 - d * d) : kNaN;
}
double meanTwist(const TwoRotorParameters& p) {
  const double p0sq = p.k * (p.J1 + p.J2) / (p.J1 * p.J2);
  return p.M1 * (M_PI - 2.0 * p.alpha) / (M_PI * p.J1 * p0sq) + p.Mc / (p.J2 * p0sq);
}
double balancedResistingTorque(const TwoRotorParameters& p) { return p.M1 * (M_PI - 2.0 * p.alpha) / M_PI; }

double driveTorque(const TwoRotorParameters& p, double t) {
  const double w = p.omega, a = p.alpha, M1 = p.M1;
  return M1 * (M_PI - 2.0 * a) / M_PI +
         2.0 * M1 / M_PI * (std::sin(w * t) + std::sin(3 * w * t) / 3.0 + std::sin(5 * w * t) / 5.0) +
         M1 / M_PI *
             (std::sin(a) * std::cos(w * t) - std::sin(2 * a) * std::cos(2 * w * t) / 2.0 +
              std::sin(3 * a) * std::cos(3 * w * t) / 3.0);
}

std::vector<HarmonicResponse> closedFormResponse(const TwoRotorParameters& p) {
  const double p0 = naturalFrequency(p), d1 = dampingRate(p);
  double A[4], B[4];
  forcing(p, A, B);
  const Printed q = printedTerms(p);
  const double printed[4] = {q.Psi1, q.Psi2, q.Psi3, q.Psi5};
  std::vector<HarmonicResponse> out;
  for (int i = 0; i < 4; ++i) {
    HarmonicResponse h;
    h.n = kHarmonics[i];
    const double nw = h.n * p.omega;
    h.phase_lag = std::atan2(2.0 * d1 * nw, p0 * p0 - nw * nw);
    const double gain = 1.0 / (p.J1 * std::hypot(p0 * p0 - nw * nw, 2.0 * d1 * nw));
    // A·sin(nωt − ξ) + B·cos(nωt − ξ), expanded in sin nωt and cos nωt
    h.a_sin = gain * (A[i] * std::cos(h.phase_lag) + B[i] * std::sin(h.phase_lag));
    h.b_cos = gain * (B[i] * std::cos(h.phase_lag) - A[i] * std::sin(h.phase_lag));
    h.amplitude = gain * std::hypot(A[i], B[i]);
    h.amplitude_printed = printed[i];
    out.push_back(h);
  }
  return out;
}

double twistExact(const TwoRotorParameters& p, double t, bool with_transient) {
  const double Phi0 = meanTwist(p);
  double y = 0;
  steadyExact(p, t, &y, nullptr);
  double psi = Phi0 + y;
  if (!with_transient) return psi;
  // Homogeneous part fitted to ψ(0) = ψ̇(0) = 0 (eq. (33)).
  double y0 = 0, v0s = 0;
  steadyExact(p, 0.0, &y0, &v0s);
  const double h0 = -(Phi0 + y0), v0 = -v0s;
  const double dl = dampingRate(p), p0 = naturalFrequency(p);
  if (dl < p0) {
    const double p1 = dampedFrequency(p);
    psi += std::exp(-dl * t) * (h0 * std::cos(p1 * t) + (v0 + dl * h0) / p1 * std::sin(p1 * t));
  } else if (dl == p0) {
    psi += std::exp(-dl * t) * (h0 + (v0 + dl * h0) * t);
  } else {
    const double s = std::sqrt(dl * dl - p0 * p0), r1 = -dl + s, r2 = -dl - s;
    const double A1 = (v0 - r2 * h0) / (r1 - r2), A2 = h0 - A1;
    psi += A1 * std::exp(r1 * t) + A2 * std::exp(r2 * t);
  }
  return psi;
}

double twistPrinted(const TwoRotorParameters& p, double t, bool with_transient) {
  const Printed q = printedTerms(p);
  const double w = p.omega, Phi0 = meanTwist(p);
  const double steady = q.Psi1 * std::sin(w * t - q.xi1) - q.Psi2 * std::cos(2 * w * t + q.xi2) +
                        q.Psi3 * std::sin(3 * w * t - q.xi3) + q.Psi5 * std::sin(5 * w * t - q.xi5);  // (26)
  if (!with_transient) return Phi0 + steady;
  const double p1 = dampedFrequency(p);
  if (!std::isfinite(p1)) return kNaN;  // (13)-(14) assume an oscillating transient
  const double dl = dampingRate(p), e = std::exp(-dl * t);
  const double Bt = (q.Psi1 * (dl * std::sin(q.xi1) - w * std::cos(q.xi1)) +
                     q.Psi2 * (dl * std::cos(q.xi2) - 2 * w * std::sin(q.xi2)) +
                     q.Psi3 * (dl * std::sin(q.xi3) - 3 * w * std::cos(q.xi3)) +
                     q.Psi5 * (dl * std::sin(q.xi5) - 5 * w * std::cos(q.xi5))) / p1;
  const double Dt = q.Psi1 * std::sin(q.xi1) + q.Psi2 * std::cos(q.xi2) + q.Psi3 * std::sin(q.xi3) +
                    q.Psi5 * std::sin(q.xi5);
  return Phi0 * (1 - e * (dl / p1 * std::sin(p1 * t) + std::cos(p1 * t))) + e * Bt * std::sin(p1 * t) +
         e * Dt * std::cos(p1 * t) + steady;  // (36)
}

}  // namespace rollerdyn
