#include "analysis/Fatigue.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "analysis/RunResult.h"
#include "analysis/StartUp.h"
#include "scene/Scene.h"

namespace rollerdyn {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// The values of `column` of `table` at the rows with t_begin <= t <= t_end.
std::vector<double> windowValues(const Table& table, const std::string& column, double t_begin, double t_end) {
  std::vector<double> v;
  if (!table.has("t") || !table.has(column)) return v;
  const int it = table.index("t"), iy = table.index(column);
  for (const auto& row : table.rows)
    if (row[it] >= t_begin && row[it] <= t_end) v.push_back(row[iy]);
  return v;
}

// The columns a signal is read from: the coupling torque of the time series, or every cart's rod
// force of the reactions.
struct SignalSource {
  const Table* table = nullptr;
  std::vector<std::string> columns;
};

SignalSource sourceOf(const std::string& signal, const RunResult& run) {
  SignalSource s;
  if (signal == "coupling_torque") {
    s.table = &run.timeseries;
    if (run.timeseries.has("coupling_torque")) s.columns.push_back("coupling_torque");
  } else {
    s.table = &run.reactions;
    for (int j = 1; run.reactions.has("F_rod_" + std::to_string(j)); ++j) s.columns.push_back("F_rod_" + std::to_string(j));
  }
  return s;
}

// The damage of the window [t_begin, t_end]: the largest over the signal's columns.
void damageOver(WindowDamage& w, const SignalSource& src, const SnCurve& curve, bool haibach) {
  w.applies = true;
  w.damage = -1;
  for (const std::string& col : src.columns) {
    const MinerResult m = minerDamage(rainflow(windowValues(*src.table, col, w.t_begin, w.t_end)), curve, haibach);
    if (m.damage > w.damage) {
      w.damage = m.damage;
      w.cycles = m.cycles;
      w.top = m.top;
      w.where = col;
    }
  }
}

// The signal's words, unit, keys and S-N curve; no damage yet.
SignalFatigue describedSignal(const std::string& signal, const SnCurve& curve) {
  SignalFatigue f;
  f.signal = signal;
  const bool torque = signal == "coupling_torque";
  f.what = torque ? "coupling torque (at the crank axis)" : "rod force (the most damaged rod)";
  f.unit = torque ? "N·m" : "N";
  f.key = "sizing.fatigue." + signal + ".*";
  f.curve = curve;
  f.curve_given = curve.given();
  f.damage_per_start = f.damage_per_hour = f.starts_to_failure = f.hours_to_failure = kNaN;
  return f;
}

// What neither window can be counted without: the S-N curve, the signal in the run; "" when both are there.
std::string missingInput(const SignalFatigue& f, const SignalSource& src) {
  if (!f.curve_given) return "no S-N curve given (" + f.key + ": endurance_amplitude, knee_cycles, slope)";
  if (src.columns.empty()) return f.signal == "coupling_torque" ? "the run has no coupling torque" : "the run has no rod forces";
  return "";
}

// Why the run holds no start to count; "" when it does.
std::string startNotCounted(const StartUp* start_up) {
  if (!start_up || !start_up->applicable) return "no motor switched on in the run, so no start to count";
  if (!start_up->from_rest)
    return "the run holds no start from rest (it begins turning, initial.crank_speed): run it "
           "from rest (initial.crank_speed: 0)";
  if (!start_up->starts || start_up->still_starting || !(start_up->start_end > start_up->t_on))
    return start_up->still_starting ? "the run ended before the start settled: run longer (simulation.t_end)"
                                    : "the drive does not start (" + start_up->verdict + ")";
  return "";
}

// Why the run holds no steady window to count; "" when it does.
std::string steadyNotCounted(const SteadyState& window) {
  if (!window.reached) return window.not_reached.empty() ? "no steady window in the run" : window.not_reached;
  if (!(window.t_end > window.t_begin)) return "the steady window has no length";
  return "";
}

SignalFatigue signalFatigue(const std::string& signal, const SnCurve& curve, bool haibach, const RunResult& run,
                            const SteadyState& window, const StartUp* start_up) {
  SignalFatigue f = describedSignal(signal, curve);
  const SignalSource src = sourceOf(signal, run);
  const std::string missing = missingInput(f, src);
  // One start: from the switch-on to where the crank speed settles (StartUp::start_end).
  f.start.not_applicable = missing.empty() ? startNotCounted(start_up) : missing;
  if (f.start.not_applicable.empty()) {
    f.start.t_begin = start_up->t_on;
    f.start.t_end = start_up->start_end;
    damageOver(f.start, src, curve, haibach);
    f.damage_per_start = f.start.damage;
    f.starts_to_failure = f.start.damage > 0 ? 1.0 / f.start.damage : kInf;
  }
  // Steady running, scaled to an hour.
  f.steady.not_applicable = missing.empty() ? steadyNotCounted(window) : missing;
  if (f.steady.not_applicable.empty()) {
    f.steady.t_begin = window.t_begin;
    f.steady.t_end = window.t_end;
    damageOver(f.steady, src, curve, haibach);
    f.damage_per_hour = f.steady.damage * 3600.0 / (window.t_end - window.t_begin);
    f.hours_to_failure = f.damage_per_hour > 0 ? 1.0 / f.damage_per_hour : kInf;
  }
  return f;
}

}  // namespace

