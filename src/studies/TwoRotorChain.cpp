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

}  // namespace

// The study's parameters as the closed form's (physics/TwoRotorClosedForm.h), with the
// resisting torque resolved (Mc < 0: the mean drive torque).
TwoRotorParameters closedFormParameters(const TwoRotorChainParams& p) {
  TwoRotorParameters q{p.J1, p.J2, p.k, p.b, p.M1, p.alpha, 0.0, p.omega};
  q.Mc = p.Mc >= 0 ? p.Mc : balancedResistingTorque(q);
  return q;
}

namespace {

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

// The two rotors as a Simbody system: rotor 2 turns on ground, rotor 1 on rotor 2 (its coordinate
// is the twist ψ), joined by the project's coupling element and driven by ChainTorques.
struct ChainSystem {
  ChainSystem(const TwoRotorChainParams& p, double Mc)
      : r2(matter.Ground(), SimTK::Transform(), rotor(p.J2), SimTK::Transform()),
        r1(r2, SimTK::Transform(), rotor(p.J1), SimTK::Transform()),  // q = twist
        // Torque k·(φ1 - φ2) + b·(φ̇1 - φ̇2), + on rotor 2, - on rotor 1.
        coupling(new ElasticCoupling(r1, p.k, p.b)) {
    SimTK::Force::Custom(forces, coupling);
    SimTK::Force::Custom(forces, new ChainTorques(r1, r2, p, Mc));
    system.realizeTopology();
  }
  // The table's row at state st: t [s]; ψ, ψ̇; φ1, φ2; ω1, ω2 [rad, rad/s]; the coupling's and the
  // drive's torque [N·m].
  std::vector<double> row(const SimTK::State& st, const TwoRotorChainParams& p) const {
    system.realize(st, SimTK::Stage::Velocity);
    return {st.getTime(), coupling->twist(st), coupling->twistRate(st),
            r2.getOneQ(st, 0) + r1.getOneQ(st, 0), r2.getOneQ(st, 0),
            r2.getOneU(st, 0) + r1.getOneU(st, 0), r2.getOneU(st, 0),
            coupling->torque(st), chainDriveTorque(p, st.getTime())};
  }

  SimTK::MultibodySystem system;
  SimTK::SimbodyMatterSubsystem matter{system};
  SimTK::GeneralForceSubsystem forces{system};
  SimTK::MobilizedBody::Pin r2, r1;
  ElasticCoupling* coupling;  // owned by forces
};

}  // namespace

TwoRotorChainDerived deriveChain(const TwoRotorChainParams& p) {
  if (!(p.J1 > 0) || !(p.J2 > 0) || !(p.k > 0) || !(p.b >= 0) || !(p.omega > 0) || !std::isfinite(p.M1) ||
      !std::isfinite(p.alpha))
    throw std::invalid_argument("chain: need J1, J2, k, omega > 0, b >= 0 and finite M1, alpha");
  const TwoRotorParameters q = closedFormParameters(p);
  TwoRotorChainDerived d;
  d.delta1 = dampingRate(q);     // (9)
  d.p0 = naturalFrequency(q);    // (10)
  d.p1 = dampedFrequency(q);     // (14)
  d.Mc = q.Mc;
  d.Phi0 = meanTwist(q);         // (11), (43)
  // Slowest decay rate of the transient: δ1 when underdamped, else the slow real root.
  const double decay = d.delta1 < d.p0 ? d.delta1 : d.delta1 - std::sqrt(d.delta1 * d.delta1 - d.p0 * d.p0);
  const double period = 2 * M_PI / p.omega;
  d.t_end = p.t_end > 0 ? p.t_end
                        : std::min(std::max(std::log(1e9) / std::max(decay, 1e-12), 10 * period), 400.0 + period);
  d.output_step = p.output_step > 0 ? p.output_step : std::min(2 * M_PI / (5 * p.omega), 2 * M_PI / d.p0) / 100;
  return d;
}

double chainDriveTorque(const TwoRotorChainParams& p, double t) { return driveTorque(closedFormParameters(p), t); }

double chainTwistCorrected(const TwoRotorChainParams& p, double t, bool with_transient) {
  deriveChain(p);  // validates p
  return twistExact(closedFormParameters(p), t, with_transient);
}

double chainTwistPrinted(const TwoRotorChainParams& p, double t, bool with_transient) {
  deriveChain(p);
  return twistPrinted(closedFormParameters(p), t, with_transient);
}

