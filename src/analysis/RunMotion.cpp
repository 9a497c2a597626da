#include "analysis/RunMotion.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "analysis/RestDetector.h"
#include "analysis/StallDetector.h"

namespace rollerdyn {

namespace {

// Whether a crank that turns one way, in a run that never settled, is still running up (or
// down): fewer than three whole revolutions (too few to see it settle), or mean speeds of the
// last three whole revolutions each above (or each below) the one before by more than kRise. A settling or beating drive has
// revolution means that fall back or level off; a drive running up on a large inertia keeps
// gaining for many revolutions (its verdicts would read the run-up as running).
// Times at which the crank completed each whole revolution, interpolated between rows (a crossing
// taken at its row would quantise a 0.12 s revolution to 5 ms steps, 4 %, and hide a 1 % trend);
// the first is the first finite row's time.
std::vector<double> revolutionTimes(const Table& ts) {
  const int it = ts.index("t"), ip = ts.index("phi_crank");
  std::vector<double> t_rev;
  double phi0 = NAN, next = NAN, t_prev = NAN, phi_prev = NAN;
  for (const auto& row : ts.rows) {
    if (!std::isfinite(row[ip]) || !std::isfinite(row[it])) continue;
    if (!std::isfinite(phi0)) {
      phi0 = phi_prev = row[ip];
      t_prev = row[it];
      t_rev.push_back(row[it]);
      next = phi0 + 2.0 * M_PI;
      continue;
    }
    while (row[ip] >= next) {
      const double a = row[ip] > phi_prev ? (next - phi_prev) / (row[ip] - phi_prev) : 1.0;
      t_rev.push_back(t_prev + std::clamp(a, 0.0, 1.0) * (row[it] - t_prev));
      next += 2.0 * M_PI;
    }
    t_prev = row[it], phi_prev = row[ip];
  }
  return t_rev;
}

bool stillGainingSpeed(const Table& ts) {
  constexpr double kRise = 0.005;  // [-] relative gain per revolution that counts as running up
  const std::vector<double> t_rev = revolutionTimes(ts);
  const int n = int(t_rev.size()) - 1;  // whole revolutions
  if (n < 3) return true;
  const double w1 = 1.0 / (t_rev[n - 2] - t_rev[n - 3]), w2 = 1.0 / (t_rev[n - 1] - t_rev[n - 2]),
               w3 = 1.0 / (t_rev[n] - t_rev[n - 1]);  // revolutions per second, proportional to the means
  // Gaining, or losing as steadily: a drive started far above its running speed (the third trial's
  // initial.crank_speed = 102 rad/s, the rotor's speed typed for the crank's) slows revolution
  // after revolution and is no more settled than one that runs up.
  return (w2 > w1 * (1.0 + kRise) && w3 > w2 * (1.0 + kRise)) || (w2 < w1 * (1.0 - kRise) && w3 < w2 * (1.0 - kRise));
}

// The status line a model ended the run with, as a motion; "" when it names none.
std::string motionOfStatus(const std::string& status) {
  std::string from_status = StallDetector::motionOfStatus(status);
  if (from_status.empty()) from_status = RestDetector::motionOfStatus(status);
  return from_status;
}

// The rest rule on the rows: every cart slower than v_s for RestDetector::kWindow.
bool restRuleHolds(const Scene& sc, const Table& ts) {
  RestDetector rest(true, sc.loads.velocity_smoothing);
  std::vector<int> iv;
  for (int j = 1; ts.has("v_cart_" + std::to_string(j)); ++j) iv.push_back(ts.index("v_cart_" + std::to_string(j)));
  std::vector<double> v(iv.size());
  const int it = ts.index("t");
  for (const auto& row : ts.rows) {
    for (std::size_t j = 0; j < iv.size(); ++j) v[j] = row[iv[j]];
    if (rest.update(row[it], v, int(v.size()))) return true;
  }
  return false;
}

// The columns the stall rule reads: time, crank angle and speed, motor speed (the crank's without
// one), and the supply's voltage and frequency ratios (-1: the run has none).
struct StallColumns {
  int it, ip, ic, im, iu, ifr;
};

StallColumns stallColumns(const Table& ts) {
  StallColumns c;
  c.it = ts.index("t"), c.ip = ts.index("phi_crank"), c.ic = ts.index("omega_crank");
  c.im = ts.has("omega_motor") ? ts.index("omega_motor") : c.ic;
  c.iu = ts.has("supply_voltage_ratio") ? ts.index("supply_voltage_ratio") : -1;
  c.ifr = ts.has("supply_frequency_ratio") ? ts.index("supply_frequency_ratio") : -1;
  return c;
}

// A drive still held at rest when the run ends, with the motor connected in a stage the rule
// skips (star that never changes over, a ramp longer than the run), did not start in this run:
// the held rule's band and time, counted back from the last row, at any supply but none.
bool heldAtRestAtEnd(const Table& ts, const StallColumns& c, double band) {
  if (c.iu < 0 || ts.rows.empty()) return false;
  double held_since = NAN;
  for (auto row = ts.rows.rbegin(); row != ts.rows.rend(); ++row) {
    if (!(std::abs((*row)[c.ic]) <= band && std::abs((*row)[c.im]) <= band && (*row)[c.iu] > 0)) break;
    held_since = (*row)[c.it];
  }
  return ts.rows.back()[c.it] - held_since >= StallDetector::kRestWindow;
}

// The stall rule on the rows, then the held rule: "rocking", "stalled", or "" when neither
// ends the run; `swings_growing` receives the stall rule's reading of the last oscillation.
std::string stallRuleMotion(const Scene& sc, const Table& ts, double band, bool& swings_growing) {
  StallDetector d(true, sc.motor.omega_sync / sc.reducer.ratio);
  const StallColumns c = stallColumns(ts);
  // With a starting method the rule counts only the rows at the rated supply (as the models'
  // run loops do, Supply::fullSupply): a drive may legitimately be slow in star, on a ramp, or
  // after a switch-off.
  for (const auto& row : ts.rows) {
    if ((c.iu >= 0 && row[c.iu] != 1.0) || (c.ifr >= 0 && row[c.ifr] != 1.0)) continue;
    if (d.update(row[c.it], row[c.ip], row[c.ic], row[c.im]))
      return d.kind() == StallKind::RockingWithoutGain ? "rocking" : "stalled";
  }
  swings_growing = d.swingsGrowing();
  return heldAtRestAtEnd(ts, c, band) ? "stalled" : "";
}

// A crank speed that changes sign in the window: "rocking" or "starting", or "" when the crank
// nonetheless turns (or its speed keeps its sign).
std::string signChangeMotion(const WindowMetrics& m, double band, double window_advance, bool steady_reached,
                             bool swings_growing) {
  // A crank that comes to a stop at a dead centre and goes on forwards reads -7e-20 rad/s there,
  // and once was "rocking" or "starting" by that round-off alone, depending on its switch-on time.
  if (!(m.omega_min < -band && m.omega_max > band)) return "";
  // Rocking in the window whose swings still grow when the run ends: a rocking-then-starting
  // drive that has not yet got over its dead centre; undecided, not "rocking".
  if (!(std::abs(window_advance) >= 2.0 * M_PI)) return swings_growing && !steady_reached ? "starting" : "rocking";
  if (!steady_reached) return "starting";
  return "";
}

// The motion the rows show where no rule ended the run: from the window's crank speeds.
std::string windowMotion(const Scene& sc, const Table& ts, const WindowMetrics& m, double band,
                         double window_advance, bool steady_reached, bool swings_growing) {
  if (!std::isfinite(m.omega_min) || !std::isfinite(m.omega_max)) return "unknown";
  const std::string sign_change = signChangeMotion(m, band, window_advance, steady_reached, swings_growing);
  if (!sign_change.empty()) return sign_change;
  if (m.omega_min == 0 && m.omega_max == 0) return "at_rest";
  // No motor and no steady state: nothing drives the machine, so a crank that turns one way but
  // never settles is losing its kinetic energy to friction and loads; the run ended before it came
  // to rest. Its speed swing is the deceleration, not an unevenness (the trial read δ = 0.22 of a
  // coast-down from 10.4 to 6.5 rad/s as "turning").
  if (!sc.motor.enabled && !steady_reached) return "coasting";
  if (!steady_reached && ts.has("t") && ts.has("phi_crank") && stillGainingSpeed(ts)) return "starting";
  return "turning";
}

}  // namespace

// One word from three rules, each of which ends a run with its own status line: the stall rule
// (StallDetector.h: a motor at the rated supply that holds the drive at rest or is driven
// backwards, "stalled"; swings that no longer grow, "rocking"), the held rule (a motor connected
// in a stage the stall rule skips that never got the drive going, "stalled"), and the rest rule
// (RestDetector.h: no motor, friction and loads have stopped the machine, "at_rest"). The models
// end a run with the detector's status line; the same rules applied to the rows catch a table
// that was not produced by a model run.
std::string classifyMotion(const Scene& sc, const RunResult& run, const WindowMetrics& m, double window_advance,
                           bool steady_reached) {
  if (!run.stats.complete) {
    const std::string from_status = motionOfStatus(run.stats.status);
    if (!from_status.empty()) return from_status;
  }
  const Table& ts = run.timeseries;
  // The stall rule's speed band, 1 % of ω0/u (StallDetector.h): held at rest inside it, and a
  // speed changes sign only when it leaves it on the other side, as the rule's swings do.
  const double band = sc.motor.enabled && sc.reducer.ratio > 0
                          ? StallDetector::kSpeedFraction * sc.motor.omega_sync / sc.reducer.ratio
                          : 0.0;
  bool swings_growing = false;  // the stall rule's reading of the last oscillation, if the crank rocked
  if (!sc.motor.enabled && ts.has("t") && ts.has("v_cart_1") && restRuleHolds(sc, ts)) return "at_rest";
  if (sc.motor.enabled && sc.reducer.ratio > 0 && ts.has("t") && ts.has("omega_crank") && ts.has("phi_crank")) {
    const std::string stalled = stallRuleMotion(sc, ts, band, swings_growing);
    if (!stalled.empty()) return stalled;
  }
  return windowMotion(sc, ts, m, band, window_advance, steady_reached, swings_growing);
}

namespace {

// How far the crank travelled over the run's finite rows: its angle's range [lo, hi] and last
// value [rad] (from the start angle phi0), and its speed's range [w_lo, w_hi] (from rest) [rad/s].
struct CrankTravel {
  double lo, hi, w_lo, w_hi, end;
};

CrankTravel crankTravel(const Table& ts, double phi0) {
  const int ip = ts.index("phi_crank"), iw = ts.index("omega_crank");
  CrankTravel c{phi0, phi0, 0, 0, phi0};
  for (const auto& row : ts.rows) {
    if (!std::isfinite(row[ip]) || !std::isfinite(row[iw])) continue;
    c.lo = std::min(c.lo, row[ip]), c.hi = std::max(c.hi, row[ip]);
    c.w_lo = std::min(c.w_lo, row[iw]), c.w_hi = std::max(c.w_hi, row[iw]);
    c.end = row[ip];
  }
  return c;
}

}  // namespace

std::string stalledCrankTravel(const Scene& sc, const RunResult& run) {
  const Table& ts = run.timeseries;
  if (!ts.has("phi_crank") || !ts.has("omega_crank") || ts.rows.empty()) return "";
  const double phi0 = sc.initial.crank_angle;
  const CrankTravel travel = crankTravel(ts, phi0);
  const double lo = travel.lo, hi = travel.hi, w_lo = travel.w_lo, w_hi = travel.w_hi, end = travel.end;
  constexpr double kMoved = 5.0 * M_PI / 180.0;  // less is a creep at the start angle, not a motion
  if (hi - phi0 < kMoved && phi0 - lo < kMoved) return "";
  const double deg = 180.0 / M_PI;
  char buf[400];
  const char* how = phi0 - lo >= kMoved && hi - phi0 < kMoved  ? "the load drove it backwards"
                    : hi - phi0 >= kMoved && phi0 - lo < kMoved ? "it moved forwards"
                                                                : "it moved both ways";
  const bool swung = w_lo < 0 && w_hi > 0;
  std::snprintf(buf, sizeof buf,
                "the crank did not stay at the start angle: %s, over %.4g ... %.4g deg%s (crank speed %.3g ... %.3g "
                "rad/s), and is at %.4g deg when the run ends",
                how, lo * deg, hi * deg, swung ? ", swinging back and forth" : "", w_lo, w_hi, end * deg);
  return buf;
}

}  // namespace rollerdyn
