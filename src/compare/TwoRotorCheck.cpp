#include "compare/TwoRotorCheck.h"

#include <cmath>
#include <memory>
#include <stdexcept>

#include "Simbody.h"
#include "multibody/ElasticCoupling.h"

namespace rollerdyn::validation {
namespace {

// The drive torque M(t) of eq. (8) on rotor 1.
class SeriesDriveTorque : public SimTK::Force::Custom::Implementation {
 public:
  SeriesDriveTorque(const SimTK::MobilizedBody& rotor, const TwoRotorParameters& p) : rotor_(rotor), p_(p) {}
  // A body torque: rotor 1 is mobilized on rotor 2, so a mobility force would also act on rotor 2.
  void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>& body_forces,
                 SimTK::Vector_<SimTK::Vec3>&, SimTK::Vector&) const override {
    rotor_.applyBodyTorque(s, SimTK::Vec3(0, 0, driveTorque(p_, s.getTime())), body_forces);
  }
  SimTK::Real calcPotentialEnergy(const SimTK::State&) const override { return 0; }

 private:
  SimTK::MobilizedBody rotor_;
  TwoRotorParameters p_;
};

// A rotor of polar inertia J on a Pin about z (a disc keeps the inertia valid; the token mass
// on the axis changes nothing on a fixed axis, as in MultibodyModel.cpp).
SimTK::Body::Rigid rotorBody(double J) {
  return SimTK::Body::Rigid(SimTK::MassProperties(1e-3, SimTK::Vec3(0), SimTK::Inertia(0.5 * J, 0.5 * J, J)));
}

struct TwoRotorSystem {
  SimTK::MultibodySystem system;
  SimTK::SimbodyMatterSubsystem matter{system};
  SimTK::GeneralForceSubsystem forces{system};
  // Rotor 2 plays the crankshaft, rotor 1 the motor side mobilized on it as in MultibodyModel:
  // rotor 1's coordinate is the twist.
  SimTK::MobilizedBody::Pin rotor2, rotor1;

