#include "bench/BenchRun.h"


#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "io/ChildProcess.h"
#include "multibody/MultibodySimulation.h"
#include "reduced/ReducedModel.h"

namespace rollerdyn::bench {

std::string SolverSetting::label() const {
  std::ostringstream os;
  os << model << ' ' << integrator << ' ';
  if (integrator == "baranov") {
    os << baranov_step * 180.0 / M_PI << " deg";
  } else {
    os.precision(3);
    os << accuracy;
  }
  return os.str();
}

const char* toString(Outcome o) {
  switch (o) {
    case Outcome::Ok: return "ok";
    case Outcome::Stalled: return "stalled";
    case Outcome::Timeout: return "timeout";
    case Outcome::Failed: return "failed";
    case Outcome::Interrupted: return "interrupted";
  }
  return "?";
}

namespace {

void applyConstrained(Scene& s, const SolverSetting& setting) {
  s.simulation.formulation = Formulation::Constrained;
  // The constrained formulation can only carry the lagged guide-friction law (GuideFriction.h).
  s.loads.guide_normal_force = GuideNormalForce::Lagged;
  s.simulation.integrator = setting.integrator;
  s.simulation.accuracy = setting.accuracy;
  s.simulation.constraint_tolerance = setting.accuracy;
}

void applyMinimal(Scene& s, const SolverSetting& setting) {
  if (setting.integrator != kMinimalIntegrator)
    throw std::invalid_argument(std::string("bench: the multibody model's minimal formulation integrates with ") +
                                kMinimalIntegrator + ", got '" + setting.integrator + "'");
  s.simulation.formulation = Formulation::Minimal;
  s.simulation.accuracy = setting.accuracy;
  s.simulation.constraint_tolerance = setting.accuracy;
}

void applyReduced(Scene& s, const SolverSetting& setting) {
  if (setting.integrator == "cvode") {
    s.reduced.integrator = ReducedIntegrator::Cvode;
    s.simulation.accuracy = setting.accuracy;
  } else if (setting.integrator == "baranov") {
    s.reduced.integrator = ReducedIntegrator::Baranov;
    s.reduced.baranov_step = setting.baranov_step;
  } else {
    throw std::invalid_argument("bench: reduced model integrator must be cvode or baranov, got '" +
                                setting.integrator + "'");
  }
}

}  // namespace

Scene applySetting(const Scene& base, const SolverSetting& setting) {
  Scene s = base;
  if (setting.model == "multibody")
    applyConstrained(s, setting);
  else if (setting.model == kMultibodyMinimal)
    applyMinimal(s, setting);
  else if (setting.model == "reduced")
    applyReduced(s, setting);
  else
    throw std::invalid_argument("bench: model must be multibody, multibody-minimal or reduced, got '" +
                                setting.model + "'");
  return s;
}

namespace {

double cpuNow() { return double(std::clock()) / CLOCKS_PER_SEC; }

// Runs shorter than this much CPU are timed as the mean of repetitions (see runIsolated).
constexpr double kMinTimedCpu = 0.2;  // [s]

struct OneRun {
  RunResult run;
  Outcome outcome = Outcome::Failed;
  std::string status;
  double cpu_with_setup = NAN;  // CPU of building the model and running it [s]
};

// A run within the CPU budget: the multibody model stopped between output rows once the budget
// is spent (or at Ctrl-C), the reduced model judged by its loop CPU afterwards.
struct BudgetedRun {
  RunResult run;
  bool over_budget = false, user_stop = false;
};

BudgetedRun runWithinBudget(const Scene& s, const SolverSetting& setting, const Budget& budget) {
  BudgetedRun b;
  if (setting.model == "multibody" || setting.model == kMultibodyMinimal) {
    std::atomic<bool> stop{false};
    const double c0 = cpuNow();
    RunControl control;
    control.interrupt = &stop;
    control.progress = [&](double, double) {
      if (budget.interrupt && budget.interrupt->load()) {
        b.user_stop = true;
        stop = true;
      } else if (cpuNow() - c0 > budget.cpu_seconds) {
        b.over_budget = true;
        stop = true;
      }
    };
    b.run = runMultibodyModel(s, control);
  } else {
    b.run = runReducedModel(s);
    b.over_budget = b.run.stats.cpu_seconds > budget.cpu_seconds;
  }
  return b;
}

// The run's outcome: interrupted, timeout (status says so), ok, stalled or failed.
void judgeRun(OneRun& r, bool over_budget, bool user_stop, const Budget& budget) {
  const RunStats& st = r.run.stats;
  r.status = st.status;
  if (user_stop) {
    r.outcome = Outcome::Interrupted;
  } else if (over_budget) {
    r.outcome = Outcome::Timeout;
    std::ostringstream os;
    os << "timeout: CPU budget " << budget.cpu_seconds << " s exceeded";
    if (!st.complete) os << " (" << st.status << ")";
    r.status = os.str();
  } else if (st.complete) {
    r.outcome = Outcome::Ok;
  } else if (st.status.find("motor stalled") != std::string::npos) {
    r.outcome = Outcome::Stalled;
  } else {
    r.outcome = Outcome::Failed;
  }
}

OneRun runOnce(const Scene& scene, const SolverSetting& setting, const Budget& budget) {
  OneRun r;
  const double c_setup = cpuNow();
  try {
    const Scene s = applySetting(scene, setting);
    BudgetedRun b = runWithinBudget(s, setting, budget);
    r.run = std::move(b.run);
    r.cpu_with_setup = cpuNow() - c_setup;
    judgeRun(r, b.over_budget, b.user_stop, budget);
  } catch (const std::exception& ex) {
    r.outcome = Outcome::Failed;
    r.status = std::string("failed: ") + ex.what();
    r.run.stats.cpu_seconds = NAN;  // nothing was integrated
  }
  return r;
}

double timeReached(const RunResult& run) {
  const Table& t = run.timeseries;
  if (t.rows.empty() || !t.has("t")) return 0.0;
  return t.rows.back()[t.index("t")];
}

// --- One repetition in a child process --------------------------------------------------------
// RunControl.progress is only called between output rows, and an integrator that collapses its
// step (e.g. Verlet or ExplicitEuler at a tight accuracy) can spend minutes inside ONE output
// interval: Simbody's stepTo() only returns at the output time or after its internal step limit.
// So each repetition runs in a fork()ed child with a hard CPU limit (RLIMIT_CPU, SIGXCPU then
// SIGKILL) above the budget; the progress check stays the graceful path that keeps the time
// reached. A crash (SIGSEGV, abort) is contained the same way and becomes a "failed" row. The
// child sends its result back through a pipe as text (outcome, status, statistics, timeseries).

std::string oneLine(std::string s) {
  for (char& c : s)
    if (c == '\n' || c == '\r') c = ' ';
  return s;
}

std::string serialize(const OneRun& r) {
  std::ostringstream os;
  os.precision(17);
  const RunStats& st = r.run.stats;
  os << int(r.outcome) << '\n' << oneLine(r.status) << '\n' << st.steps << ' ' << st.realizations << ' '
     << st.cpu_seconds << ' ' << st.constraint_error_max << ' ' << r.run.energy.residualRelative() << ' '
     << r.cpu_with_setup << '\n';
  const Table& t = r.run.timeseries;
  os << t.columns.size() << ' ' << t.rows.size() << '\n';
  for (const std::string& c : t.columns) os << c << '\n';
  for (const auto& row : t.rows) {
    for (size_t i = 0; i < row.size(); ++i) os << (i ? " " : "") << row[i];
    os << '\n';
  }
  return os.str();
}

// A double as a token through strtod: operator>> rejects "nan" and "inf".
bool readNumber(std::istream& in, double& v) {
  std::string tok;
  if (!(in >> tok)) return false;
  v = std::strtod(tok.c_str(), nullptr);  // reads "nan" and "inf" too
  return true;
}

// The timeseries' column names, one a line, then its rows; false when cut short.
bool readTimeseries(std::istream& in, size_t ncols, size_t nrows, Table& t) {
  t.columns.resize(ncols);
  for (auto& c : t.columns)
    if (!std::getline(in, c)) return false;
  t.rows.assign(nrows, std::vector<double>(ncols));
  for (auto& row : t.rows)
    for (double& v : row)
      if (!readNumber(in, v)) return false;
  return true;
}

// Fills r from the child's text; false when the text is incomplete (the child died mid-write).
bool deserialize(const std::string& text, OneRun& r, double& energy_rel) {
  std::istringstream in(text);
  int outcome = 0;
  if (!(in >> outcome)) return false;
  in.ignore(1);
  std::getline(in, r.status);
  RunStats& st = r.run.stats;
  size_t ncols = 0, nrows = 0;
  if (!(in >> st.steps >> st.realizations) || !readNumber(in, st.cpu_seconds) ||
      !readNumber(in, st.constraint_error_max) || !readNumber(in, energy_rel) || !readNumber(in, r.cpu_with_setup) ||
      !(in >> ncols >> nrows))
    return false;
  in.ignore(1);
  if (!readTimeseries(in, ncols, nrows, r.run.timeseries)) return false;
  r.outcome = Outcome(outcome);
  return true;
}

// Process CPU time is accounted in scheduler ticks (milliseconds on this kind of VM), so a run
// of a few milliseconds (the reduced model) reads 0 or one tick. Short usable runs are
// therefore repeated until kMinTimedCpu of CPU has accumulated; cpu_seconds is the mean of the
// repetitions' loop CPU, cpu_with_setup the mean of their whole CPU (model building included).
void repeatShortRun(OneRun& first, const Scene& scene, const SolverSetting& setting, const Budget& budget) {
  const double c = first.run.stats.cpu_seconds;
  if (!((first.outcome == Outcome::Ok || first.outcome == Outcome::Stalled) && c < kMinTimedCpu)) return;
  const double c0 = cpuNow();
  int n = 0;
  double loop = 0.0;
  while (cpuNow() - c0 < kMinTimedCpu && n < 100000) {
    loop += runOnce(scene, setting, budget).run.stats.cpu_seconds;
    ++n;
  }
  first.run.stats.cpu_seconds = loop / n;
  first.cpu_with_setup = (cpuNow() - c0) / n;
}

// The row of a child that did not report: stopped by the hard CPU limit, interrupted or crashed.
OneRun unreportedRun(const ChildOutcome& child, const Budget& budget) {
  OneRun r;
  r.run.stats.cpu_seconds = NAN;  // spent, but not reported by the killed process
  std::ostringstream os;
  if (child.stoppedByCpuLimit()) {
    r.outcome = Outcome::Timeout;
    os << "timeout: CPU budget " << budget.cpu_seconds
       << " s exceeded inside one output interval (stopped by the hard CPU limit)";
  } else if (child.killedBy(SIGINT)) {
    r.outcome = Outcome::Interrupted;
    os << "interrupted";
  } else {
    r.outcome = Outcome::Failed;
    os << "failed: run process ended abnormally (" << child.howItEnded() << ")";
  }
  r.status = os.str();
  return r;
}

OneRun runIsolated(const Scene& scene, const SolverSetting& setting, const Budget& budget, double& energy_rel) {
  const long soft = long(std::ceil(1.5 * budget.cpu_seconds + 2.0));
  const std::optional<ChildOutcome> child = runInChild(soft, soft + 2, [&] {
    OneRun first = runOnce(scene, setting, budget);
    repeatShortRun(first, scene, setting, budget);
    return serialize(first);
  });
  OneRun r;
  if (!child) {  // no isolation available: run in this process
    r = runOnce(scene, setting, budget);
    energy_rel = r.run.energy.residualRelative();
    return r;
  }
  if (child->exitedCleanly() && deserialize(child->text, r, energy_rel)) return r;
  energy_rel = NAN;
  return unreportedRun(*child, budget);
}

}  // namespace

namespace {

// The first repetition gives the measurement its outcome, counts and tables.
void takeFirstRun(Measurement& m, OneRun& r, double energy_rel) {
  m.outcome = r.outcome;
  m.status = r.status;
  m.steps = r.run.stats.steps;
  m.realizations = r.run.stats.realizations;
  m.simulated_time = timeReached(r.run);
  m.energy_residual_rel = energy_rel;
  m.constraint_error_max = r.run.stats.constraint_error_max;
  m.run = std::move(r.run);
}

// The median, least and largest loop CPU of the repetitions, and the median CPU with set-up.
void setCpuStatistics(Measurement& m, const std::vector<double>& cpu, const std::vector<double>& cpu_setup) {
  m.repeats = int(cpu.size());
  m.cpu_seconds = median(cpu);
  m.cpu_min = *std::min_element(cpu.begin(), cpu.end());
  m.cpu_max = *std::max_element(cpu.begin(), cpu.end());
  m.cpu_with_setup = median(cpu_setup);
  m.real_time_factor = m.cpu_seconds > 0 ? m.simulated_time / m.cpu_seconds : NAN;
}

}  // namespace

Measurement measure(const Scene& scene, const SolverSetting& setting, const Budget& budget,
                    int repeats) {
  Measurement m;
  m.setting = setting;
  std::vector<double> cpu, cpu_setup;
  for (int k = 0; k < std::max(repeats, 1); ++k) {
    double energy_rel = NAN;
    OneRun r = runIsolated(scene, setting, budget, energy_rel);
    const bool usable = r.outcome == Outcome::Ok || r.outcome == Outcome::Stalled;
    if (k == 0) {
      takeFirstRun(m, r, energy_rel);
      cpu.push_back(m.run.stats.cpu_seconds);
      cpu_setup.push_back(r.cpu_with_setup);
      if (!usable) break;  // a timeout or failure is not repeated
    } else {
      if (!usable) break;  // e.g. Ctrl-C during a repetition: keep what was timed
      cpu.push_back(r.run.stats.cpu_seconds);
      cpu_setup.push_back(r.cpu_with_setup);
    }
  }
  setCpuStatistics(m, cpu, cpu_setup);
  return m;
}

namespace {

// max_i |X_i - X_ref,i| over the rows of `run` matching a row of `ref` in time; NaN when none match.
double maxDifference(const Table& run, const Table& ref, const std::string& column) {
  if (!run.has(column) || !ref.has(column) || !run.has("t") || !ref.has("t")) return NAN;
  const int c = run.index(column), cr = ref.index(column);
  const int t = run.index("t"), tr = ref.index("t");
  double worst = 0.0;
  size_t matched = 0, j = 0;
  for (const auto& row : run.rows) {
    // Both tables are sorted in time: advance the reference cursor to this row's time.
    while (j < ref.rows.size() && ref.rows[j][tr] < row[t] - 1e-9) ++j;
    if (j == ref.rows.size()) break;
    if (std::abs(ref.rows[j][tr] - row[t]) > 1e-9) continue;
    const double d = std::abs(row[c] - ref.rows[j][cr]);
    if (!std::isfinite(d)) return NAN;
    worst = std::max(worst, d);
    ++matched;
  }
  return matched ? worst : NAN;
}

}  // namespace

double relativeMaxError(const Table& run, const Table& ref, const std::string& column) {
  if (!run.has(column) || !ref.has(column)) return NAN;
  const int cr = ref.index(column);
  double scale = 0.0;
  for (const auto& row : ref.rows) scale = std::max(scale, std::abs(row[cr]));
  if (!(scale > 0.0)) return NAN;
  return maxDifference(run, ref, column) / scale;
}

double absoluteMaxError(const Table& run, const Table& ref, const std::string& column) {
  return maxDifference(run, ref, column);
}

double median(std::vector<double> v) {
  if (v.empty()) return NAN;
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace rollerdyn::bench
