#include "modes/FrozenModes.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include "reduced/ReducedModel.h"

namespace rollerdyn::modes {

double FrozenAngle::torsional_frequency() const {
  for (const FrozenMode& m : modes)
    if (m.torsional) return m.frequency;
  return NAN;
}

double FrozenAngle::torsional_damped_frequency() const {
  for (const FrozenMode& m : modes)
    if (m.torsional) return m.damped_frequency;
  return NAN;
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
void nameMode(FrozenMode& m, const Scene& scene, double phi, bool elastic) {
  const ReducedModel rm(scene);
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
                      elastic ? std::max(scene.motor.breakdown_torque * scene.reducer.ratio * scene.reducer.efficiency, 1.0) /
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
  // Damped frozen modes: the state matrix [[0, I], [Aq, Av]].
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  S.topRightCorner(n, n).setIdentity();
  S.bottomLeftCorner(n, n) = Aq;
  S.bottomRightCorner(n, n) = Av;
  Eigen::EigenSolver<Eigen::MatrixXd> ds(S, false);
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
    nameMode(m, scene, p.phi, elastic);
    // Damping ratio of the damped pair whose frequency is closest to this mode's.
    m.damping_ratio = NAN;
    if (std::isfinite(m.frequency)) {
      double best = INFINITY;
      for (int k = 0; k < 2 * n; ++k) {
        const std::complex<double> l = ds.eigenvalues()(k);
        if (l.imag() <= 0) continue;
        const double wn = std::abs(l);
        if (std::abs(wn - m.frequency) < best) {
          best = std::abs(wn - m.frequency);
          m.damping_ratio = -l.real() / wn;
          m.damped_frequency = l.imag();
        }
      }
      if (!std::isfinite(best)) {  // no oscillating pair: at least critically damped
        m.damping_ratio = 1.0;
        m.damped_frequency = 0.0;
      }
    }
    f.modes.push_back(m);
  }
  std::sort(f.modes.begin(), f.modes.end(), [](const FrozenMode& a, const FrozenMode& b) {
    return a.torsional != b.torsional ? !a.torsional : a.lambda < b.lambda;
  });
  return f;
}

}  // namespace rollerdyn::modes