double cyclesToFailure(const SnCurve& c, bool haibach, double S) {
  if (!(S > 0)) return kInf;
  if (std::isinf(S)) return 1.0;  // beyond the ultimate value: the cycle breaks the part by itself
  if (S >= c.endurance_amplitude) return c.knee_cycles * std::pow(c.endurance_amplitude / S, c.slope);
  if (!haibach) return kInf;
  return c.knee_cycles * std::pow(c.endurance_amplitude / S, 2.0 * c.slope - 1.0);
}

double goodmanAmplitude(const SnCurve& c, double amplitude, double mean) {
  if (!(c.ultimate > 0)) return amplitude;
  const double r = std::abs(mean) / c.ultimate;
  if (r >= 1.0) return kInf;
  return amplitude / (1.0 - r);
}

MinerResult minerDamage(const std::vector<RainflowCycle>& cycles, const SnCurve& curve, bool haibach) {
  MinerResult m;
  std::vector<DamagingCycle> all;
  all.reserve(cycles.size());
  for (const RainflowCycle& c : cycles) {
    DamagingCycle d{c.range, c.mean, c.count, goodmanAmplitude(curve, 0.5 * c.range, c.mean), 0.0};
    const double N = cyclesToFailure(curve, haibach, d.amplitude_equivalent);
    d.damage = std::isinf(N) ? 0.0 : c.count / N;
    m.damage += d.damage;
    m.cycles += c.count;
    all.push_back(d);
  }
  const std::size_t k = std::min<std::size_t>(3, all.size());
  std::partial_sort(all.begin(), all.begin() + static_cast<long>(k), all.end(),
                    [](const DamagingCycle& a, const DamagingCycle& b) { return a.damage > b.damage; });
  m.top.assign(all.begin(), all.begin() + static_cast<long>(k));
  return m;
}

FatigueSizing computeFatigue(const Scene& scene, const RunResult& run, const SteadyState& window,
                             const StartUp* start_up) {
  const FatigueInputs& in = scene.sizing.fatigue;
  FatigueSizing f;
  f.required_starts = in.required_starts > 0 ? in.required_starts : kNaN;
  f.required_hours = in.required_hours > 0 ? in.required_hours : kNaN;
  const bool any_curve = in.coupling_torque.given() || in.rod_force.given();
  f.requested = any_curve || in.required_starts > 0 || in.required_hours > 0;
  if (!f.requested) return f;
  f.below_knee = in.haibach ? "Haibach's extension: slope 2m - 1 below the knee S_D"
                            : "cut-off: no damage below the knee S_D (Basquin)";
  f.mean_correction = "Goodman, S_ar = S_a/(1 - |S_m|/S_u), where S_u is given; none otherwise";
  const std::pair<const char*, const SnCurve*> signals[] = {{"coupling_torque", &in.coupling_torque},
                                                            {"rod_force", &in.rod_force}};
  for (const auto& [name, curve] : signals)
    if (curve->given() || !any_curve) f.signals.push_back(signalFatigue(name, *curve, in.haibach, run, window, start_up));
  return f;
}

}  // namespace rollerdyn
