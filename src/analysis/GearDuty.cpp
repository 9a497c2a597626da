#include "analysis/GearDuty.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <tuple>

#include "analysis/DriveSizing.h"
#include "analysis/RunResult.h"
#include "analysis/StartUp.h"
#include "scene/Scene.h"
#include "io/FieldFormat.h"

namespace rollerdyn {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kTwoPi = 6.283185307179586;

double givenOrNaN(double v) { return v > 0 ? v : kNaN; }

std::string g4(double v) { return significant(v, 4); }

// Classes indexed 1 ... (class k holds (k-1)·ΔT < |T| <= k·ΔT); cycles per index.
void addCycles(std::vector<double>& bins, double magnitude, double class_width, double cycles) {
  if (!(magnitude > 0) || !(cycles > 0)) return;
  const std::size_t k = static_cast<std::size_t>(std::max(1.0, std::ceil(magnitude / class_width - 1e-9)));
  if (bins.size() <= k) bins.resize(k + 1, 0.0);
  bins[k] += cycles;
}

FlankSpectrum flank(const std::vector<double>& bins, double class_width, double p, double total) {
  FlankSpectrum f;
  for (std::size_t k = 1; k < bins.size(); ++k)
    if (bins[k] > 0) {
      f.classes.push_back({k * class_width, bins[k]});
      f.cycles += bins[k];
    }
  f.equivalent_torque = equivalentTorque(f.classes, p, total);
  return f;
}

// The classes of `a` times `wa` plus those of `b` times `wb`, merged by torque.
std::vector<TorqueClass> combine(const FlankSpectrum& a, double wa, const FlankSpectrum& b, double wb) {
  std::vector<TorqueClass> out;
  for (const TorqueClass& c : a.classes) out.push_back({c.torque, c.cycles * wa});
  for (const TorqueClass& c : b.classes) out.push_back({c.torque, c.cycles * wb});
  return out;
}

// Row range [b, e) of the rows with t_begin <= t <= t_end.
std::pair<std::size_t, std::size_t> rowsOf(const Table& ts, double t_begin, double t_end) {
  const int it = ts.index("t");
  std::size_t b = ts.rows.size(), e = 0;
  for (std::size_t i = 0; i < ts.rows.size(); ++i)
    if (ts.rows[i][it] >= t_begin && ts.rows[i][it] <= t_end) b = std::min(b, i), e = i + 1;
  return {b, e};
}

void peakOf(GearDuty& g, const Table& ts, std::size_t b, std::size_t e) {
  const int it = ts.index("t"), iy = ts.index("coupling_torque");
  for (std::size_t i = b; i < e && i < ts.rows.size(); ++i)
    if (std::isfinite(ts.rows[i][iy]) && !(std::abs(ts.rows[i][iy]) <= g.peak)) {
      g.peak = std::abs(ts.rows[i][iy]);
      g.t_peak = ts.rows[i][it];
    }
}

// How much of an hour each window's spectrum counts: N starts and the rest of the hour steady
// running, or the steady window alone (its spectrum scaled to the hour).
struct DutyWeights {
  double start = 0, steady = 0;
};

// The duty hour's weights and its basis in words; false (with the reason) when the duty needs a
// start's spectrum the run does not hold.
bool weighDutyHour(GearDuty& g, DutyWeights& h) {
  const GearSpectrum &st = g.start, &w = g.steady;
  const double window = w.t_end - w.t_begin;
  h.steady = 3600.0 / window;
  if (!(g.starts_per_hour > 0)) {
    g.duty_basis = "continuous running (sizing.starts_per_hour not given): the steady window's spectrum, scaled to "
                   "one hour; the start's load cycles are not counted";
    return true;
  }
  if (!st.applies) {
    g.duty_not_applicable = "the duty's " + g4(g.starts_per_hour) + " starts per hour (sizing.starts_per_hour) need "
                            "the start's spectrum: " + st.not_applicable;
    return false;
  }
  const double t_D = st.t_end - st.t_begin;
  h.start = g.starts_per_hour;
  h.steady = std::max(0.0, 3600.0 - g.starts_per_hour * t_D) / window;
  g.duty_basis = "one hour of the duty: " + g4(g.starts_per_hour) + " starts (sizing.starts_per_hour) of " + g4(t_D) +
                 " s each and " + g4(std::max(0.0, 3600.0 - g.starts_per_hour * t_D)) +
                 " s of steady running (the steady window's spectrum scaled)";
  return true;
}

// The duty hour's equivalent torque on each flank; the larger decides.
void dutyHour(GearDuty& g) {
  const GearSpectrum &st = g.start, &w = g.steady;
  if (!w.applies) {
    g.duty_not_applicable = w.not_applicable;
    return;
  }
  DutyWeights h;
  if (!weighDutyHour(g, h)) return;
  g.hour_revolutions = h.start * st.revolutions + h.steady * w.revolutions;
  const double p = g.exponent;
  g.equivalent_torque_drive = equivalentTorque(combine(st.drive, h.start, w.drive, h.steady), p, g.hour_revolutions);
  g.equivalent_torque_coast = equivalentTorque(combine(st.coast, h.start, w.coast, h.steady), p, g.hour_revolutions);
  const bool coast_decides = g.equivalent_torque_coast > g.equivalent_torque_drive;
  g.equivalent_torque = coast_decides ? g.equivalent_torque_coast : g.equivalent_torque_drive;
  g.deciding_flank = coast_decides ? "other flank (reversed torque)" : "drive flank";
  g.duty_applies = std::isfinite(g.equivalent_torque);
  if (!g.duty_applies) g.duty_not_applicable = "the crank does not turn in the steady window, so no load cycles count";
}

// The reducer's ratings (sizing.reducer.*) and nominal torque; every figure of the run NaN until counted.
void takeRatings(GearDuty& g, const Scene& sc) {
  const ReducerRatings& in = sc.sizing.reducer;
  g.exponent = in.sn_exponent;
  g.assumed_application_factor = givenOrNaN(in.application_factor);
  g.rated_torque = givenOrNaN(in.rated_torque);
  g.max_torque = givenOrNaN(in.max_torque);
  g.nominal_torque = sc.reducer.ratio * sc.reducer.efficiency * nominalMotorTorque(sc, &g.nominal_source);
  g.starts_per_hour = sc.sizing.starts_per_hour;
  g.class_width = g.hour_revolutions = g.peak = g.t_peak = kNaN;
  g.equivalent_torque_drive = g.equivalent_torque_coast = g.equivalent_torque = g.application_factor = kNaN;
  g.application_ratio = g.rated_ratio = g.max_ratio = kNaN;
}

// The load spectra of the start from rest (switch-on to the start's end) and of the steady window,
// in classes of the two windows' peak torque, and the duty hour from them.
void countSpectra(GearDuty& g, const Table& ts, const SteadyState& w, const StartUp* start_up) {
  std::size_t sb = 0, se = 0, wb = 0, we = 0;
  const bool start_in_run = start_up && start_up->applicable && start_up->from_rest && start_up->start_end > start_up->t_on;
  if (start_in_run) std::tie(sb, se) = rowsOf(ts, start_up->t_on, start_up->start_end);
  if (w.reached) wb = std::min(w.row_begin, ts.rows.size()), we = std::min(w.row_end, ts.rows.size());
  peakOf(g, ts, sb, se);
  peakOf(g, ts, wb, we);
  g.class_width = std::isfinite(g.peak) && g.peak > 0 ? g.peak / kGearTorqueClasses : kNaN;
  if (!(g.class_width > 0)) {
    g.duty_not_applicable = g.start.not_applicable = g.steady.not_applicable =
        "neither a start nor a steady window with a torque to count";
    return;
  }
  if (start_in_run) g.start = loadSpectrum(ts, sb, se, g.class_width, g.exponent);
  else
    g.start.not_applicable = "the run holds no start from rest (it begins turning, initial.crank_speed): run it "
                             "from rest (initial.crank_speed: 0)";
  if (w.reached) g.steady = loadSpectrum(ts, wb, we, g.class_width, g.exponent);
  else g.steady.not_applicable = w.not_reached;
  dutyHour(g);
}

}  // namespace

