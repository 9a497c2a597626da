#include "modes/ModalAnalysis.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <sstream>

#include "reduced/ReducedModel.h"
#include "io/FieldFormat.h"

namespace rollerdyn::modes {
namespace {

// The frozen modes' values over the angles, one list per band of ModelFrozenModes.
struct FrozenLists {
  std::vector<double> p, z, pd, pn, osc, on, oz, em, es, ec;

  // One mode at one angle: the torsional mode's frequencies, damping and energy shares, the other
  // mode's where it oscillates; the names as the modes give them.
  void add(const FrozenMode& mode, ModelFrozenModes& m) {
    if (mode.torsional) {
      p.push_back(mode.frequency);
      z.push_back(mode.damping_ratio);
      pd.push_back(mode.damped_frequency);
      pn.push_back(mode.natural_frequency);
      if (std::isfinite(mode.frequency) && !mode.oscillates) ++m.torsional_overdamped_angles;
      em.push_back(mode.energy_motor_side);
      es.push_back(mode.energy_shaft_rods);
      ec.push_back(mode.energy_carts);
      m.torsional_name = mode.name;
    } else {
      m.rigid_name = mode.name;
      if (mode.oscillates) {
        on.push_back(mode.natural_frequency);
        oz.push_back(mode.damping_ratio);
      }
    }
  }

