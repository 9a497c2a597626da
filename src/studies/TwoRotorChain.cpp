#include "studies/TwoRotorChain.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "Simbody.h"
#include "multibody/ElasticCoupling.h"
#include "studies/ResonanceCheck.h"

namespace rollerdyn {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
const int kHarm[4] = {1, 2, 3, 5};

// Forcing of eq. (12) per unit of ψ̈ (i.e. divided by J1): a_n·sin(nωt) + c_n·cos(nωt).
void forcing(const TwoRotorChainParams& p, double a[4], double c[4]) {
  const double f = p.M1 / (M_PI * p.J1), al = p.alpha;
  a[0] = 2 * f;      c[0] = f * std::sin(al);
  a[1] = 0;          c[1] = -f * std::sin(2 * al) / 2;
  a[2] = 2 * f / 3;  c[2] = f * std::sin(3 * al) / 3;
  a[3] = 2 * f / 5;  c[3] = 0;
}

// Corrected steady harmonics ψ*(t) and ψ̇*(t) (no mean).
void steadyCorrected(const TwoRotorChainParams& p, const TwoRotorChainDerived& d, double t,
                     double* psi, double* rate) {
  double a[4], c[4];
  forcing(p, a, c);
  double y = 0, v = 0;
  for (int i = 0; i < 4; ++i) {
    const double nw = kHarm[i] * p.omega;
    const double re = d.p0 * d.p0 - nw * nw, im = 2 * d.delta1 * nw;
    const double D = std::hypot(re, im), xi = std::atan2(im, re);
    const double th = nw * t - xi;
    y += (a[i] * std::sin(th) + c[i] * std::cos(th)) / D;
    v += nw * (a[i] * std::cos(th) - c[i] * std::sin(th)) / D;
  }
  *psi = y;
  if (rate) *rate = v;
}

// The printed amplitudes and phases, eq. (16)-(25), (27)-(30).
struct Printed {
  double Psi1, Psi2, Psi3, Psi5, xi1, xi2, xi3, xi5;
};
Printed printedTerms(const TwoRotorChainParams& p, const TwoRotorChainDerived& d) {
  const double w = p.omega, dl = d.delta1, p02 = d.p0 * d.p0, M1 = p.M1, J1 = p.J1, al = p.alpha;
  auto den = [&](double n) { return std::sqrt(std::pow(p02 - n * n * w * w, 2) + 4 * dl * dl * n * n * w * w); };
  const double Psi11 = 2 * M1 / (M_PI * J1 * den(1));              // (16)
  const double Psi31 = 2 * M1 / (M_PI * J1 * den(3));              // (17)
  const double Psi51 = 2 * M1 / (M_PI * J1 * den(5));              // (18)
  const double Psi12 = M1 * std::sin(al) / (M_PI * J1 * den(1));   // (19)
  const double Psi2 = M1 * std::sin(2 * al) / (M_PI * J1 * den(2));  // (20)
  const double Psi32 = M1 * std::sin(3 * al) / (M_PI * J1 * den(3));  // (21)
  const double xi11 = std::atan(2 * dl * w / (p02 - w * w));       // (22)
  const double xi2 = std::atan(4 * dl * w / (p02 - 4 * w * w));    // (23)
  const double xi31 = std::atan(6 * dl * w / (p02 - 9 * w * w));   // (24)
  const double xi5 = std::atan(10 * dl * w / (p02 - 25 * w * w));  // (25)
  Printed r;
  r.Psi1 = std::sqrt(Psi11 * Psi11 + Psi12 * Psi12 - 2 * Psi11 * Psi12 * std::sin(2 * xi11));  // (27)
  r.Psi3 = std::sqrt(Psi31 * Psi31 + Psi32 * Psi32 - 2 * Psi31 * Psi32 * std::sin(2 * xi31));  // (28)
  r.xi1 = std::atan((Psi11 * std::sin(xi11) - Psi12 * std::cos(xi11)) /
                    (Psi11 * std::cos(xi11) - Psi12 * std::sin(xi11)));  // (29)
  r.xi3 = std::atan((Psi31 * std::sin(xi31) - Psi32 * std::cos(xi31)) /
                    (Psi31 * std::cos(xi31) - Psi32 * std::sin(xi31)));  // (30)
  r.Psi2 = Psi2;
  r.Psi5 = Psi51;
  r.xi2 = xi2;
  r.xi5 = xi5;
  return r;
}

// Mobility forces of the drive: M(t) on rotor 1, -M_c on rotor 2 (eq. (1)-(2) right-hand sides).
class ChainTorques : public SimTK::Force::Custom::Implementation {
 public:
  ChainTorques(const SimTK::MobilizedBody& r1, const SimTK::MobilizedBody& r2,
               const TwoRotorChainParams& p, double Mc)
      : r1_(r1), r2_(r2), p_(p), Mc_(Mc) {}
  // Rotor 1 is mobilized on rotor 2 (its coordinate is the twist), so its drive is a body
  // torque; rotor 2 turns on ground and takes the resisting torque as a mobility force.
  void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>& body_forces,
                 SimTK::Vector_<SimTK::Vec3>&, SimTK::Vector& mobility_forces) const override {
    r1_.applyBodyTorque(s, SimTK::Vec3(0, 0, chainDriveTorque(p_, s.getTime())), body_forces);
    r2_.applyOneMobilityForce(s, 0, -Mc_, mobility_forces);
  }
  SimTK::Real calcPotentialEnergy(const SimTK::State&) const override { return 0; }

