#include "modes/FrozenModes.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <vector>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include "motor/BreakdownTorque.h"
#include "reduced/ReducedModel.h"

namespace rollerdyn::modes {

double FrozenAngle::torsional_frequency() const {
  for (const FrozenMode& m : modes)
    if (m.torsional) return m.frequency;
  return NAN;
}

double FrozenAngle::oscillation_frequency() const {
  double torsional = NAN, other = 0;
  for (const FrozenMode& m : modes) {
    if (m.torsional) torsional = m.oscillates ? m.damped_frequency : (std::isfinite(m.frequency) ? 0.0 : NAN);
    else if (m.oscillates) other = m.damped_frequency;
  }
  return std::isfinite(torsional) && torsional == 0 ? other : torsional;
}

Band bandOf(const std::vector<double>& v) {
  Band b;
  double sum = 0;
  int n = 0;
  for (double x : v) {
    if (!std::isfinite(x)) continue;
    sum += x;
    ++n;
    b.min = std::isfinite(b.min) ? std::min(b.min, x) : x;
    b.max = std::isfinite(b.max) ? std::max(b.max, x) : x;
  }
  if (n) b.mean = sum / n;
  return b;
}

namespace {

// Kinetic energy of one mode split over the machine's parts (fractions of the total).
void nameMode(FrozenMode& m, const ReducedModel& rm, double phi, bool elastic) {
  const Scene& scene = rm.scene();
  const double J1 = scene.motorSideInertia();
  const double dphi2 = m.shape(0), dpsi = elastic ? m.shape(1) : 0.0;
  const double dphi1 = dphi2 + dpsi;
  double carts = 0;
  for (int j = 0; j < scene.carts.count; ++j) {
    const double dx = rm.cartPose(j, phi).dx_B;
    carts += scene.cartMassWithRodShare(j) * dx * dx;
  }
  const double J2 = rm.crankSideInertia(phi);
  const double e_motor = J1 * dphi1 * dphi1, e_carts = carts * dphi2 * dphi2,
               e_shaft = std::max(0.0, J2 - carts) * dphi2 * dphi2;
  const double total = e_motor + e_carts + e_shaft;
  if (total > 0) {
    m.energy_motor_side = e_motor / total;
    m.energy_carts = e_carts / total;
    m.energy_shaft_rods = e_shaft / total;
  }
  if (!elastic) {
    m.name = "whole drive turning (rigid-body mode: motor, shaft and carts together)";
    return;
  }
  if (dphi1 * dphi2 < 0) {
    m.torsional = true;
    m.name = "motor side against crank side and carts (coupling twist)";
  } else {
    m.name = "whole drive turning together (rigid-body mode; coupling nearly untwisted)";
  }
}

// The damped state matrix [[0, I], [Aq, Av]].
Eigen::MatrixXd stateMatrix(const Eigen::MatrixXd& Aq, const Eigen::MatrixXd& Av) {
  const int n = int(Aq.rows());
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  S.topRightCorner(n, n).setIdentity();
  S.bottomLeftCorner(n, n) = Aq;
  S.bottomRightCorner(n, n) = Av;
  return S;
}

// Modal assurance of a damped eigenvector's displacement part v against an undamped shape φ, in
// the mass metric: |vᴴMφ|² / ((vᴴMv)(φᵀMφ)), 1 for the same shape.
double assurance(const Eigen::VectorXcd& v, const Eigen::VectorXd& phi, const Eigen::MatrixXd& M) {
  const Eigen::VectorXcd Mphi = (M * phi).cast<std::complex<double>>();
  const double num = std::norm(v.dot(Mphi));
  const double den = std::abs(v.dot((M.cast<std::complex<double>>() * v))) * phi.dot(M * phi);
  return den > 0 ? num / den : 0;
}

// The damped pairs of eigenvalues, entries 2i and 2i+1 for undamped mode i (shapes: columns of
// `shapes`): the state matrix's own pairs (a complex conjugate pair, or two real eigenvalues), each
// given to the undamped mode its eigenvectors resemble most (FrozenModes.h).
std::vector<std::complex<double>> dampedPairs(const Eigen::MatrixXd& Aq, const Eigen::MatrixXd& Av,
                                              const Eigen::MatrixXd& M, const Eigen::MatrixXd& shapes,
                                              const Eigen::VectorXd& lambda_undamped) {
  const int n = int(Aq.rows());
  Eigen::EigenSolver<Eigen::MatrixXd> ds(stateMatrix(Aq, Av), true);
  const Eigen::VectorXcd lambda = ds.eigenvalues();
  const Eigen::MatrixXcd vec = ds.eigenvectors();
  std::vector<std::complex<double>> out(2 * n, std::complex<double>(NAN, NAN));
  if (n == 1) {
    out[0] = lambda(0);
    out[1] = lambda(1);
    return out;
  }
  // Candidate pairs: conjugate pairs (the one with Im > 0 stands for both) and the real eigenvalues.
  struct Pair {
    std::complex<double> a, b;
    double mac[2];
  };
  std::vector<int> complex_up, reals;
  const double scale = lambda.cwiseAbs().maxCoeff();
  for (int k = 0; k < 2 * n; ++k) {
    if (std::abs(lambda(k).imag()) > 1e-9 * scale) {
      if (lambda(k).imag() > 0) complex_up.push_back(k);
    } else {
      reals.push_back(k);
    }
  }
  auto mac = [&](int k, int mode) { return assurance(vec.col(k).head(n), shapes.col(mode), M); };
  std::vector<Pair> pairs;
  for (int k : complex_up) pairs.push_back({lambda(k), std::conj(lambda(k)), {mac(k, 0), mac(k, 1)}});
  if (reals.size() == 2) {
    pairs.push_back({lambda(reals[0]), lambda(reals[1]),
                     {mac(reals[0], 0) + mac(reals[1], 0), mac(reals[0], 1) + mac(reals[1], 1)}});
  } else if (reals.size() == 4) {  // the pairing of four real eigenvalues that resembles the modes best
    const int splits[3][4] = {{0, 1, 2, 3}, {0, 2, 1, 3}, {0, 3, 1, 2}};
    double best = -1;
    for (const auto& sp : splits)
      for (int first = 0; first < 2; ++first) {
        const int a0 = reals[size_t(sp[0])], a1 = reals[size_t(sp[1])], b0 = reals[size_t(sp[2])], b1 = reals[size_t(sp[3])];
        const double score = mac(a0, first) + mac(a1, first) + mac(b0, 1 - first) + mac(b1, 1 - first);
        if (score > best) {
          best = score;
          pairs.clear();
          Pair p{lambda(a0), lambda(a1), {0, 0}}, q{lambda(b0), lambda(b1), {0, 0}};
          p.mac[first] = 1;
          q.mac[1 - first] = 1;
          pairs = {p, q};
        }
      }
  }
  if (pairs.size() != 2) return out;  // cannot happen for a real 4×4 matrix
  bool straight = pairs[0].mac[0] + pairs[1].mac[1] >= pairs[0].mac[1] + pairs[1].mac[0];
  // One complex pair and two real eigenvalues: the oscillation is the coupling's. The rigid-body
  // mode has no restoring stiffness but the loads' small one, so a pair that oscillates is the
  // coupling twisting (the motor side against the crank side) whatever the motor's slope does to
  // its shape; the real pair is the rigid-body mode's.
  if (complex_up.size() == 1) {
    int coupling = -1;
    for (int i = 0; i < 2; ++i) {
      const double dphi2 = shapes(0, i), dphi1 = shapes(0, i) + shapes(1, i);
      if (dphi1 * dphi2 < 0) coupling = coupling < 0 ? i : 2;  // 2: both look twisted, undecided
    }
    // Only where the other mode's stiffness is negligible (|λ| below 1 % of the coupling mode's);
    // a stiff second mode is told apart by its shape alone.
    if ((coupling == 0 || coupling == 1) && std::abs(lambda_undamped(1 - coupling)) <= 1e-2 * std::abs(lambda_undamped(coupling)))
      straight = coupling == 0;  // pairs[0] is the complex pair
  }
  const Pair& m0 = straight ? pairs[0] : pairs[1];
  const Pair& m1 = straight ? pairs[1] : pairs[0];
  out[0] = m0.a;
  out[1] = m0.b;
  out[2] = m1.a;
  out[3] = m1.b;
  return out;
}

// ζ, ω_n and ω_d of a mode from its damped pair (see FrozenModes.h).
void setDampedPair(FrozenMode& m, std::complex<double> a, std::complex<double> b) {
  const double tiny = 1e-9 * (std::abs(a) + std::abs(b));
  const bool complex_pair = std::abs(a.imag()) > tiny && std::abs(b.imag()) > tiny;
  if (complex_pair) {
    const std::complex<double> l = a.imag() > 0 ? a : b;
    m.natural_frequency = std::abs(l);
    m.damping_ratio = -l.real() / m.natural_frequency;
    m.damped_frequency = std::abs(l.imag());
    m.oscillates = true;
  } else {  // two real eigenvalues: overdamped (ζ ≥ 1), no damped frequency
    const double product = a.real() * b.real();
    m.natural_frequency = product > 0 ? std::sqrt(product) : NAN;
    m.damping_ratio = product > 0 ? -(a.real() + b.real()) / (2 * m.natural_frequency) : NAN;
    m.damped_frequency = 0.0;
    m.oscillates = false;
  }
}

}  // namespace

FrozenAngle frozenModes(DriveModel& drive, const Scene& scene, const DrivePoint& p) {
  FrozenAngle f;
  f.point = p;
  drive.setOperatingPoint(p);
  const bool elastic = drive.elastic();
  const int n = elastic ? 2 : 1;
  f.M = drive.massMatrix(p.phi);
  const double twist_h =
      1e-6 * std::max(std::abs(p.twist),
                      elastic ? std::max(motorBreakdownTorque(scene) * scene.reducer.ratio * scene.reducer.efficiency, 1.0) /
                                    scene.coupling.stiffness
                              : 1.0);
  const double phi_h = 1e-6, omega_h = 1e-6 * std::max(std::abs(p.omega), 1.0);
  const double rate_h = twist_h * std::max(std::abs(p.omega), 1.0);
  Eigen::MatrixXd Aq(n, n), Av(n, n);
  auto column = [&](DrivePoint plus, DrivePoint minus, double h) {
    const Eigen::Vector2d d = (drive.accelerations(plus) - drive.accelerations(minus)) / (2 * h);
    return Eigen::VectorXd(d.head(n));
  };
  {
    DrivePoint a = p, b = p;
    a.phi += phi_h;
    b.phi -= phi_h;
    Aq.col(0) = column(a, b, phi_h);
    a = p, b = p;
    a.omega += omega_h;
    b.omega -= omega_h;
    Av.col(0) = column(a, b, omega_h);
  }
  if (elastic) {
    DrivePoint a = p, b = p;
    a.twist += twist_h;
    b.twist -= twist_h;
    Aq.col(1) = column(a, b, twist_h);
    a = p, b = p;
    a.twist_rate += rate_h;
    b.twist_rate -= rate_h;
    Av.col(1) = column(a, b, rate_h);
  }
  f.K = -f.M * Aq;
  f.C = -f.M * Av;
  // Undamped frozen modes: eigen-pairs of M⁻¹K = -Aq.
  if (!Aq.allFinite() || !Av.allFinite()) return f;  // no modes where the accelerations are not finite
  Eigen::EigenSolver<Eigen::MatrixXd> es(-Aq, true);
  Eigen::MatrixXd shapes(n, n);
  for (int i = 0; i < n; ++i) shapes.col(i) = es.eigenvectors().col(i).real();
  const std::vector<std::complex<double>> damped = dampedPairs(Aq, Av, f.M, shapes, es.eigenvalues().real());
  for (int i = 0; i < n; ++i) {
    FrozenMode m;
    m.lambda = es.eigenvalues()(i).real();
    m.frequency = m.lambda > 0 ? std::sqrt(m.lambda) : NAN;
    Eigen::Vector2d v = Eigen::Vector2d::Zero();
    v.head(n) = es.eigenvectors().col(i).real();
    // Normalized so the larger of |δφ2|, |δφ1| is 1, with δφ1 ≥ 0 (motor side turning forward).
    const double dphi1 = elastic ? v(0) + v(1) : v(0);
    const double scale = std::max(std::abs(v(0)), std::abs(dphi1));
    if (scale > 0) v /= (dphi1 < 0 ? -scale : scale);
    m.shape = v;
    nameMode(m, drive.reducedModel(), p.phi, elastic);
    // This mode's damped pair: the state matrix's pair whose eigenvectors resemble its shape.
    m.damping_ratio = NAN;
    if (std::isfinite(m.frequency)) setDampedPair(m, damped[2 * i], damped[2 * i + 1]);
    f.modes.push_back(m);
  }
  std::sort(f.modes.begin(), f.modes.end(), [](const FrozenMode& a, const FrozenMode& b) {
    return a.torsional != b.torsional ? !a.torsional : a.lambda < b.lambda;
  });
  return f;
}

}  // namespace rollerdyn::modes