  TwoRotorSystem(const TwoRotorParameters& p, bool drive)
      : rotor2(matter.Ground(), SimTK::Transform(), rotorBody(p.J2), SimTK::Transform()),
        rotor1(rotor2, SimTK::Transform(), rotorBody(p.J1), SimTK::Transform()) {
    SimTK::Force::Custom(forces, new ElasticCoupling(rotor1, p.k, p.b));
    if (drive) {
      SimTK::Force::Custom(forces, new SeriesDriveTorque(rotor1, p));
      if (p.Mc != 0.0) SimTK::Force::MobilityConstantForce(forces, rotor2, 0, -p.Mc);
    }
    system.realizeTopology();
  }
  double twist(const SimTK::State& s) const { return rotor1.getOneQ(s, 0); }
  double twistRate(const SimTK::State& s) const { return rotor1.getOneU(s, 0); }
  double twistAccel(const SimTK::State& s) const { return rotor1.getOneUDot(s, 0); }
};

// stepTo() may return before the requested time (e.g. at the start of the first continuous
// interval): advance until the integrator's own time is there.
void advanceTo(SimTK::Integrator& integ, double t) {
  while (integ.getTime() < t - 1e-14 * std::max(1.0, std::abs(t))) integ.stepTo(t);
}

std::unique_ptr<SimTK::Integrator> makeExactIntegrator(const SimTK::System& system, double accuracy) {
  auto integ = std::make_unique<SimTK::RungeKuttaMersonIntegrator>(system);
  integ->setAccuracy(accuracy);
  // Land on every sample time by shortening the step, never by interpolating: interpolated
  // states are less accurate than the integrator's own steps.
  integ->setAllowInterpolation(false);
  integ->setInternalStepLimit(1000000);
  return integ;
}

// Cubic Hermite interpolant on [t0, t1] through (y0, d0), (y1, d1), evaluated at s in [0, 1].
double hermite(double s, double h, double y0, double d0, double y1, double d1) {
  const double s2 = s * s, s3 = s2 * s;
  return (2 * s3 - 3 * s2 + 1) * y0 + (s3 - 2 * s2 + s) * h * d0 + (-2 * s3 + 3 * s2) * y1 +
         (s3 - s2) * h * d1;
}

// Root in [0, 1] of the Hermite interpolant, whose end values have opposite signs (bisection).
double hermiteRoot(double h, double y0, double d0, double y1, double d1) {
  double lo = 0, hi = 1;
  const double s_lo = y0;
  for (int it = 0; it < 80; ++it) {
    const double mid = 0.5 * (lo + hi);
    const double v = hermite(mid, h, y0, d0, y1, d1);
    if ((v < 0) == (s_lo < 0)) lo = mid; else hi = mid;
  }
  return 0.5 * (lo + hi);
}

// An integrator started from the system's default state, rotor 1 twisted by `initial_twist`.
std::unique_ptr<SimTK::Integrator> startedIntegrator(TwoRotorSystem& sys, double accuracy, double initial_twist) {
  SimTK::State s = sys.system.getDefaultState();
  sys.system.realizeModel(s);
  if (initial_twist != 0.0) sys.rotor1.setOneQ(s, 0, initial_twist);
  auto integ = makeExactIntegrator(sys.system, accuracy);
  integ->initialize(s);
  return integ;
}

// The twist and its derivatives sampled every h from t = 0 to N·h (the integrator's own steps).
struct TwistSamples {
  std::vector<double> t, y, dy, ddy;
};
TwistSamples sampleTwist(const TwoRotorSystem& sys, SimTK::Integrator& integ, double h, int N) {
  TwistSamples out;
  for (int i = 0; i <= N; ++i) {
    if (i > 0) advanceTo(integ, i * h);
    const SimTK::State& st = integ.getState();
    sys.system.realize(st, SimTK::Stage::Acceleration);
    out.t.push_back(st.getTime());
    out.y.push_back(sys.twist(st));
    out.dy.push_back(sys.twistRate(st));
    out.ddy.push_back(sys.twistAccel(st));
  }
  return out;
}

// Upward zero crossings of ψ and maxima of ψ (ψ̇ from + to -), located between samples by
// cubic Hermite interpolation.
struct TwistEvents {
  std::vector<double> up;              // upward zero crossings of ψ
  std::vector<double> peak_t, peak_y;  // maxima of ψ
};
TwistEvents locateTwistEvents(const TwistSamples& x) {
  TwistEvents e;
  const auto &t = x.t, &y = x.y, &dy = x.dy, &ddy = x.ddy;
  for (std::size_t i = 0; i + 1 < t.size(); ++i) {
    const double hh = t[i + 1] - t[i];
    if (y[i] < 0 && y[i + 1] >= 0) e.up.push_back(t[i] + hh * hermiteRoot(hh, y[i], dy[i], y[i + 1], dy[i + 1]));
    if (dy[i] > 0 && dy[i + 1] <= 0) {
      const double sroot = hermiteRoot(hh, dy[i], ddy[i], dy[i + 1], ddy[i + 1]);
      e.peak_t.push_back(t[i] + hh * sroot);
      e.peak_y.push_back(hermite(sroot, hh, y[i], dy[i], y[i + 1], dy[i + 1]));
    }
  }
  return e;
}

// Harmonic n of the steady twist from the sums Σψ·sin(nωt) and Σψ·cos(nωt) over N samples.
HarmonicResponse harmonicFromSums(int n, double sum_sin, double sum_cos, int N) {
  HarmonicResponse h;
  h.n = n;
  h.a_sin = 2.0 * sum_sin / N;
  h.b_cos = 2.0 * sum_cos / N;
  h.amplitude = std::hypot(h.a_sin, h.b_cos);
  h.phase_lag = std::atan2(-h.b_cos, h.a_sin);  // of the combined response, for information
  return h;
}

// The mean twist and harmonics 1, 2, 3, 5 of the sampled steady twist (whole periods of ω).
void steadyHarmonics(ForcedResponseMeasurement& m, double omega) {
  const int N = int(m.t.size());
  const int ns[] = {1, 2, 3, 5};
  double sum0 = 0, sa[4] = {0, 0, 0, 0}, sb[4] = {0, 0, 0, 0};
  for (int i = 0; i < N; ++i) {
    const double t = m.t[i], psi = m.twist[i];
    sum0 += psi;
    for (int k = 0; k < 4; ++k) {
      sa[k] += psi * std::sin(ns[k] * omega * t);
      sb[k] += psi * std::cos(ns[k] * omega * t);
    }
  }
  m.mean_twist = sum0 / N;
  for (int k = 0; k < 4; ++k) m.harmonics.push_back(harmonicFromSums(ns[k], sa[k], sb[k], N));
}

// Frequency from the first and last of up to `periods` whole periods of upward crossings; decay
// rate from the maxima that many periods apart.
void frequencyAndDecay(const TwistEvents& e, int periods, FreeOscillationMeasurement& m) {
  const std::vector<double> &up = e.up, &peak_t = e.peak_t, &peak_y = e.peak_y;
  const int mc = std::min<int>(periods, int(up.size()) - 1);
  if (mc < 1) throw std::runtime_error("two-rotor check: fewer than two upward zero crossings");
  m.periods = mc;
  m.frequency = 2.0 * M_PI * mc / (up[mc] - up[0]);
  const int mp = std::min<int>(periods, int(peak_t.size()) - 1);
  m.decay_periods = mp;
  m.decay_rate = mp >= 1 && peak_y[mp] > 0 ? std::log(peak_y[0] / peak_y[mp]) / (peak_t[mp] - peak_t[0]) : 0.0;
  m.natural_frequency = std::sqrt(m.frequency * m.frequency + m.decay_rate * m.decay_rate);
}

}  // namespace