 private:
  SimTK::MobilizedBody r1_, r2_;
  TwoRotorChainParams p_;
  double Mc_;
};

SimTK::Body::Rigid rotor(double J) {
  // Token mass on the axis as in MultibodyModel (Simbody needs mass with inertia).
  return SimTK::Body::Rigid(SimTK::MassProperties(1e-3, SimTK::Vec3(0), SimTK::Inertia(0.5 * J, 0.5 * J, J)));
}

}  // namespace

TwoRotorChainDerived deriveChain(const TwoRotorChainParams& p) {
  if (!(p.J1 > 0) || !(p.J2 > 0) || !(p.k > 0) || !(p.b >= 0) || !(p.omega > 0) || !std::isfinite(p.M1) ||
      !std::isfinite(p.alpha))
    throw std::invalid_argument("chain: need J1, J2, k, omega > 0, b >= 0 and finite M1, alpha");
  TwoRotorChainDerived d;
  d.delta1 = p.b * (p.J1 + p.J2) / (2 * p.J1 * p.J2);    // (9)
  d.p0 = std::sqrt(p.k * (p.J1 + p.J2) / (p.J1 * p.J2));  // (10)
  d.p1 = d.delta1 < d.p0 ? std::sqrt(d.p0 * d.p0 - d.delta1 * d.delta1) : kNaN;  // (14)
  d.Mc = p.Mc >= 0 ? p.Mc : p.M1 * (M_PI - 2 * p.alpha) / M_PI;
  d.Phi0 = p.M1 * (M_PI - 2 * p.alpha) / (M_PI * p.J1 * d.p0 * d.p0) + d.Mc / (p.J2 * d.p0 * d.p0);  // (11), (43)
  // Slowest decay rate of the transient: δ1 when underdamped, else the slow real root.
  const double decay = d.delta1 < d.p0 ? d.delta1 : d.delta1 - std::sqrt(d.delta1 * d.delta1 - d.p0 * d.p0);
  const double period = 2 * M_PI / p.omega;
  d.t_end = p.t_end > 0 ? p.t_end
                        : std::min(std::max(std::log(1e9) / std::max(decay, 1e-12), 10 * period), 400.0 + period);
  d.output_step = p.output_step > 0 ? p.output_step : std::min(2 * M_PI / (5 * p.omega), 2 * M_PI / d.p0) / 100;
  return d;
}

double chainDriveTorque(const TwoRotorChainParams& p, double t) {
  const double w = p.omega, al = p.alpha, M1 = p.M1;  // eq. (8) times J1
  return M1 * (M_PI - 2 * al) / M_PI +
         2 * M1 / M_PI * (std::sin(w * t) + std::sin(3 * w * t) / 3 + std::sin(5 * w * t) / 5) +
         M1 / M_PI * (std::sin(al) * std::cos(w * t) - std::sin(2 * al) * std::cos(2 * w * t) / 2 +
                      std::sin(3 * al) * std::cos(3 * w * t) / 3);
}

