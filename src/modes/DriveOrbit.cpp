#include "modes/DriveOrbit.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "modes/PeriodicFlow.h"
#include "motor/MotorLawFactory.h"
#include "reduced/ReducedModel.h"
#include "scene/MotorModels.h"

namespace rollerdyn::modes {

const char* toString(ModeKind k) { return k == ModeKind::Torsional ? "torsional (coupling)" : "speed (whole drive)"; }

namespace {

// The load torque at the crank averaged over a revolution (720 angles) at crank speed w.
double meanLoadTorque(const ReducedModel& model, double w) {
  const int n = 720;
  double mean = 0;
  for (int i = 0; i < n; ++i) mean += model.loadTorque(2 * M_PI * i / n, w);
  return mean / n;
}

// The crank speed between breakdown (w_kr) and synchronous (w_sync) where the motor's static
// torque at the crank equals `load`: it falls from breakdown to 0 there, so bisect.
double speedCarrying(const ReducedModel& model, double load, double w_kr, double w_sync) {
  if (load <= 0) return w_sync;  // no net load (or driving loads): synchronous speed
  double lo = w_kr, hi = w_sync;
  for (int it = 0; it < 100; ++it) {
    const double mid = 0.5 * (lo + hi);
    (model.motorTorque(mid) > load ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

SteadyGuess steadyGuess(const ReducedModel& model) {
  const Scene& scene = model.scene();
  SteadyGuess g;
  if (!scene.motor.enabled) {
    g.failure = "no motor (motor.enabled is false): the drive has no steady running to linearize about";
    return g;
  }
  const double u = scene.reducer.ratio;
  const double w_sync = scene.motor.omega_sync / u;                            // crank axis
  const double w_kr = scene.motor.omega_sync * (1 - scene.motor.critical_slip) / u;  // breakdown
  const double mean = meanLoadTorque(model, 0.98 * w_sync);
  g.mean_load_torque = mean;
  if (mean > model.motorTorque(w_kr)) {
    g.failure = "the mean load torque exceeds the motor's breakdown torque at the crank: the drive stalls";
    return g;
  }
  g.omega = speedCarrying(model, mean, w_kr, w_sync);
  if (scene.coupling.type == CouplingType::Elastic) g.twist = mean / scene.coupling.stiffness;
  g.ok = true;
  return g;
}

namespace {

// The equivalent-circuit laws (circuit, Park) are built from the machine's supply, not from
// omega_sync: the converter's frequency and voltage scale with the speed (U/f constant, no
// boost), the circuit fixed (taken from the catalogue fit where the scene gives none, so the fit
// is not redone at the new frequency). Left alone, every speed of a Campbell diagram ran at the
// operating speed. w0, w0_new: the synchronous speed before and after [rad/s].
void convertMachineSupply(const Scene& scene, double w0, double w0_new, Scene& s) {
  const InductionMachineParameters m = sceneMachine(scene);
  s.induction.circuit.R_s = m.R_s;
  s.induction.circuit.L_sigma_s = m.L_sigma_s;
  s.induction.circuit.L_m = m.L_m;
  s.induction.circuit.R_r = m.R_r[0];
  s.induction.circuit.L_sigma_r = m.L_sigma_r[0];
  s.induction.circuit.R_r2 = m.cages > 1 ? m.R_r[1] : 0.0;
  s.induction.circuit.L_sigma_r2 = m.cages > 1 ? m.L_sigma_r[1] : 0.0;
  s.induction.frequency = scene.induction.frequency * w0_new / w0;
  s.induction.voltage = scene.induction.voltage * w0_new / w0;
}

}  // namespace

Scene sceneAtCrankSpeed(const Scene& scene, double omega_target, double omega_now) {
  Scene s = scene;
  const double w0 = scene.motor.omega_sync;
  const double w0_new = w0 + scene.reducer.ratio * (omega_target - omega_now);
  if (!(w0_new > 0)) throw std::invalid_argument("crank speed " + std::to_string(omega_target) + " rad/s is out of reach");
  s.motor.omega_sync = w0_new;
  s.motor.critical_slip = scene.motor.critical_slip * w0 / w0_new;
  if (scene.motor.enabled && isMachineLaw(scene.induction.model)) convertMachineSupply(scene, w0, w0_new, s);
  return s;
}

namespace {

bool oscillates(const FloquetMultiplier& f) { return std::abs(f.mu.imag()) > 1e-12 * f.modulus; }

// Speed mode: motor and crank side move together (the twist rate is a small part of the speed
// change). Torsional: they move against each other, |δψ̇| > |δφ̇2|.
ModeKind kindByShape(const FloquetMultiplier& f, bool elastic) {
  return (elastic && f.vector.size() == 3 && std::abs(f.vector(2)) > std::abs(f.vector(0))) ? ModeKind::Torsional
                                                                                         : ModeKind::Speed;
}

// The most unstable multiplier's verdict: its modulus, margin and decay rate, and the words.
void setWorst(FloquetVerdict& v, const ClassifiedMultiplier& worst) {
  v.max_modulus = worst.m.modulus;
  v.margin = 1 - v.max_modulus;
  v.slowest_decay_rate = -worst.m.growth_rate;
  v.stable = v.max_modulus < 1;
  if (v.stable)
    v.text = "stable";
  else if (worst.kind == ModeKind::Torsional)
    v.text = "parametrically unstable";
  else
    v.text = "unstable speed mode";
}

// The torsional mode's numbers from its largest multiplier. A multiplier below kResolvedModulus
// is only known to be small: the monodromy's entries carry the integration's absolute error
// (~1e-8), so its angle, and the frequency and damping ratio read from it, are noise.
void setTorsional(FloquetVerdict& v, const std::vector<ClassifiedMultiplier>& m) {
  for (const auto& c : m)
    if (c.kind == ModeKind::Torsional && (!v.has_torsional || c.m.modulus > v.torsional_modulus)) {
      v.has_torsional = true;
      v.torsional_modulus = c.m.modulus;
      v.torsional_frequency = c.m.frequency;
      v.torsional_damping_ratio = c.m.damping_ratio;
    }
  if (v.has_torsional && v.torsional_modulus < kResolvedModulus) {
    v.torsional_resolved = false;
    v.torsional_frequency = v.torsional_damping_ratio = NAN;
  }
}

}  // namespace

std::vector<ClassifiedMultiplier> classifyMultipliers(const std::vector<FloquetMultiplier>& m, bool elastic) {
  std::vector<ClassifiedMultiplier> out;
  // A complex-conjugate pair among the three multipliers is an oscillation, and the drive has one:
  // the coupling's; the remaining real multiplier is the non-oscillating motion. Heavy damping
  // makes the eigenvector test below fail: six carts at k = 8000 N·m·s/rad oscillate (ζ = 0.82,
  // |μ| = 3.7e-6) with the motor side held back by the damping, so the twist rate is smaller than
  // the crank speed's change, and the real multiplier (the motor side settling on the damping,
  // |μ| ~ 1e-21) was taken for the coupling mode.
  const bool one_pair = elastic && m.size() == 3 && std::count_if(m.begin(), m.end(), oscillates) == 2;
  for (const FloquetMultiplier& f : m) {
    ClassifiedMultiplier c;
    c.m = f;
    if (one_pair)
      c.kind = oscillates(f) ? ModeKind::Torsional : ModeKind::Speed;
    else
      c.kind = kindByShape(f, elastic);
    out.push_back(c);
  }
  return out;
}

FloquetVerdict judge(const std::vector<ClassifiedMultiplier>& m) {
  FloquetVerdict v;
  if (m.empty()) return v;
  const ClassifiedMultiplier* worst = &m.front();
  for (const auto& c : m)
    if (c.m.modulus > worst->m.modulus) worst = &c;
  setWorst(v, *worst);
  setTorsional(v, m);
  return v;
}

namespace {

// The drive's state at crank angle phi from the orbit's state x (speed, and twist and its rate
// when the coupling is elastic).
DrivePoint drivePointAt(double phi, const Eigen::VectorXd& x, bool elastic) {
  DrivePoint p;
  p.phi = phi;
  p.omega = x(0);
  if (elastic) {
    p.twist = x(1);
    p.twist_rate = x(2);
  }
  return p;
}

// dx/dφ2 of the drive at crank angle phi: each rate over the crank speed, dt/dφ2 = 1/ω2 last;
// NaN where the crank stalls or reverses (φ2 is no clock any more).
void ratesOverCrankAngle(DriveModel& drive, double phi, const Eigen::VectorXd& x, bool elastic, bool quasi_static,
                         Eigen::VectorXd& f) {
  const DrivePoint p = drivePointAt(phi, x, elastic);
  f.resize(x.size());
  if (!(p.omega > 0)) {
    f.setConstant(NAN);
    return;
  }
  if (quasi_static) drive.setOperatingPoint(p);
  const Eigen::Vector2d a = drive.accelerations(p);
  f(0) = a(0) / p.omega;
  if (elastic) {
    f(1) = p.twist_rate / p.omega;
    f(2) = a(1) / p.omega;
  }
  f(x.size() - 1) = 1.0 / p.omega;
}

// The drive over one crank revolution with the crank angle φ2 as the clock: x = [ω2] (rigid) or
// [ω2, ψ, ψ'] (elastic), scaled by the crank speed and the twist of the breakdown torque, and the
// time t as the quadrature.
PeriodicSystem revolutionSystem(DriveModel& drive, double phi0, bool elastic, bool quasi_static, double omega_scale,
                                double twist_scale) {
  PeriodicSystem sys;
  sys.n = elastic ? 3 : 1;
  sys.quadratures = 1;
  sys.period = 2 * M_PI;
  if (elastic)
    sys.scale = Eigen::VectorXd(Eigen::Vector3d(omega_scale, twist_scale, twist_scale * omega_scale));
  else
    sys.scale = Eigen::VectorXd::Constant(1, omega_scale);
  sys.rhs = [&drive, phi0, elastic, quasi_static](double s, const Eigen::VectorXd& x, Eigen::VectorXd& f) {
    ratesOverCrankAngle(drive, phi0 + s, x, elastic, quasi_static, f);
  };
  return sys;
}

// Tolerances of the orbit search from the steady motion's options.
OrbitOptions orbitOptions(const SteadyMotionOptions& o) {
  OrbitOptions oo;
  oo.flow.rtol = o.rtol;
  oo.flow.atol_scale = o.rtol;
  oo.flow.samples = o.samples;
  oo.warmup_periods = o.warmup_periods;
  oo.max_newton = o.max_newton;
  oo.tolerance = 10 * o.rtol;
  oo.accept_stagnation = 1e-5;
  return oo;
}

}  // namespace

namespace {

// Newton's start: the options' own, else the steady guess (a failure when there is none).
std::string searchStart(DriveModel& drive, const SteadyMotionOptions& o, bool elastic, Eigen::VectorXd& start) {
  start = o.start;
  if (start.size() != 0) return "";
  const SteadyGuess g = steadyGuess(drive.reducedModel());
  if (!g.ok) return g.failure;
  if (elastic)
    start = Eigen::VectorXd(Eigen::Vector3d(g.omega, g.twist, 0.0));
  else
    start = Eigen::VectorXd::Constant(1, g.omega);
  return "";
}

// The steady motion from the periodic orbit found: start, monodromy, period and the samples.
void takeOrbit(SteadyMotion& r, const PeriodicOrbit& orbit) {
  r.found = true;
  r.x0 = orbit.x0;
  r.monodromy = orbit.monodromy;
  r.newton_iterations = orbit.newton_iterations;
  r.period = orbit.quadratures(0);
  r.omega_mean = 2 * M_PI / r.period;
  for (size_t k = 0; k < orbit.s_samples.size(); ++k) {
    const Eigen::VectorXd& x = orbit.x_samples[k];
    r.samples.push_back(drivePointAt(r.phi0 + orbit.s_samples[k], x, r.elastic));
    r.sample_time.push_back(x(x.size() - 1));
  }
}

}  // namespace

SteadyMotion steadyMotion(DriveModel& drive, const Scene& scene, const SteadyMotionOptions& o) {
  SteadyMotion r;
  r.elastic = drive.elastic();
  r.phi0 = scene.initial.crank_angle;
  Eigen::VectorXd start;
  r.failure = searchStart(drive, o, r.elastic, start);
  if (!r.failure.empty()) return r;
  const double omega_scale = scene.motor.omega_sync / scene.reducer.ratio;
  const double twist_scale = r.elastic ? breakdownTwist(scene) : 1e-6;
  const PeriodicSystem sys =
      revolutionSystem(drive, r.phi0, r.elastic, o.quasi_static_auxiliary, omega_scale, twist_scale);
  const PeriodicOrbit orbit = findPeriodicOrbit(sys, start, orbitOptions(o));
  r.evaluations = orbit.evaluations;
  if (!orbit.found) {
    r.failure = orbit.failure;
    return r;
  }
  takeOrbit(r, orbit);
  rebranch(r, o.reference_frequency);
  return r;
}

void rebranch(SteadyMotion& r, double reference_frequency) {
  if (!r.found) return;
  r.multipliers = classifyMultipliers(floquetMultipliers(r.monodromy, r.period, reference_frequency), r.elastic);
  for (ClassifiedMultiplier& c : r.multipliers)
    if (c.kind == ModeKind::Speed) {  // its frequency (if any) is the principal branch, not the torsional one
      c.m.frequency = std::abs(std::arg(c.m.mu)) / r.period;
      const double wn = std::hypot(c.m.growth_rate, c.m.frequency);
      c.m.damping_ratio = wn > 0 ? -c.m.growth_rate / wn : NAN;
    }
  r.verdict = judge(r.multipliers);
}

}  // namespace rollerdyn::modes
