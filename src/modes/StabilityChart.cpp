#include "modes/StabilityChart.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <functional>
#include <thread>

#include "modes/DriveOrbit.h"
#include "modes/FrozenModes.h"

namespace rollerdyn::modes {

std::vector<double> geometricGrid(double a, double b, int n) {
  std::vector<double> v;
  for (int i = 0; i < n; ++i) v.push_back(n == 1 ? a : a * std::pow(b / a, double(i) / (n - 1)));
  return v;
}

std::vector<double> linearGrid(double a, double b, int n) {
  std::vector<double> v;
  for (int i = 0; i < n; ++i) v.push_back(n == 1 ? a : a + (b - a) * i / (n - 1));
  return v;
}

namespace {

// How a chart point's steady motion is searched: warm-started from `warm` (found at stiffness
// c_warm), the Floquet branch referred to the frozen frequency at the expected running speed.
SteadyMotionOptions chartSearch(DriveModel& drive, const Scene& s, double c, const Eigen::VectorXd& warm,
                                double c_warm) {
  SteadyMotionOptions o;
  o.samples = 0;
  o.rtol = 1e-6;  // the verdict compares |μ| with 1: six digits are plenty
  // Warm-started points converge in 1-3 iterations; one that needs more is near a forced
  // resonance of an undamped coupling (Φ - I nearly singular) and is reported without a
  // steady motion rather than chased.
  o.max_newton = 10;
  if (warm.size() == 3) {  // twist and its rate scale as 1/c
    o.start = warm;
    o.start(1) *= c_warm / c;
    o.start(2) *= c_warm / c;
    o.warmup_periods = 0;
  }
  DrivePoint p0;
  p0.phi = s.initial.crank_angle;
  const SteadyGuess g = steadyGuess(drive.reducedModel());
  p0.omega = g.ok ? g.omega : s.motor.omega_sync / s.reducer.ratio;
  p0.twist = g.twist;
  o.reference_frequency = frozenModes(drive, s, p0).oscillation_frequency();
  return o;
}

// The steady motion searched with `o`; when a warm start found none, searched again from the guess.
SteadyMotion chartSteadyMotion(DriveModel& drive, const Scene& s, SteadyMotionOptions o, bool warm_started) {
  SteadyMotion m = steadyMotion(drive, s, o);
  if (!m.found && warm_started) {  // the warm start may mislead: try from the guess
    o.start.resize(0);
    o.warmup_periods = 3;
    m = steadyMotion(drive, s, o);
  }
  return m;
}

// The point's verdict from the steady motion found.
void setVerdict(StabilityPoint& p, const SteadyMotion& m) {
  p.found = true;
  p.omega_mean = m.omega_mean;
  p.max_modulus = m.verdict.max_modulus;
  p.stable = m.verdict.stable;
  p.verdict = m.verdict.text;
  if (m.verdict.has_torsional) {
    p.torsional_damping_ratio = m.verdict.torsional_damping_ratio;
    p.torsional_frequency = m.verdict.torsional_frequency;
  }
}

// One chart point: the Floquet verdict of `s`, warm-started from `warm` (updated).
StabilityPoint evaluate(const Scene& s, double c, double y, Eigen::VectorXd& warm, double c_warm) {
  StabilityPoint p;
  p.c = c;
  p.y = y;
  try {
    auto drive = makeReducedDrive(s);
    const SteadyMotion m = chartSteadyMotion(*drive, s, chartSearch(*drive, s, c, warm, c_warm), warm.size() > 0);
    if (!m.found) {
      p.verdict = "no steady running";
      warm.resize(0);
      return p;
    }
    warm = m.x0;
    setVerdict(p, m);
  } catch (const std::exception& e) {
    p.verdict = "no steady running";
    warm.resize(0);
  }
  return p;
}

// rows[i] = row(i) for i < n, on up to `threads` threads (0: one per processor). A row
// warm-starts only from its own previous points, so every row is the same whichever thread
// computes it, and the chart the same bit for bit. An exception of a row is rethrown here.
std::vector<std::vector<StabilityPoint>> computeRows(int n, const std::function<std::vector<StabilityPoint>(int)>& row,
                                                     int threads) {
  std::vector<std::vector<StabilityPoint>> rows(n);
  if (threads <= 0) threads = int(std::max(1u, std::thread::hardware_concurrency()));
  threads = std::max(1, std::min(threads, n));
  std::atomic<int> next{0};
  std::vector<std::exception_ptr> errors(threads);
  auto work = [&](int t) {
    try {
      for (int i = next++; i < n; i = next++) rows[i] = row(i);
    } catch (...) {
      errors[t] = std::current_exception();
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(work, t);
  work(0);
  for (std::thread& th : pool) th.join();
  for (const std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);
  return rows;
}

Scene withCoupling(const Scene& scene, double c, double k) {
  Scene s = scene;
  s.coupling.type = CouplingType::Elastic;
  s.coupling.stiffness = c;
  s.coupling.damping = k;
  return s;
}

// The zone takes in point q: one point more, its extent and worst |μ| widened.
void widenZone(StabilityZone& z, const StabilityPoint& q) {
  ++z.points;
  z.c_min = std::min(z.c_min, q.c);
  z.c_max = std::max(z.c_max, q.c);
  z.y_min = std::min(z.y_min, q.y);
  z.y_max = std::max(z.y_max, q.y);
  z.worst_modulus = std::max(z.worst_modulus, q.max_modulus);
}

// The unstable zone around grid point (iy, ic): every unstable point reached through unstable
// neighbours (rows and columns), marked in `seen`, with its extent and worst |μ|.
StabilityZone unstableZone(const StabilityChart& ch, std::vector<std::vector<int>>& seen, int iy, int ic) {
  const int ny = int(ch.y.size()), nc = int(ch.c.size());
  const StabilityPoint& p = ch.grid[iy][ic];
  StabilityZone z;
  z.c_min = z.c_max = p.c;
  z.y_min = z.y_max = p.y;
  std::vector<std::pair<int, int>> stack{{iy, ic}};
  seen[iy][ic] = 1;
  while (!stack.empty()) {
    auto [a, b] = stack.back();
    stack.pop_back();
    widenZone(z, ch.grid[a][b]);
    const int da[] = {1, -1, 0, 0}, db[] = {0, 0, 1, -1};
    for (int d = 0; d < 4; ++d) {
      const int na = a + da[d], nb = b + db[d];
      if (na < 0 || nb < 0 || na >= ny || nb >= nc || seen[na][nb]) continue;
      const StabilityPoint& r = ch.grid[na][nb];
      if (r.found && !r.stable) {
        seen[na][nb] = 1;
        stack.push_back({na, nb});
      }
    }
  }
  return z;
}

void findZones(StabilityChart& ch) {
  const int ny = int(ch.y.size()), nc = int(ch.c.size());
  std::vector<std::vector<int>> seen(ny, std::vector<int>(nc, 0));
  for (int iy = 0; iy < ny; ++iy)
    for (int ic = 0; ic < nc; ++ic) {
      const StabilityPoint& p = ch.grid[iy][ic];
      if (!p.found) ++ch.failed_points;
      if (p.found && !p.stable) ++ch.unstable_points;
      if (seen[iy][ic] || !p.found || p.stable) continue;
      ch.zones.push_back(unstableZone(ch, seen, iy, ic));
    }
}

// The chart's row at crank speed w: the stiffnesses c in turn, each warm-started from the last.
// A point whose scene cannot be set up has no steady running (and the next starts cold).
std::vector<StabilityPoint> speedRow(const Scene& scene, const std::vector<double>& c, double w, double omega_op,
                                     double damping) {
  std::vector<StabilityPoint> row;
  Eigen::VectorXd warm;
  double c_warm = 0;
  for (double ci : c) {
    StabilityPoint p;
    try {
      const Scene s = sceneAtCrankSpeed(withCoupling(scene, ci, damping), w, omega_op);
      if (warm.size()) warm(0) = w;
      p = evaluate(s, ci, w, warm, c_warm);
    } catch (const std::exception&) {
      p.c = ci;
      p.y = w;
      p.verdict = "no steady running";
      warm.resize(0);
    }
    c_warm = ci;
    row.push_back(p);
  }
  return row;
}

}  // namespace

StabilityChart chartOverSpeed(const Scene& scene, double omega_op, const std::vector<double>& c,
                              const std::vector<double>& omega, double damping, int threads) {
  StabilityChart ch;
  ch.y_key = "omega";
  ch.fixed_damping = damping;
  ch.c = c;
  ch.y = omega;
  ch.operating_c = scene.coupling.type == CouplingType::Elastic ? scene.coupling.stiffness : NAN;
  ch.operating_y = omega_op;
  ch.grid = computeRows(int(omega.size()), [&](int iy) { return speedRow(scene, c, omega[iy], omega_op, damping); },
                       threads);
  findZones(ch);
  return ch;
}

StabilityChart chartOverDamping(const Scene& scene, double omega_op, const std::vector<double>& c,
                                const std::vector<double>& k, int threads) {
  StabilityChart ch;
  ch.fixed_speed = omega_op;
  ch.y_key = "damping";
  ch.c = c;
  ch.y = k;
  ch.operating_c = scene.coupling.type == CouplingType::Elastic ? scene.coupling.stiffness : NAN;
  ch.operating_y = scene.coupling.type == CouplingType::Elastic ? scene.coupling.damping : NAN;
  ch.grid = computeRows(int(k.size()), [&](int iy) {
    const double kk = k[iy];
    std::vector<StabilityPoint> row;
    Eigen::VectorXd warm;
    double c_warm = 0;
    for (double ci : c) {
      row.push_back(evaluate(withCoupling(scene, ci, kk), ci, kk, warm, c_warm));
      c_warm = ci;
    }
    return row;
  }, threads);
  findZones(ch);
  return ch;
}

}  // namespace rollerdyn::modes