double chainTwistCorrected(const TwoRotorChainParams& p, double t, bool with_transient) {
  const TwoRotorChainDerived d = deriveChain(p);
  double y = 0;
  steadyCorrected(p, d, t, &y, nullptr);
  double psi = d.Phi0 + y;
  if (!with_transient) return psi;
  // Homogeneous part fitted to ψ(0) = ψ̇(0) = 0 (eq. (33)).
  double y0 = 0, v0s = 0;
  steadyCorrected(p, d, 0.0, &y0, &v0s);
  const double h0 = -(d.Phi0 + y0), v0 = -v0s;
  const double dl = d.delta1, p0 = d.p0;
  if (dl < p0) {
    const double p1 = d.p1;
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

double chainTwistPrinted(const TwoRotorChainParams& p, double t, bool with_transient) {
  const TwoRotorChainDerived d = deriveChain(p);
  const Printed q = printedTerms(p, d);
  const double w = p.omega;
  const double steady = q.Psi1 * std::sin(w * t - q.xi1) - q.Psi2 * std::cos(2 * w * t + q.xi2) +
                        q.Psi3 * std::sin(3 * w * t - q.xi3) + q.Psi5 * std::sin(5 * w * t - q.xi5);  // (26)
  if (!with_transient) return d.Phi0 + steady;
  if (!std::isfinite(d.p1)) return kNaN;  // (13)-(14) assume an oscillating transient
  const double dl = d.delta1, p1 = d.p1, e = std::exp(-dl * t);
  const double Bt = (q.Psi1 * (dl * std::sin(q.xi1) - w * std::cos(q.xi1)) +
                     q.Psi2 * (dl * std::cos(q.xi2) - 2 * w * std::sin(q.xi2)) +
                     q.Psi3 * (dl * std::sin(q.xi3) - 3 * w * std::cos(q.xi3)) +
                     q.Psi5 * (dl * std::sin(q.xi5) - 5 * w * std::cos(q.xi5))) / p1;
  const double Dt = q.Psi1 * std::sin(q.xi1) + q.Psi2 * std::cos(q.xi2) + q.Psi3 * std::sin(q.xi3) +
                    q.Psi5 * std::sin(q.xi5);
  return d.Phi0 * (1 - e * (dl / p1 * std::sin(p1 * t) + std::cos(p1 * t))) + e * Bt * std::sin(p1 * t) +
         e * Dt * std::cos(p1 * t) + steady;  // (36)
}

ChainHarmonics chainHarmonics(const TwoRotorChainParams& p) {
  const TwoRotorChainDerived d = deriveChain(p);
  const Printed q = printedTerms(p, d);
  ChainHarmonics h;
  h.printed[0] = q.Psi1;
  h.printed[1] = q.Psi2;
  h.printed[2] = q.Psi3;
  h.printed[3] = q.Psi5;
  double a[4], c[4];
  forcing(p, a, c);
  for (int i = 0; i < 4; ++i) {
    const double nw = kHarm[i] * p.omega;
    const double D = std::hypot(d.p0 * d.p0 - nw * nw, 2 * d.delta1 * nw);
    h.corrected[i] = std::hypot(a[i], c[i]) / D;  // sin and cos share the phase lag: amplitudes add in quadrature
  }
  return h;
}

Table simulateTwoRotorChain(const TwoRotorChainParams& p) {
  const TwoRotorChainDerived d = deriveChain(p);
  SimTK::MultibodySystem system;
  SimTK::SimbodyMatterSubsystem matter(system);
  SimTK::GeneralForceSubsystem forces(system);
  SimTK::MobilizedBody::Pin r2(matter.Ground(), SimTK::Transform(), rotor(p.J2), SimTK::Transform());
  SimTK::MobilizedBody::Pin r1(r2, SimTK::Transform(), rotor(p.J1), SimTK::Transform());  // q = twist
  // The project's coupling element: torque k·(φ1 - φ2) + b·(φ̇1 - φ̇2), + on rotor 2, - on rotor 1.
  auto* chain = new ElasticCoupling(r1, p.k, p.b);
  SimTK::Force::Custom(forces, chain);
  SimTK::Force::Custom(forces, new ChainTorques(r1, r2, p, d.Mc));
  system.realizeTopology();
  SimTK::State s = system.getDefaultState();  // rest, ψ = 0 (eq. (33), (53))
  SimTK::RungeKuttaMersonIntegrator integ(system);
  integ.setAccuracy(p.accuracy);
  integ.initialize(s);

  Table t;
  t.columns = {"t", "psi", "psi_rate", "phi1", "phi2", "omega1", "omega2", "chain_torque", "drive_torque"};
  auto record = [&](const SimTK::State& st) {
    system.realize(st, SimTK::Stage::Velocity);
    t.rows.push_back({st.getTime(), chain->twist(st), chain->twistRate(st),
                      r2.getOneQ(st, 0) + r1.getOneQ(st, 0), r2.getOneQ(st, 0),
                      r2.getOneU(st, 0) + r1.getOneU(st, 0), r2.getOneU(st, 0), chain->torque(st), chainDriveTorque(p, st.getTime())});
  };
  record(integ.getState());
  const long n = static_cast<long>(std::ceil(d.t_end / d.output_step - 1e-9));
  for (long k = 1; k <= n; ++k) {
    const double t_out = std::min(k * d.output_step, d.t_end);
    while (integ.getTime() < t_out - 1e-12) integ.stepTo(t_out, d.t_end);
    record(integ.getState());
  }
  return t;
}

ChainComparison compareTwoRotorChain(const TwoRotorChainParams& p) {
  ChainComparison c;
  c.derived = deriveChain(p);
  c.harmonics = chainHarmonics(p);
  const Table sim = simulateTwoRotorChain(p);
  c.table.columns = {"t", "psi_sim", "psi_corrected", "psi_printed", "drive_torque", "chain_torque_sim"};
  const double t_steady = c.derived.t_end - 2 * M_PI / p.omega;
  double smin = 1e300, smax = -1e300, cmin = 1e300, cmax = -1e300, pmin = 1e300, pmax = -1e300;
  double sum = 0;
  long count = 0;
  for (const auto& row : sim.rows) {
    const double t = row[0], ps = row[1];
    const double pc = chainTwistCorrected(p, t, true), pp = chainTwistPrinted(p, t, true);
    c.table.rows.push_back({t, ps, pc, pp, row[8], row[7]});
    c.max_err_corrected_full = std::max(c.max_err_corrected_full, std::abs(ps - pc));
    c.max_err_printed_full = std::max(c.max_err_printed_full, std::abs(ps - pp));
    if (t >= t_steady - 1e-12) {
      const double sc = chainTwistCorrected(p, t, false), sp = chainTwistPrinted(p, t, false);
      c.max_err_corrected_steady = std::max(c.max_err_corrected_steady, std::abs(ps - sc));
      c.max_err_printed_steady = std::max(c.max_err_printed_steady, std::abs(ps - sp));
      smin = std::min(smin, ps); smax = std::max(smax, ps);
      cmin = std::min(cmin, sc); cmax = std::max(cmax, sc);
      pmin = std::min(pmin, sp); pmax = std::max(pmax, sp);
      if (t > t_steady + 1e-9) {  // one whole period on a uniform grid: exact mean of the harmonics
        sum += ps;
        ++count;
      }
    }
  }
  c.swing_sim = smax - smin;
  c.swing_corrected = cmax - cmin;
  c.swing_printed = pmax - pmin;
  c.mean_sim = count ? sum / count : kNaN;
  c.mean_closed = c.derived.Phi0;
  for (const ResonanceHit& h : resonanceHits(c.derived.p0, p.omega)) {
    c.resonance_warnings.push_back("p0 = " + std::to_string(c.derived.p0) + " rad/s is within 10 % of " +
                                   std::to_string(h.harmonic) + "*omega = " +
                                   std::to_string(h.harmonic * p.omega) + " rad/s (Dyomin (two rotors) eq. (10), (16)-(21))");
  }
  return c;
}

}  // namespace rollerdyn
