#include "bench/SetupStudy.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "io/AtomicFile.h"

namespace rollerdyn::bench {
namespace {

double median(std::vector<double> v) {
  v.erase(std::remove_if(v.begin(), v.end(), [](double x) { return !std::isfinite(x); }), v.end());
  if (v.empty()) return NAN;
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

std::string fmt(double v, const char* f = "%.3f") {
  if (!std::isfinite(v)) return "";
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

// One phase of one task: the medians of its times over the samples [s], and how many it had.
SetupRow phaseMedians(const std::vector<SetupSample>& samples, const std::string& task, const std::string& phase) {
  std::vector<double> wall, cpu, child;
  for (const SetupSample& s : samples)
    if (s.task == task)
      for (const PhaseTime& p : s.phases)
        if (p.name == phase) {
          wall.push_back(p.wall);
          cpu.push_back(p.cpu);
          child.push_back(p.child_cpu);
        }
  SetupRow r;
  r.task = task;
  r.phase = phase;
  r.repeats = int(wall.size());
  r.wall = median(wall);
  r.cpu = median(cpu);
  r.child_cpu = median(child);
  return r;
}

// A task's heading, with the sums of its phases' medians [s], and its table's header.
std::string taskHeading(const std::vector<SetupRow>& rows, const std::string& task) {
  double wall = 0, cpu = 0, child = 0;
  for (const SetupRow& q : rows)
    if (q.task == task) {
      if (std::isfinite(q.wall)) wall += q.wall;
      if (std::isfinite(q.wall) && std::isfinite(q.cpu)) cpu += q.cpu;
      if (std::isfinite(q.child_cpu)) child += q.child_cpu;
    }
  return "\n## " + task + ": " + fmt(wall) + " s wall, " + fmt(cpu) + " s CPU, " + fmt(child) +
         " s child CPU (sum of the medians)\n\n" +
         "| phase | wall [s] | CPU [s] | child CPU [s] | repetitions |\n|---|---:|---:|---:|---:|\n";
}

}  // namespace

std::vector<SetupRow> setupRows(const std::vector<SetupSample>& samples) {
  std::vector<std::pair<std::string, std::string>> keys;
  for (const SetupSample& s : samples)
    for (const PhaseTime& p : s.phases)
      if (std::find(keys.begin(), keys.end(), std::make_pair(s.task, p.name)) == keys.end())
        keys.push_back({s.task, p.name});
  std::vector<SetupRow> rows;
  for (const auto& [task, phase] : keys) rows.push_back(phaseMedians(samples, task, phase));
  return rows;
}

std::string setupCsv(const std::vector<SetupRow>& rows) {
  std::string s = "task,phase,repeats,wall_s,cpu_s,child_cpu_s\n";
  for (const SetupRow& r : rows)
    s += r.task + ",\"" + r.phase + "\"," + std::to_string(r.repeats) + "," + fmt(r.wall, "%.6f") + "," +
         fmt(r.cpu, "%.6f") + "," + fmt(r.child_cpu, "%.6f") + "\n";
  return s;
}

std::string setupReport(const std::string& scene_name, const std::vector<SetupRow>& rows, const std::string& machine) {
  std::string s = "# Where the time of a report and of a short run goes: " + scene_name + "\n\n";
  s += "Medians over the repetitions of each phase. wall: elapsed time [s]; CPU: this process's CPU time, all "
       "its threads [s]; child CPU: the CPU time of the processes it started and waited for (gnuplot, the "
       "shell of the process start) [s]. A phase whose wall time exceeds its CPU time waited: for gnuplot, or "
       "for the processor (other work on the machine). The short run integrates simulation.t_end = " +
       fmt(kSetupShortRunEnd, "%g") + " s of the scene.\n\n";
  s += "Machine: " + machine + "\n\n";
  std::string task;
  for (const SetupRow& r : rows) {
    if (r.task != task) {
      task = r.task;
      s += taskHeading(rows, task);
    }
    s += "| " + r.phase + " | " + fmt(r.wall) + " | " + fmt(r.cpu) + " | " + fmt(r.child_cpu) + " | " +
         std::to_string(r.repeats) + " |\n";
  }
  return s;
}

std::vector<std::string> writeSetupStudy(const std::string& out_dir, const std::string& scene_name,
                                         const std::vector<SetupRow>& rows, const std::string& machine) {
  writeFileAtomic(out_dir + "/setup.csv", setupCsv(rows));
  writeFileAtomic(out_dir + "/setup.md", setupReport(scene_name, rows, machine));
  return {out_dir + "/setup.csv", out_dir + "/setup.md"};
}

}  // namespace rollerdyn::bench