  void setBands(ModelFrozenModes& m) const {
    m.torsional = bandOf(p);
    m.torsional_damping = bandOf(z);
    m.torsional_damped = bandOf(pd);
    m.torsional_natural = bandOf(pn);
    m.oscillation_damped = bandOf(osc);
    m.other_natural = bandOf(on);
    m.other_damping = bandOf(oz);
    m.other_oscillating_angles = int(on.size());
    m.energy_motor_side = bandOf(em).mean;
    m.energy_shaft_rods = bandOf(es).mean;
    m.energy_carts = bandOf(ec).mean;
  }
};

ModelFrozenModes frozenAlong(DriveModel& drive, const Scene& scene, const std::vector<DrivePoint>& points) {
  ModelFrozenModes m;
  m.model = drive.name();
  if (points.empty()) {
    m.failure = "no steady motion and no running speed to linearize about";
    return m;
  }
  FrozenLists lists;
  for (const DrivePoint& q : points) {
    FrozenAngle f = frozenModes(drive, scene, q);
    for (const FrozenMode& mode : f.modes) lists.add(mode, m);
    lists.osc.push_back(f.oscillation_frequency());
    m.angles.push_back(std::move(f));
  }
  lists.setBands(m);
  m.ok = true;
  return m;
}

// The scene the linear analysis describes, and the approximations it makes. Linear modes know no
// gap: with backlash they are those of the teeth always in contact.
Scene linearizedScene(const Scene& given, ModesReport& r) {
  Scene scene = given;
  if (given.hasBacklash()) {
    scene.reducer.backlash = 0.0;
    char b[512];
    std::snprintf(b, sizeof b,
                  "the modes, Floquet multipliers and stability charts are those of the drive with the reducer's teeth "
                  "always in contact (backlash %.4g rad taken as 0, contact stiffness c = %.4g N*m/rad); where the "
                  "teeth separate in the run (summary.json backlash: teeth separate) the drive leaves this linear "
                  "model at every parting and the resonance verdicts hold only between impacts",
                  given.reducer.backlash, given.coupling.stiffness);
    r.approximations.push_back({"permanent tooth contact", b});
  }
  r.chain = crankshaftChainModes(scene);
  if (r.chain.applies)
    r.approximations.push_back(
        {"rigid crankshaft", "the modes, the Floquet analysis, the Campbell diagram and the coupling mode's "
                             "separation margins take the crankshaft as one rigid body (crankshaft.torsional_stiffness "
                             "is given: the chain's own modes are listed apart and get margins of their own, " +
                             r.chain.approximations + ")"});
  return scene;
}

// How the steady motion is searched, with the frozen-angle frequency at the expected running
// speed as the Floquet frequency's reference (an elastic coupling's).
SteadyMotionOptions steadyMotionOptions(DriveModel& reduced, const Scene& scene, const ModesOptions& o, bool elastic) {
  SteadyMotionOptions so;
  so.samples = o.angles;
  so.max_newton = o.max_newton;
  so.warmup_periods = o.warmup_periods;
  DrivePoint p0;
  p0.phi = scene.initial.crank_angle;
  const SteadyGuess g = steadyGuess(reduced.reducedModel());
  p0.omega = g.ok ? g.omega : std::max(std::abs(scene.initial.crank_speed), 1.0);
  p0.twist = g.twist;
  so.reference_frequency = elastic ? frozenModes(reduced, scene, p0).oscillation_frequency() : 0.0;
  return so;
}

// `angles` points at equal crank angles over one revolution from phi0 [rad], each at the guess's
// speed and twist: the drive turning uniformly.
std::vector<DrivePoint> uniformRotation(double phi0, const SteadyGuess& g, int angles) {
  std::vector<DrivePoint> points;
  for (int k = 0; k < angles; ++k) {
    DrivePoint p;
    p.phi = phi0 + 2 * M_PI * k / angles;
    p.omega = g.omega;
    p.twist = g.twist;
    points.push_back(p);
  }
  return points;
}

// Without a steady motion: frozen-angle modes only at the speed the machine runs at, where the
// motor's static curve carries the mean load. A speed that is not the running speed (the initial
// speed, often 0) would give modes of a machine that does not exist. Empty (and said in the notes)
// where there is no such speed.
std::vector<DrivePoint> uniformRotationPoints(const ReducedModel& rm, const ModesOptions& o, ModesReport& r) {
  const SteadyGuess g = steadyGuess(rm);
  if (!g.ok) {
    r.notes.push_back("no steady motion (" + r.steady.failure +
                      "): the modal analysis is not applicable (no running speed to linearize about)");
    return {};
  }
  // The failure's own words are of any length: printfText, not a fixed buffer, so they are never cut.
  r.notes.push_back(printfText("no steady motion (%s): no Floquet analysis; frozen-angle modes at uniform rotation "
                               "at omega = %.4g rad/s instead, where the motor's static curve carries the mean load "
                               "torque %.4g N*m (an estimate of the running speed)",
                               r.steady.failure.c_str(), g.omega, g.mean_load_torque));
  r.fallback_omega = g.omega;
  return uniformRotation(rm.scene().initial.crank_angle, g, o.angles);
}

// The largest relative difference of the two models' frozen-angle frequencies over the points.
double largestModelDifference(const ModelFrozenModes& reduced, const ModelFrozenModes& multibody, size_t points) {
  double d = 0;
  for (size_t i = 0; i < points; ++i) {
    const double a = reduced.angles[i].torsional_frequency(), b = multibody.angles[i].torsional_frequency();
    if (std::isfinite(a) && std::isfinite(b)) d = std::max(d, std::abs(a - b) / a);
  }
  return d;
}

// The multibody model's steady motion is searched from the reduced model's, without samples and
// at a tighter tolerance, its Floquet branch referred to the frozen mean.
SteadyMotionOptions multibodySearch(const SteadyMotionOptions& so, const ModesReport& r, double branch_reference) {
  SteadyMotionOptions mo = so;
  mo.samples = 0;
  mo.rtol = 1e-8;
  mo.start = r.steady.x0;
  mo.warmup_periods = 0;
  mo.reference_frequency = r.elastic ? branch_reference : 0.0;
  return mo;
}

// The multibody model's frozen-angle modes along the same points, their largest difference from
// the reduced model's, and (o.multibody_floquet) its own steady motion and Floquet multipliers,
// started from the reduced model's.
void addMultibodyModes(const Scene& scene, const ModesOptions& o, const SteadyMotionOptions& so,
                       const std::vector<DrivePoint>& points, double branch_reference, ModesReport& r) {
  try {
    auto mb = makeMultibodyDrive(scene);
    r.frozen.push_back(frozenAlong(*mb, scene, points));
    if (r.elastic) r.model_difference = largestModelDifference(r.frozen[0], r.frozen[1], points.size());
    markPhase(o.clock, "modes: frozen-angle modes (multibody)");
    if (o.multibody_floquet && r.steady.found) {
      r.steady_multibody = steadyMotion(*mb, scene, multibodySearch(so, r, branch_reference));
      r.has_multibody_steady = true;
      markPhase(o.clock, "modes: steady motion and Floquet (multibody)");
    }
  } catch (const std::exception& e) {
    ModelFrozenModes m;
    m.model = "multibody";
    m.failure = e.what();
    r.frozen.push_back(m);
  }
}

// The Campbell diagram over the speed range, with the orders that can reach the modes.
void addCampbellDiagram(const Scene& scene, const ModesOptions& o, double w_op, ModesReport& r) {
  if (!(o.campbell && r.elastic && r.steady.found)) {
    if (o.campbell) r.campbell.note = !r.elastic ? "rigid coupling: the drive has no torsional mode" : "no steady motion";
    return;
  }
  std::vector<int> orders;
  const double p_top = 1.3 * std::max(r.frozen[0].torsional.max, r.two_mass.p0);
  for (int k : r.orders.all)
    if (0.5 * k * o.speed_low * w_op <= p_top) orders.push_back(k);
  r.campbell = campbellDiagram(scene, w_op, linearGrid(o.speed_low * w_op, o.speed_high * w_op, o.speeds), orders,
                               36);
  int failed = 0;
  std::string first;
  for (const CampbellPoint& p : r.campbell.points)
    if (!p.found && failed++ == 0) first = p.failure;
  if (!r.campbell.note.empty()) r.notes.push_back("Campbell diagram: " + r.campbell.note);
  if (failed)
    r.notes.push_back("Campbell diagram: no steady motion at " + std::to_string(failed) + " of " +
                      std::to_string(r.campbell.points.size()) + " speeds (" + first + ")");
}

// The coupling mode's separation margins from the excitation orders, and the crankshaft chain's.
void addSeparationMargins(const ReducedModel& rm, ModesReport& r) {
  const Band none;
  r.separation = separationMargins(r.elastic, r.steady, r.frozen.empty() ? none : r.frozen[0].torsional_natural,
                                   r.frozen.empty() ? none : r.frozen[0].torsional,
                                   r.frozen.empty() ? none : r.frozen[0].torsional_damping, r.orders, r.campbell);
  if (r.chain.applies && r.steady.found && r.steady.omega_mean > 0) {
    // The throws' orders up to 1.3 times the chain's highest mode (at least the layout's 24).
    double p_top = 0;
    for (const ChainModeBand& b : r.chain.modes) p_top = std::max(p_top, b.p_max);
    const int orders = std::clamp(int(std::ceil(1.3 * p_top / r.steady.omega_mean)), 24, 400);
    addChainSeparation(r.separation, r.chain, r.elastic, r.steady,
                       throwOrderShares(rm, r.steady.omega_mean, orders));
  }
}

// The stability charts over stiffness and speed (one per damping) and over stiffness and damping.
void addStabilityCharts(const Scene& scene, const ModesOptions& o, double w_op, ModesReport& r) {
  double c_ref = scene.coupling.stiffness;
  if (!r.elastic) {  // the stiffness that would put the two-mass p0 at 6ω
    const double J1 = r.two_mass.J1, J2 = r.two_mass.J2_mean, p = 6 * w_op;
    c_ref = p * p * J1 * J2 / (J1 + J2);
    r.notes.push_back("rigid coupling: the stability charts show what an elastic coupling of stiffness c would do");
  }
  const std::vector<double> c = geometricGrid(o.c_low * c_ref, o.c_high * c_ref, o.chart_c);
  std::vector<double> dampings = o.chart_dampings;
  if (dampings.empty()) dampings.push_back(r.elastic ? scene.coupling.damping : 0.0);
  for (double k : dampings)
    r.charts.push_back(chartOverSpeed(scene, w_op,
                                      c, linearGrid(o.chart_speed_low * w_op, o.chart_speed_high * w_op, o.chart_y), k));
  double k_top = o.damping_high;
  if (!(k_top > 0)) {
    k_top = std::max(1000.0, r.elastic ? scene.coupling.damping : 0.0);
    for (double k : o.marked_dampings) k_top = std::max(k_top, k);
    k_top *= 2;
  }
  r.charts.push_back(chartOverDamping(scene, w_op, c, linearGrid(0.0, k_top, o.chart_y)));
  r.charts.back().marked = o.marked_dampings;
  if (!r.elastic) r.charts.back().operating_y = NAN;
}

}  // namespace

TwoMassEstimate twoMassEstimate(const ReducedModel& rm) {
  const Scene& scene = rm.scene();
  TwoMassEstimate t;
  double J2 = 0;
  const int n = 720;
  for (int i = 0; i < n; ++i) J2 += rm.crankSideInertia(2 * M_PI * i / n);
  t.J2_mean = J2 / n;
  t.J1 = scene.motorSideInertia();
  if (scene.coupling.type == CouplingType::Elastic) {
    t.applicable = true;
    t.stiffness = scene.coupling.stiffness;
    t.p0 = std::sqrt(t.stiffness * (t.J1 + t.J2_mean) / (t.J1 * t.J2_mean));  // Dyomin (two rotors) eq. (10)
  }
  return t;
}

namespace {

// 1. Steady motion (reduced model) and its Floquet multipliers; returns how it was searched.
SteadyMotionOptions addSteadyMotion(DriveModel& reduced, const Scene& scene, const ModesOptions& o, ModesReport& r) {
  const SteadyMotionOptions so = steadyMotionOptions(reduced, scene, o, r.elastic);
  r.steady = steadyMotion(reduced, scene, so);
  markPhase(o.clock, "modes: steady motion and Floquet (reduced)");
  return so;
}

// The crank angles of the frozen-angle modes: the steady motion's samples, else uniform rotation
// at the estimated running speed.
std::vector<DrivePoint> frozenPoints(const ReducedModel& rm, const ModesOptions& o, ModesReport& r) {
  std::vector<DrivePoint> points = r.steady.samples;
  if (!r.steady.found) {
    const std::vector<DrivePoint> uniform = uniformRotationPoints(rm, o, r);
    points.insert(points.end(), uniform.begin(), uniform.end());
  }
  return points;
}

// Frozen-angle modes of both models along the points; the reduced model's choose the branch of
// the Floquet frequency.
void addFrozenModes(DriveModel& reduced, const Scene& scene, const ModesOptions& o, const SteadyMotionOptions& so,
                    const std::vector<DrivePoint>& points, ModesReport& r) {
  r.frozen.push_back(frozenAlong(reduced, scene, points));
  markPhase(o.clock, "modes: frozen-angle modes (reduced)");
  // The Floquet frequency is known only modulo 2π/T: its branch is the one nearest the frozen-angle
  // mode's damped frequency Im λ over the revolution (the undamped √λ of M⁻¹K lies branches away
  // when the damping is heavy: six carts at k = 2000 N·m·s/rad, ζ = 0.54, have √λ ≈ 65 rad/s and
  // Im λ ≈ 32.7 rad/s with 2π/T = 10.7 rad/s).
  const double branch_reference = std::isfinite(r.frozen[0].oscillation_damped.mean) ? r.frozen[0].oscillation_damped.mean
                                                                                    : r.frozen[0].torsional.mean;
  if (r.elastic && r.steady.found) rebranch(r.steady, branch_reference);  // with the frozen mean
  if (o.multibody) addMultibodyModes(scene, o, so, points, branch_reference, r);
}

// 3. Excitation orders at the operating speed w_op, 4. the Campbell diagram and the separation
// margins, 5. the stability charts.
void addOperatingSpeedAnalyses(const ReducedModel& rm, const Scene& scene, const ModesOptions& o, double w_op,
                               ModesReport& r) {
  r.orders = excitationOrders(rm, w_op);
  markPhase(o.clock, "modes: excitation orders");
  addCampbellDiagram(scene, o, w_op, r);
  markPhase(o.clock, "modes: Campbell diagram");
  addSeparationMargins(rm, r);
  if (o.charts && r.steady.found) addStabilityCharts(scene, o, w_op, r);
  markPhase(o.clock, "modes: stability charts");
}

}  // namespace

ModesReport analyseModes(const Scene& given, const ModesOptions& o) {
  const std::clock_t c0 = std::clock();
  ModesReport r;
  const Scene scene = linearizedScene(given, r);
  r.scene = scene.name;
  r.elastic = scene.coupling.type == CouplingType::Elastic;
  r.motor = scene.motor.enabled;
  // The reduced model, built once: the reduced drive's equations and the kinematics, inertias and
  // loads every stage reads.
  auto reduced = makeReducedDrive(scene);
  const ReducedModel& rm = reduced->reducedModel();
  markPhase(o.clock, "modes: set-up");
  // First estimate: two constant inertias (Dyomin (two rotors) eq. (10)).
  r.two_mass = twoMassEstimate(rm);
  const SteadyMotionOptions so = addSteadyMotion(*reduced, scene, o, r);
  // 2. Frozen-angle modes, both models.
  const std::vector<DrivePoint> points = frozenPoints(rm, o, r);
  addFrozenModes(*reduced, scene, o, so, points, r);
  const double w_op = r.steady.found ? r.steady.omega_mean : (points.empty() ? 1.0 : points[0].omega);
  addOperatingSpeedAnalyses(rm, scene, o, w_op, r);
  r.warnings = modalWarnings(r);
  r.cpu_seconds = double(std::clock() - c0) / CLOCKS_PER_SEC;
  return r;
}

std::vector<std::string> modalWarnings(const ModesReport& r) {
  return modalWarnings(r, r.steady.omega_mean, r.orders);
}

namespace {

// The analysis could not be made for a driven machine: say so (the first estimate is then the
// only resonance check), never leave it silent.
std::string incompleteAnalysisWarning(const ModesReport& r) {
  if (std::isfinite(r.fallback_omega))
    return printfText("modal analysis incomplete: no steady motion of the drive was found (%s), so there are no "
                      "Floquet multipliers and no stability or resonance verdict; the frozen-angle modes are taken at "
                      "uniform rotation at omega = %.4g rad/s, where the motor's static curve carries the mean load "
                      "(an estimate of the running speed)",
                      r.steady.failure.c_str(), r.fallback_omega);
  return printfText("modal analysis not applicable: no steady motion of the drive (%s), so no torsional modes, "
                    "Floquet multipliers or resonance verdict",
                    r.steady.failure.c_str());
}

std::string instabilityWarning(const FloquetVerdict& v, double omega) {
  char buf[640];
  std::snprintf(buf, sizeof buf,
                "%s: the largest Floquet multiplier of the drive linearized about its steady motion has "
                "|mu| = %.4g per crank revolution (> 1: a disturbance grows %.3g-fold each turn, growth rate "
                "%.3g 1/s); the steady running at omega = %.4g rad/s is unstable",
                v.text == "parametrically unstable" ? "parametric resonance" : "unstable steady motion",
                v.max_modulus, v.max_modulus, -v.slowest_decay_rate, omega);
  return buf;
}

// Forced resonance: the torsional mode's Floquet frequency p_F within 5 % of k·ω for an order k
// that drives the coupling mode (ExcitationOrders.h: at least 1 % of the largest harmonic of the
// load torque plus the inertia's own torque ½·J_n2'·ω²).
void addForcedResonanceWarnings(const ModesReport& r, double omega, const ExcitationOrders& orders,
                                std::vector<std::string>& w) {
  const FloquetVerdict& v = r.steady.verdict;
  if (!(v.has_torsional && v.torsional_resolved && std::isfinite(v.torsional_frequency) && omega > 0)) return;
  const double pf = v.torsionalNaturalFrequency();
  char buf[640];
  for (int k : orders.forced) {
    if (k < 1 || k > int(orders.table.size())) continue;
    const double torque = orders.table[size_t(k - 1)].exciting_torque;
    const double f = k * omega;
    if (std::abs(pf - f) > 0.05 * f) continue;
    std::snprintf(buf, sizeof buf,
                  "torsional resonance: the coupling mode's natural frequency from the Floquet multipliers, p = %.4g rad/s, "
                  "is within 5 %% of order %d of the crank speed (%d*omega = %.4g rad/s at omega = %.4g rad/s), which "
                  "carries %.3g N*m (%.0f %% of the largest exciting harmonic); damping ratio %.3g (without the damping, "
                  "the frozen-angle band is p = %.4g ... %.4g rad/s)",
                  pf, k, k, f, omega, torque, 100 * torque / orders.exciting_largest, v.torsional_damping_ratio,
                  r.frozen[0].torsional.min, r.frozen[0].torsional.max);
    w.push_back(buf);
  }
}

}  // namespace

std::vector<std::string> modalWarnings(const ModesReport& r, double omega, const ExcitationOrders& orders) {
  std::vector<std::string> w;
  if (r.elastic && r.motor && !r.steady.found) {
    w.push_back(incompleteAnalysisWarning(r));
    return w;
  }
  if (!r.elastic || !r.steady.found || r.frozen.empty()) return w;
  if (!r.steady.verdict.stable) w.push_back(instabilityWarning(r.steady.verdict, omega));
  addForcedResonanceWarnings(r, omega, orders, w);
  return w;
}

}  // namespace rollerdyn::modes