double equivalentTorque(const std::vector<TorqueClass>& classes, double p, double total_cycles) {
  if (!(total_cycles > 0) || !(p > 0)) return kNaN;
  double sum = 0;
  for (const TorqueClass& c : classes) sum += c.cycles * std::pow(c.torque, p);
  return std::pow(sum / total_cycles, 1.0 / p);
}

GearSpectrum loadSpectrum(const Table& ts, std::size_t b, std::size_t e, double class_width, double p) {
  GearSpectrum s;
  e = std::min(e, ts.rows.size());
  if (e < b + 2) {
    s.not_applicable = "the window holds fewer than two output rows";
    return s;
  }
  const int it = ts.index("t"), iphi = ts.index("phi_crank"), iT = ts.index("coupling_torque");
  s.t_begin = ts.rows[b][it];
  s.t_end = ts.rows[e - 1][it];
  std::vector<double> drive, coast;
  for (std::size_t i = b + 1; i < e; ++i) {
    const auto &r0 = ts.rows[i - 1], &r1 = ts.rows[i];
    const double T = 0.5 * (r0[iT] + r1[iT]), n = std::abs(r1[iphi] - r0[iphi]) / kTwoPi;
    if (!std::isfinite(T) || !std::isfinite(n)) continue;
    s.revolutions += n;
    addCycles(T >= 0 ? drive : coast, std::abs(T), class_width, n);
  }
  s.drive = flank(drive, class_width, p, s.revolutions);
  s.coast = flank(coast, class_width, p, s.revolutions);
  s.applies = s.revolutions > 0;
  if (!s.applies) s.not_applicable = "the crank does not turn in the window, so no load cycles count";
  return s;
}

GearDuty computeGearDuty(const Scene& sc, const RunResult& run, const SteadyState& w, const StartUp* start_up) {
  GearDuty g;
  g.requested = sc.sizing.reducer.anyGiven();
  if (!g.requested) return g;
  takeRatings(g, sc);
  const Table& ts = run.timeseries;
  const std::string missing = "the run has no coupling torque or crank angle (columns coupling_torque, phi_crank)";
  g.start.not_applicable = g.steady.not_applicable = missing;
  if (!ts.has("t") || !ts.has("coupling_torque") || !ts.has("phi_crank")) {
    g.duty_not_applicable = missing;
    return g;
  }
  countSpectra(g, ts, w, start_up);
  g.application_factor = g.equivalent_torque / g.nominal_torque;
  g.application_ratio = g.application_factor / g.assumed_application_factor;
  g.rated_ratio = g.equivalent_torque / g.rated_torque;
  g.max_ratio = g.peak / g.max_torque;
  return g;
}

}  // namespace rollerdyn
