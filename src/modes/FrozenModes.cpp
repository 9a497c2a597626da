#include "modes/FrozenModes.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <vector>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

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
void setEnergyShares(FrozenMode& m, const ReducedModel& rm, double phi, bool elastic) {
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
}

// The mode's energy shares, and its name from its shape: the coupling twists when the motor side
// and the crank side turn against each other.
void nameMode(FrozenMode& m, const ReducedModel& rm, double phi, bool elastic) {
  setEnergyShares(m, rm, phi, elastic);
  if (!elastic) {
    m.name = "whole drive turning (rigid-body mode: motor, shaft and carts together)";
    return;
  }
  const double dphi2 = m.shape(0), dphi1 = dphi2 + m.shape(1);
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

// A candidate damped pair of eigenvalues (a complex conjugate pair, or two real eigenvalues) with
// its resemblance to each undamped mode.
struct Pair {
  std::complex<double> a, b;
  double mac[2];
};

// The state matrix's eigenvalues and eigenvectors, and the undamped shapes (columns) and mass
// matrix the eigenvectors' displacement parts are compared with.
struct DampedEigen {
  int n;
  Eigen::VectorXcd lambda;
  Eigen::MatrixXcd vec;
  const Eigen::MatrixXd& M;
  const Eigen::MatrixXd& shapes;
  double mac(int k, int mode) const { return assurance(vec.col(k).head(n), shapes.col(mode), M); }
};

// The eigenvalues by kind: of each conjugate pair the one with Im > 0 (it stands for both), and
// the real ones.
struct EigenvalueKinds {
  std::vector<int> complex_up, reals;
};

EigenvalueKinds eigenvalueKinds(const Eigen::VectorXcd& lambda) {
  EigenvalueKinds kinds;
  const double scale = lambda.cwiseAbs().maxCoeff();
  for (int k = 0; k < int(lambda.size()); ++k) {
    if (std::abs(lambda(k).imag()) > 1e-9 * scale) {
      if (lambda(k).imag() > 0) kinds.complex_up.push_back(k);
    } else {
      kinds.reals.push_back(k);
    }
  }
  return kinds;
}

// The pairing of four real eigenvalues that resembles the modes best, each pair marked as the
// mode it resembles (empty when no pairing scores).
std::vector<Pair> bestRealPairing(const DampedEigen& e, const std::vector<int>& reals) {
  const int splits[3][4] = {{0, 1, 2, 3}, {0, 2, 1, 3}, {0, 3, 1, 2}};
  std::vector<Pair> pairs;
  double best = -1;
  for (const auto& sp : splits)
    for (int first = 0; first < 2; ++first) {
      const int a0 = reals[size_t(sp[0])], a1 = reals[size_t(sp[1])], b0 = reals[size_t(sp[2])], b1 = reals[size_t(sp[3])];
      const double score = e.mac(a0, first) + e.mac(a1, first) + e.mac(b0, 1 - first) + e.mac(b1, 1 - first);
      if (score > best) {
        best = score;
        Pair p{e.lambda(a0), e.lambda(a1), {0, 0}}, q{e.lambda(b0), e.lambda(b1), {0, 0}};
        p.mac[first] = 1;
        q.mac[1 - first] = 1;
        pairs = {p, q};
      }
    }
  return pairs;
}

// Candidate pairs: the conjugate pairs, and the real eigenvalues paired.
std::vector<Pair> candidatePairs(const DampedEigen& e, const EigenvalueKinds& kinds) {
  std::vector<Pair> pairs;
  for (int k : kinds.complex_up) pairs.push_back({e.lambda(k), std::conj(e.lambda(k)), {e.mac(k, 0), e.mac(k, 1)}});
  const std::vector<int>& reals = kinds.reals;
  if (reals.size() == 2) {
    pairs.push_back({e.lambda(reals[0]), e.lambda(reals[1]),
                     {e.mac(reals[0], 0) + e.mac(reals[1], 0), e.mac(reals[0], 1) + e.mac(reals[1], 1)}});
  } else if (reals.size() == 4) {
    const std::vector<Pair> best = bestRealPairing(e, reals);
    if (!best.empty()) pairs = best;
  }
  return pairs;
}

// The undamped mode whose shape twists the coupling (motor side against crank side): 0 or 1, 2
// when both look twisted (undecided), -1 when neither does.
int twistedMode(const Eigen::MatrixXd& shapes) {
  int coupling = -1;
  for (int i = 0; i < 2; ++i) {
    const double dphi2 = shapes(0, i), dphi1 = shapes(0, i) + shapes(1, i);
    if (dphi1 * dphi2 < 0) coupling = coupling < 0 ? i : 2;
  }
  return coupling;
}

// Whether pairs[0] goes to undamped mode 0 (and pairs[1] to mode 1), else the other way round.
bool pairsInModeOrder(const std::vector<Pair>& pairs, const EigenvalueKinds& kinds, const Eigen::MatrixXd& shapes,
                      const Eigen::VectorXd& lambda_undamped) {
  bool straight = pairs[0].mac[0] + pairs[1].mac[1] >= pairs[0].mac[1] + pairs[1].mac[0];
  // One complex pair and two real eigenvalues: the oscillation is the coupling's. The rigid-body
  // mode has no restoring stiffness but the loads' small one, so a pair that oscillates is the
  // coupling twisting (the motor side against the crank side) whatever the motor's slope does to
  // its shape; the real pair is the rigid-body mode's.
  if (kinds.complex_up.size() == 1) {
    const int coupling = twistedMode(shapes);
    // Only where the other mode's stiffness is negligible (|λ| below 1 % of the coupling mode's);
    // a stiff second mode is told apart by its shape alone.
    if ((coupling == 0 || coupling == 1) && std::abs(lambda_undamped(1 - coupling)) <= 1e-2 * std::abs(lambda_undamped(coupling)))
      straight = coupling == 0;  // pairs[0] is the complex pair
  }
  return straight;
}

// The damped pairs of eigenvalues, entries 2i and 2i+1 for undamped mode i (shapes: columns of
// `shapes`): the state matrix's own pairs (a complex conjugate pair, or two real eigenvalues), each
// given to the undamped mode its eigenvectors resemble most (FrozenModes.h).
std::vector<std::complex<double>> dampedPairs(const Eigen::MatrixXd& Aq, const Eigen::MatrixXd& Av,
                                              const Eigen::MatrixXd& M, const Eigen::MatrixXd& shapes,
                                              const Eigen::VectorXd& lambda_undamped) {
  const int n = int(Aq.rows());
  Eigen::EigenSolver<Eigen::MatrixXd> ds(stateMatrix(Aq, Av), true);
  const DampedEigen e{n, ds.eigenvalues(), ds.eigenvectors(), M, shapes};
  std::vector<std::complex<double>> out(2 * n, std::complex<double>(NAN, NAN));
  if (n == 1) {
    out[0] = e.lambda(0);
    out[1] = e.lambda(1);
    return out;
  }
  const EigenvalueKinds kinds = eigenvalueKinds(e.lambda);
  const std::vector<Pair> pairs = candidatePairs(e, kinds);
  if (pairs.size() != 2) return out;  // cannot happen for a real 4×4 matrix
  const bool straight = pairsInModeOrder(pairs, kinds, shapes, lambda_undamped);
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

// Central-difference steps of each coordinate: the crank angle's absolute, the speed's relative
// to it (at least 1 rad/s), the twist's relative to it or to the breakdown torque's static twist.
struct DifferenceSteps {
  double phi, omega, twist, twist_rate;
};

DifferenceSteps differenceSteps(const Scene& scene, const DrivePoint& p, bool elastic) {
  const double twist_h = 1e-6 * std::max(std::abs(p.twist), elastic ? breakdownTwist(scene) : 1.0);
  const double phi_h = 1e-6, omega_h = 1e-6 * std::max(std::abs(p.omega), 1.0);
  const double rate_h = twist_h * std::max(std::abs(p.omega), 1.0);
  return {phi_h, omega_h, twist_h, rate_h};
}

// ∂(accelerations)/∂(one coordinate of p) by central differences of step h: the first n entries.
Eigen::VectorXd accelerationDerivative(DriveModel& drive, const DrivePoint& p, double DrivePoint::*coordinate,
                                       double h, int n) {
  DrivePoint plus = p, minus = p;
  plus.*coordinate += h;
  minus.*coordinate -= h;
  const Eigen::Vector2d d = (drive.accelerations(plus) - drive.accelerations(minus)) / (2 * h);
  return Eigen::VectorXd(d.head(n));
}

// The linearized accelerations at p: Aq by the coordinates (φ2, ψ), Av by their rates.
struct AccelerationSlopes {
  Eigen::MatrixXd Aq, Av;
};

AccelerationSlopes accelerationSlopes(DriveModel& drive, const DrivePoint& p, const DifferenceSteps& h, int n) {
  AccelerationSlopes a{Eigen::MatrixXd(n, n), Eigen::MatrixXd(n, n)};
  a.Aq.col(0) = accelerationDerivative(drive, p, &DrivePoint::phi, h.phi, n);
  a.Av.col(0) = accelerationDerivative(drive, p, &DrivePoint::omega, h.omega, n);
  if (n == 2) {
    a.Aq.col(1) = accelerationDerivative(drive, p, &DrivePoint::twist, h.twist, n);
    a.Av.col(1) = accelerationDerivative(drive, p, &DrivePoint::twist_rate, h.twist_rate, n);
  }
  return a;
}

// Undamped mode i of the eigen-pairs of M⁻¹K = -Aq: its eigenvalue, frequency and shape.
FrozenMode undampedMode(const Eigen::EigenSolver<Eigen::MatrixXd>& es, int i, int n, bool elastic) {
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
  return m;
}

// The rigid-body mode (not torsional) first, then by eigenvalue.
void sortRigidBodyFirst(std::vector<FrozenMode>& modes) {
  std::sort(modes.begin(), modes.end(), [](const FrozenMode& a, const FrozenMode& b) {
    return a.torsional != b.torsional ? !a.torsional : a.lambda < b.lambda;
  });
}

// The modes at the frozen angle phi: undamped eigen-pairs of M⁻¹K = -Aq, named from their shapes,
// each with the damped pair its shape resembles; the rigid-body mode first.
void addModes(FrozenAngle& f, const AccelerationSlopes& slopes, const ReducedModel& rm, double phi, bool elastic) {
  const int n = int(slopes.Aq.rows());
  Eigen::EigenSolver<Eigen::MatrixXd> es(-slopes.Aq, true);
  Eigen::MatrixXd shapes(n, n);
  for (int i = 0; i < n; ++i) shapes.col(i) = es.eigenvectors().col(i).real();
  const std::vector<std::complex<double>> damped =
      dampedPairs(slopes.Aq, slopes.Av, f.M, shapes, es.eigenvalues().real());
  for (int i = 0; i < n; ++i) {
    FrozenMode m = undampedMode(es, i, n, elastic);
    nameMode(m, rm, phi, elastic);
    // This mode's damped pair: the state matrix's pair whose eigenvectors resemble its shape.
    m.damping_ratio = NAN;
    if (std::isfinite(m.frequency)) setDampedPair(m, damped[2 * i], damped[2 * i + 1]);
    f.modes.push_back(m);
  }
  sortRigidBodyFirst(f.modes);
}

}  // namespace

FrozenAngle frozenModes(DriveModel& drive, const Scene& scene, const DrivePoint& p) {
  FrozenAngle f;
  f.point = p;
  drive.setOperatingPoint(p);
  const bool elastic = drive.elastic();
  const int n = elastic ? 2 : 1;
  f.M = drive.massMatrix(p.phi);
  const AccelerationSlopes slopes = accelerationSlopes(drive, p, differenceSteps(scene, p, elastic), n);
  f.K = -f.M * slopes.Aq;
  f.C = -f.M * slopes.Av;
  // No modes where the accelerations are not finite.
  if (!slopes.Aq.allFinite() || !slopes.Av.allFinite()) return f;
  addModes(f, slopes, drive.reducedModel(), p.phi, elastic);
  return f;
}

}  // namespace rollerdyn::modes
