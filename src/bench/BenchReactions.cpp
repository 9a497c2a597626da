// The reactions study of `rollerdyn bench` (BenchStudies.h): what the joint reactions cost the
// multibody model's minimal formulation, at every accuracy of the grid down to 1e-8. The two
// settings of simulation.reactions are timed alternately (with, without, with, ...) so that a
// drift of the shared machine's speed falls on both alike; the report gives the ratio of the
// medians against the target of BenchStudies.h.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "bench/BenchStudies.h"
#include "bench/BenchText.h"
#include "io/AtomicFile.h"

namespace rollerdyn::bench {

namespace {

// The accuracies of the grid down to 1e-8.
std::vector<double> reactionsGrid(bool quick) {
  std::vector<double> grid;
  for (double a : accuracyGrid(quick))
    if (a >= 0.99e-8) grid.push_back(a);
  return grid;
}

// One accuracy's runs with and without reactions, timed alternately: the first run of each
// (its outcome and counts) and the CPU times of the repetitions while both were usable.
struct AlternatePair {
  Measurement with, without;
  std::vector<double> cpu_with, cpu_without;
  bool interrupted = false;
};

AlternatePair timeAlternately(const Scene& with, const Scene& without, const SolverSetting& setting,
                              const BenchOptions& opt) {
  AlternatePair pair;
  for (int k = 0; k < std::max(1, opt.repeats); ++k) {
    if (opt.interrupt && opt.interrupt->load()) {
      pair.interrupted = true;
      return pair;
    }
    const Budget b{opt.budget, opt.interrupt};
    Measurement w = measure(with, setting, b, 1), wo = measure(without, setting, b, 1);
    if (k == 0) {
      pair.with = w;
      pair.without = wo;
    }
    if (!usable(w.outcome) || !usable(wo.outcome)) break;
    pair.cpu_with.push_back(w.cpu_seconds);
    pair.cpu_without.push_back(wo.cpu_seconds);
  }
  return pair;
}

// The measurement's CPU time the median of the repetitions `cpu` (unchanged without any).
void setMedianCpu(Measurement& m, const std::vector<double>& cpu) {
  if (cpu.empty()) return;
  m.repeats = int(cpu.size());
  m.cpu_seconds = median(cpu);
  m.cpu_min = *std::min_element(cpu.begin(), cpu.end());
  m.cpu_max = *std::max_element(cpu.begin(), cpu.end());
  m.real_time_factor = m.simulated_time / m.cpu_seconds;
}

// The row "reactions" or "no reactions" at accuracy a (x = a), logged.
void addReactionsRow(std::vector<BenchRow>& rows, double a, bool is_with, int carts, Measurement&& m,
                     const BenchOptions& opt) {
  BenchRow r;
  r.study = "reactions";
  r.variant = is_with ? "reactions" : "no reactions";
  r.x = a;
  r.carts = carts;
  r.m = std::move(m);
  r.m.run = RunResult{};
  r.error_omega = r.error_coupling = r.error_angle = NAN;
  rows.push_back(std::move(r));
  if (opt.log)
    opt.log("[reactions] accuracy " + num(a, 1) + ", " + rows.back().variant + ": " +
            toString(rows.back().m.outcome) + ", " + num(rows.back().m.cpu_seconds) + " s CPU");
}

}  // namespace

std::vector<BenchRow> runReactionsStudy(const SceneSource& source, const BenchOptions& opt) {
  std::vector<BenchRow> rows;
  for (double a : reactionsGrid(opt.quick)) {
    const SolverSetting setting{kMinimal, kMinimalIntegrator, a, 0};
    Scene with = benchScene(source.load({"simulation.reactions=true"}), opt);
    Scene without = benchScene(source.load({"simulation.reactions=false"}), opt);
    AlternatePair pair = timeAlternately(with, without, setting, opt);
    if (pair.interrupted) return rows;
    setMedianCpu(pair.with, pair.cpu_with);
    addReactionsRow(rows, a, true, with.carts.count, std::move(pair.with), opt);
    setMedianCpu(pair.without, pair.cpu_without);
    addReactionsRow(rows, a, false, with.carts.count, std::move(pair.without), opt);
  }
  return rows;
}

namespace {

// Per accuracy: both CPU times, their ratio against the target, steps and real-time factor.
std::string reactionsTable(const std::vector<BenchRow>& rows) {
  std::ostringstream os;
  os << "| accuracy | CPU with reactions [s] | CPU without [s] | ratio | steps | real-time factor with | met |\n"
     << "|---|---|---|---|---|---|---|\n";
  for (size_t i = 0; i + 1 < rows.size(); i += 2) {
    const BenchRow& w = rows[i];
    const BenchRow& wo = rows[i + 1];
    const bool ok = usable(w.m.outcome) && usable(wo.m.outcome);
    const double ratio = ok ? w.m.cpu_seconds / wo.m.cpu_seconds : NAN;
    os << "| " << num(w.x, 1) << " | " << num(w.m.cpu_seconds) << " | " << num(wo.m.cpu_seconds) << " | "
       << num(ratio) << " | " << w.m.steps << " | " << num(w.m.real_time_factor) << " | "
       << (ok ? (ratio <= kTargetReactionsCostRatio ? "yes" : "no") : "not measured") << " |\n";
  }
  return os.str();
}

}  // namespace

std::vector<std::string> writeReactionsStudy(const std::string& dir, const Scene& scene,
                                             const std::vector<BenchRow>& rows, const BenchOptions& opt) {
  writeFileAtomic(dir + "/reactions.csv", rowsCsv(rows));
  std::ostringstream os;
  os << "# What the joint reactions cost: " << scene.name << "\n\n"
     << "The multibody model's minimal formulation (" << kMinimalIntegrator << ") with simulation.reactions true "
     << "and false at each accuracy, " << num(benchScene(scene, opt).simulation.t_end)
     << " s simulated, output step " << num(scene.simulation.output_step)
     << " s. With reactions every row's reaction columns come from the O(n) inverse-dynamics pass; both settings "
        "check against Simbody's constrained solve every simulation.self_check_interval rows. The two settings "
        "are timed alternately, "
     << std::max(1, opt.repeats)
     << " pair(s); CPU is the integration loop's process CPU (median). Target: with reactions at most "
     << num(kTargetReactionsCostRatio) << "x the cost without, at every accuracy.\n\n"
     << reactionsTable(rows);
  os << "\nData: reactions.csv.\n";
  writeFileAtomic(dir + "/reactions.md", os.str());
  return {dir + "/reactions.csv", dir + "/reactions.md"};
}

}  // namespace rollerdyn::bench
