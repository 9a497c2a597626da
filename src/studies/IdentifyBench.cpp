#include "studies/IdentifyBench.h"

#include <algorithm>
#include <chrono>
#include <ctime>
#include <sstream>

#include "io/AtomicFile.h"
#include "io/FieldFormat.h"
#include "scene/SceneSchema.h"
#include "studies/Identify.h"
#include "studies/SyntheticMeasurements.h"

namespace rollerdyn {
namespace {

struct BenchCase {
  std::string name, model;
  std::vector<std::string> sets, signals;
  double t_end;  // [s]
};

// The benches' median: the mean of the two middle values for an even count (bench/BenchRun.cpp's
// rule, which this layer cannot call).
double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n == 0 ? 0.0 : n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

double processCpu() { return double(std::clock()) / CLOCKS_PER_SEC; }

// The case's measurement (a run of the model with the true values, noise of seed 1) and the fit's options.
IdentifyOptions benchCaseFit(const std::string& scene_path, const std::vector<std::string>& overrides,
                             const BenchCase& bc, const std::atomic<bool>* interrupt) {
  std::vector<std::string> sets = overrides;
  sets.insert(sets.end(), bc.sets.begin(), bc.sets.end());
  const RunResult run = truthRun(scene_path, couplingCaseTruth(sets), bc.t_end, 0.005, bc.model);
  IdentifyOptions o = couplingCaseFit(scene_path, bc.model, sets);
  o.interrupt = interrupt;
  o.data = measureRun(run, bc.signals, kCouplingCaseNoise, 1);
  return o;
}

IdentifyBenchRow benchRowOf(const BenchCase& bc) {
  IdentifyBenchRow row;
  row.name = bc.name;
  row.model = bc.model;
  for (std::size_t i = 0; i < bc.signals.size(); ++i) row.signals += (i ? "," : "") + bc.signals[i];
  row.c_true = kCouplingCaseStiffness;
  row.k_true = kCouplingCaseDamping;
  return row;
}

// An identification's result into the row (the last repetition's).
void recordResult(const IdentifyResult& res, IdentifyBenchRow& row) {
  row.samples = int(res.t.size());
  row.runs = res.runs;
  row.iterations = res.iterations;
  row.converged = res.converged;
  row.c = res.keys.at(0).value;
  row.c_std = res.keys.at(0).std;
  row.k = res.keys.at(1).value;
  row.k_std = res.keys.at(1).std;
}

// The identification repeated and timed (wall and this process's CPU); the medians into the row.
void timeRepetitions(const IdentifyOptions& o, int repeats, const std::atomic<bool>* interrupt,
                     const std::function<void(const std::string&)>& log, IdentifyBenchRow& row) {
  std::vector<double> walls, cpus;
  for (int r = 0; r < repeats && !(interrupt && *interrupt); ++r) {
    const auto w0 = std::chrono::steady_clock::now();
    const double c0 = processCpu();
    const IdentifyResult res = runIdentify(o);
    cpus.push_back(processCpu() - c0);
    walls.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count());
    recordResult(res, row);
    if (log)
      log("identify bench: " + row.name + ", repetition " + std::to_string(r + 1) + ": " + significant(walls.back(), 3) +
          " s wall, " + significant(cpus.back(), 3) + " s CPU, " + std::to_string(res.runs) + " runs");
  }
  row.repeats = int(walls.size());
  row.wall = median(walls);
  row.cpu = median(cpus);
}

}  // namespace

std::vector<IdentifyBenchRow> runIdentifyBench(const std::string& scene_path, const std::vector<std::string>& overrides,
                                               int repeats,
                                               const std::atomic<bool>* interrupt,
                                               const std::function<void(const std::string&)>& log) {
  const std::vector<BenchCase> cases = {
      {"coupling c and k, reduced model, a 2.5 s start", "reduced", {}, {"omega_crank", "omega_motor"}, 2.5},
      {"coupling c and k, multibody model, catalogue motor, a 3 s start", "multibody", {"motor.model=circuit"},
       {"omega_crank", "omega_motor", "stator_current"}, 3.0}};
  std::vector<IdentifyBenchRow> rows;
  for (const BenchCase& bc : cases) {
    const IdentifyOptions o = benchCaseFit(scene_path, overrides, bc, interrupt);
    IdentifyBenchRow row = benchRowOf(bc);
    timeRepetitions(o, repeats, interrupt, log, row);
    if (row.repeats > 0) rows.push_back(row);
  }
  return rows;
}