ChainHarmonics chainHarmonics(const TwoRotorChainParams& p) {
  deriveChain(p);
  const std::vector<HarmonicResponse> h = closedFormResponse(closedFormParameters(p));
  ChainHarmonics c;
  for (int i = 0; i < 4; ++i) {
    c.printed[i] = h[i].amplitude_printed;
    c.corrected[i] = h[i].amplitude;
  }
  return c;
}

Table simulateTwoRotorChain(const TwoRotorChainParams& p) {
  const TwoRotorChainDerived d = deriveChain(p);
  const ChainSystem chain(p, d.Mc);
  SimTK::State s = chain.system.getDefaultState();  // rest, ψ = 0 (eq. (33), (53))
  SimTK::RungeKuttaMersonIntegrator integ(chain.system);
  integ.setAccuracy(p.accuracy);
  integ.initialize(s);

  Table t;
  t.columns = {"t", "psi", "psi_rate", "phi1", "phi2", "omega1", "omega2", "chain_torque", "drive_torque"};
  t.rows.push_back(chain.row(integ.getState(), p));
  const long n = static_cast<long>(std::ceil(d.t_end / d.output_step - 1e-9));
  for (long k = 1; k <= n; ++k) {
    const double t_out = std::min(k * d.output_step, d.t_end);
    while (integ.getTime() < t_out - 1e-12) integ.stepTo(t_out, d.t_end);
    t.rows.push_back(chain.row(integ.getState(), p));
  }
  return t;
}

namespace {

// The smallest and largest value of a sequence.
struct Span {
  double lo = 1e300, hi = -1e300;
  void add(double v) {
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  double swing() const { return hi - lo; }
};

// The last period of the run (the steady state): swings of the simulated, corrected and printed
// twist, and the sum of the simulated twist over one whole period for its mean.
struct SteadyPeriod {
  explicit SteadyPeriod(double begin) : t_begin(begin) {}
  double t_begin;
  Span sim, corrected, printed;
  double sum = 0;
  long count = 0;

  // A row of the last period: the steady errors of the closed forms and the swings.
  void add(const TwoRotorChainParams& p, double t, double ps, ChainComparison& c) {
    const double sc = chainTwistCorrected(p, t, false), sp = chainTwistPrinted(p, t, false);
    c.max_err_corrected_steady = std::max(c.max_err_corrected_steady, std::abs(ps - sc));
    c.max_err_printed_steady = std::max(c.max_err_printed_steady, std::abs(ps - sp));
    sim.add(ps);
    corrected.add(sc);
    printed.add(sp);
    if (t > t_begin + 1e-9) {  // one whole period on a uniform grid: exact mean of the harmonics
      sum += ps;
      ++count;
    }
  }
};

std::vector<std::string> chainResonanceWarnings(double p0, double omega) {
  std::vector<std::string> warnings;
  for (const ResonanceHit& h : resonanceHits(p0, omega))
    warnings.push_back("p0 = " + std::to_string(p0) + " rad/s is within 10 % of " + std::to_string(h.harmonic) +
                       "*omega = " + std::to_string(h.harmonic * omega) +
                       " rad/s (Dyomin (two rotors) eq. (10), (16)-(21))");
  return warnings;
}

}  // namespace

ChainComparison compareTwoRotorChain(const TwoRotorChainParams& p) {
  ChainComparison c;
  c.derived = deriveChain(p);
  c.harmonics = chainHarmonics(p);
  const Table sim = simulateTwoRotorChain(p);
  c.table.columns = {"t", "psi_sim", "psi_corrected", "psi_printed", "drive_torque", "chain_torque_sim"};
  SteadyPeriod last{c.derived.t_end - 2 * M_PI / p.omega};
  for (const auto& row : sim.rows) {
    const double t = row[0], ps = row[1];
    const double pc = chainTwistCorrected(p, t, true), pp = chainTwistPrinted(p, t, true);
    c.table.rows.push_back({t, ps, pc, pp, row[8], row[7]});
    c.max_err_corrected_full = std::max(c.max_err_corrected_full, std::abs(ps - pc));
    c.max_err_printed_full = std::max(c.max_err_printed_full, std::abs(ps - pp));
    if (t >= last.t_begin - 1e-12) last.add(p, t, ps, c);
  }
  c.swing_sim = last.sim.swing();
  c.swing_corrected = last.corrected.swing();
  c.swing_printed = last.printed.swing();
  c.mean_sim = last.count ? last.sum / last.count : kNaN;
  c.mean_closed = c.derived.Phi0;
  c.resonance_warnings = chainResonanceWarnings(c.derived.p0, p.omega);
  return c;
}

}  // namespace rollerdyn
