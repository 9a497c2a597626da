#include "modes/Campbell.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "modes/DriveOrbit.h"

namespace rollerdyn::modes {

std::vector<double> lineCrossings(const std::vector<double>& w, const std::vector<double>& f, double slope) {
  std::vector<double> out;
  for (size_t i = 1; i < w.size(); ++i) {
    const double a = f[i - 1] - slope * w[i - 1], b = f[i] - slope * w[i];
    if (!std::isfinite(a) || !std::isfinite(b)) continue;
    if (a == 0) out.push_back(w[i - 1]);
    if ((a < 0) != (b < 0) && b != 0) out.push_back(w[i - 1] + (w[i] - w[i - 1]) * a / (a - b));
  }
  return out;
}

namespace {

// How the steady motion at crank speed w is searched: warm-started from the last speed's orbit
// when there is one, the Floquet branch referred to the frozen frequency at uniform rotation.
SteadyMotionOptions campbellSearch(DriveModel& drive, const Scene& s, double w, int angles,
                                   const Eigen::VectorXd& warm) {
  SteadyMotionOptions o;
  o.samples = angles;
  o.rtol = 1e-7;
  if (warm.size()) {
    o.start = warm;
    o.start(0) = w;
    o.warmup_periods = 0;
  }
  // Reference for the Floquet branch: frozen frequency at uniform rotation.
  DrivePoint p0;
  p0.phi = s.initial.crank_angle;
  p0.omega = w;
  o.reference_frequency = frozenModes(drive, s, p0).oscillation_frequency();
  return o;
}

// The frozen-angle band along the orbit m, its damping and whether the mode oscillates at every
// angle; returns the mean of the damped frequency Im λ (the Floquet branch's reference).
double addFrozenBand(CampbellPoint& p, DriveModel& drive, const Scene& s, const SteadyMotion& m) {
  std::vector<double> f, fd, z;
  p.oscillates = true;
  for (const DrivePoint& q : m.samples) {
    const FrozenAngle fa = frozenModes(drive, s, q);
    f.push_back(fa.torsional_frequency());
    fd.push_back(fa.oscillation_frequency());
    for (const FrozenMode& mode : fa.modes)
      if (mode.torsional) {
        z.push_back(mode.damping_ratio);
        p.oscillates = p.oscillates && mode.oscillates;
      }
  }
  p.frozen = bandOf(f);
  p.frozen_damping = bandOf(z);
  return bandOf(fd).mean;
}

// Floquet frequency on the branch nearest the frozen mean of the damped frequency Im λ (`ref`).
void addFloquet(CampbellPoint& p, const SteadyMotion& m, double ref) {
  const auto mult =
      classifyMultipliers(floquetMultipliers(m.monodromy, m.period, std::isfinite(ref) ? ref : p.frozen.mean), true);
  const FloquetVerdict v = judge(mult);
  p.max_modulus = v.max_modulus;
  if (v.has_torsional) {
    p.floquet_frequency = v.torsional_frequency;
    p.floquet_damping_ratio = v.torsional_damping_ratio;
  }
}

// One speed of the diagram: the steady motion at crank speed w (warm-started from the last speed's
// orbit, which `warm` carries on), the frozen-angle band along it and the Floquet verdict.
CampbellPoint campbellPoint(const Scene& scene, double w, double omega_op, int angles, Eigen::VectorXd& warm) {
  CampbellPoint p;
  p.omega_target = w;
  try {
    const Scene s = sceneAtCrankSpeed(scene, w, omega_op);
    auto drive = makeReducedDrive(s);
    const SteadyMotion m = steadyMotion(*drive, s, campbellSearch(*drive, s, w, angles, warm));
    if (!m.found) {
      p.failure = m.failure;
    } else {
      p.found = true;
      p.omega_mean = m.omega_mean;
      warm = m.x0;
      addFloquet(p, m, addFrozenBand(p, *drive, s, m));
    }
  } catch (const std::exception& e) {
    p.failure = e.what();
  }
  return p;
}

// The frozen band over the speeds found: speed, mean, lowest and highest frequency (NaN where the
// mode is overdamped).
struct FrozenBandCurves {
  std::vector<double> w, fmean, fmin, fmax;
};

FrozenBandCurves frozenBandCurves(CampbellDiagram& d) {
  FrozenBandCurves b;
  for (const CampbellPoint& p : d.points) {
    if (!p.found) continue;
    // An overdamped mode has no frequency a line could meet: NaN breaks the lines there.
    if (!p.oscillates) ++d.overdamped_speeds;
    b.w.push_back(p.omega_mean);
    b.fmean.push_back(p.oscillates ? p.frozen.mean : NAN);
    b.fmin.push_back(p.oscillates ? p.frozen.min : NAN);
    b.fmax.push_back(p.oscillates ? p.frozen.max : NAN);
  }
  return b;
}

// The value of v nearest x (NaN when v is empty).
double nearestTo(const std::vector<double>& v, double x) {
  double best = NAN;
  for (double y : v)
    if (!std::isfinite(best) || std::abs(y - x) < std::abs(best - x)) best = y;
  return best;
}

// The crossings of one order's line (p = k*omega, or 2p = k*omega when parametric) with the frozen
// mean, each with the band between the crossings of the lowest and highest frequency nearest it.
void addLineCrossings(CampbellDiagram& d, const FrozenBandCurves& b, int k, bool parametric) {
  const double slope = campbellSlope(k, parametric);
  const std::vector<double> cm = lineCrossings(b.w, b.fmean, slope);
  const std::vector<double> clo = lineCrossings(b.w, b.fmin, slope), chi = lineCrossings(b.w, b.fmax, slope);
  for (double x : cm) {
    CampbellCrossing c;
    c.order = k;
    c.parametric = parametric;
    c.omega = x;
    c.frequency = slope * x;
    // The band's edges: the crossings of the lowest and highest frequency nearest this one.
    const double lo = nearestTo(clo, x), hi = nearestTo(chi, x);
    c.omega_band_low = std::isfinite(lo) && std::isfinite(hi) ? std::min(lo, hi) : NAN;
    c.omega_band_high = std::isfinite(lo) && std::isfinite(hi) ? std::max(lo, hi) : NAN;
    d.crossings.push_back(c);
  }
}

// Where the lines p = k*omega and 2p = k*omega of every order meet the frozen mean, with the band
// between their crossings of the lowest and highest frozen frequency; sorted by speed.
void findCrossings(CampbellDiagram& d, const std::vector<int>& orders) {
  const FrozenBandCurves b = frozenBandCurves(d);
  for (int k : orders)
    for (bool parametric : {false, true}) addLineCrossings(d, b, k, parametric);
  if (d.overdamped_speeds)
    d.note = "the coupling mode is overdamped (damping ratio >= 1, no oscillation) at " +
             std::to_string(d.overdamped_speeds) + " of " + std::to_string(b.w.size()) +
             " speeds: no crossings are listed there";
  std::sort(d.crossings.begin(), d.crossings.end(),
            [](const CampbellCrossing& a, const CampbellCrossing& b) { return a.omega < b.omega; });
}

}  // namespace

CampbellDiagram campbellDiagram(const Scene& scene, double omega_op, const std::vector<double>& speeds,
                                const std::vector<int>& orders, int angles) {
  CampbellDiagram d;
  if (scene.coupling.type != CouplingType::Elastic) {
    d.note = "rigid coupling: the drive has no torsional mode";
    return d;
  }
  if (!scene.motor.enabled) {
    d.note = "no motor: no steady running to vary";
    return d;
  }
  d.applicable = true;
  d.orders = orders;
  Eigen::VectorXd warm;
  for (double w : speeds) d.points.push_back(campbellPoint(scene, w, omega_op, angles, warm));
  findCrossings(d, orders);
  return d;
}

}  // namespace rollerdyn::modes