namespace {

std::string benchCsvRow(const IdentifyBenchRow& r) {
  std::ostringstream csv;
  csv << '"' << r.name << "\"," << r.model << ",\"" << r.signals << "\"," << r.samples << ',' << r.repeats << ','
      << significant(r.wall, 4) << ',' << significant(r.cpu, 4) << ',' << r.runs << ',' << r.iterations << ','
      << (r.converged ? "yes" : "no") << ',' << significant(r.c, 6) << ',' << significant(r.c_std, 3) << ','
      << formatNumber(r.c_true) << ',' << significant(r.k, 6) << ',' << significant(r.k_std, 3) << ','
      << formatNumber(r.k_true) << '\n';
  return csv.str();
}

std::string benchTableRow(const IdentifyBenchRow& r) {
  std::ostringstream md;
  md << "| " << r.name << " | " << r.signals << " | " << r.samples << " | " << r.runs << " | " << r.iterations
     << " | " << significant(r.wall, 3) << " | " << significant(r.cpu, 3) << " | "
     << significant(r.runs > 0 ? 1000 * r.cpu / r.runs : 0.0, 3) << " | " << significant(r.c, 6) << " ± "
     << significant(r.c_std, 2) << " | " << significant(r.k, 5) << " ± " << significant(r.k_std, 2) << " |\n";
  return md.str();
}

// identify.md up to its table's header: what was measured and how, on which machine.
std::string benchPageHead(const std::string& scene_name, const std::string& machine) {
  std::ostringstream md;
  md << "# What an identification costs: " << scene_name << "\n\n"
     << "`rollerdyn bench " << scene_name << " --study identify`: the coupling's stiffness c and damping k "
     << "identified (`rollerdyn identify`, docs/identify.md) from a start of the scene made by the model itself with "
     << "c = " << formatNumber(kCouplingCaseStiffness) << " N·m/rad and k = " << formatNumber(kCouplingCaseDamping)
     << " N·m·s/rad, every output row measured with Gaussian noise of 0.2 % of the signal's RMS value (seed 1); "
        "the search starts from the scene's values, the runs of a Jacobian on 2 threads. Medians over the "
        "repetitions; CPU is this process's, all its threads.\n\n"
     << machine << "\n\n"
     << "| case | signals | samples | runs | iterations | wall [s] | CPU [s] | CPU per run [ms] | c ± σ [N·m/rad] | "
        "k ± σ [N·m·s/rad] |\n|---|---|---|---|---|---|---|---|---|---|\n";
  return md.str();
}

}  // namespace

std::vector<std::string> writeIdentifyBench(const std::string& out_dir, const std::string& scene_name,
                                            const std::vector<IdentifyBenchRow>& rows, const std::string& machine) {
  std::string csv = "case,model,signals,samples,repeats,wall[s],cpu[s],runs,iterations,converged,"
                    "c[N*m/rad],c_std[N*m/rad],c_true[N*m/rad],k[N*m*s/rad],k_std[N*m*s/rad],k_true[N*m*s/rad]\n";
  std::string md = benchPageHead(scene_name, machine);
  for (const IdentifyBenchRow& r : rows) {
    csv += benchCsvRow(r);
    md += benchTableRow(r);
  }
  md += "\nThe runs dominate: an identification costs its runs (the Jacobian's forward differences, two per "
        "iteration for two keys, the central differences at the estimate and the hold-out run) times the cost of "
        "one run at accuracy 1e-8.\n";
  const std::string csv_path = out_dir + "/identify.csv", md_path = out_dir + "/identify.md";
  writeFileAtomic(csv_path, csv);
  writeFileAtomic(md_path, md);
  return {csv_path, md_path};
}

}  // namespace rollerdyn