TwoRotorParameters loveikin2018Drive() {
  TwoRotorParameters p;
  p.J1 = 0.766 * 9.8 * 9.8;
  p.J2 = 100.0;
  p.k = 2.0e5;
  p.b = 2000.0;
  p.M1 = 1000.0;
  p.alpha = M_PI / 6.0;
  p.Mc = balancedResistingTorque(p);
  p.omega = 10.68;
  return p;
}

ForcedResponseMeasurement measureForcedResponse(const TwoRotorParameters& p, double settle_time,
                                                int periods, int samples_per_period, double accuracy) {
  if (!(p.omega > 0) || periods < 1 || samples_per_period < 12)
    throw std::invalid_argument("two-rotor check: need omega > 0, periods >= 1, >= 12 samples per period");
  TwoRotorSystem sys(p, true);
  auto integ = startedIntegrator(sys, accuracy, 0.0);
  ForcedResponseMeasurement m;
  m.settle_time = settle_time;
  m.periods = periods;
  m.samples_per_period = samples_per_period;
  const double T = 2.0 * M_PI / p.omega;
  const int N = periods * samples_per_period;
  for (int i = 0; i < N; ++i) {
    const double t = settle_time + i * T / samples_per_period;
    advanceTo(*integ, t);
    m.t.push_back(t);
    m.twist.push_back(sys.twist(integ->getState()));
  }
  steadyHarmonics(m, p.omega);
  return m;
}

FreeOscillationMeasurement measureFreeOscillation(const TwoRotorParameters& p, double initial_twist,
                                                  int periods, int samples_per_period, double accuracy) {
  if (periods < 2 || samples_per_period < 12 || initial_twist == 0.0)
    throw std::invalid_argument("two-rotor check: need >= 2 periods, >= 12 samples per period, a twist");
  TwoRotorSystem sys(p, false);
  auto integ = startedIntegrator(sys, accuracy, initial_twist);
  FreeOscillationMeasurement m;
  m.initial_twist = initial_twist;
  // Sample spacing from the expected period only sets the resolution; the measurement itself
  // uses the crossings found in the samples.
  const double h = 2.0 * M_PI / dampedFrequency(p) / samples_per_period;
  const int N = (periods + 2) * samples_per_period;
  TwistSamples x = sampleTwist(sys, *integ, h, N);
  const TwistEvents e = locateTwistEvents(x);
  m.t = std::move(x.t);
  m.twist = std::move(x.y);
  frequencyAndDecay(e, periods, m);
  return m;
}

}  // namespace rollerdyn::validation
