// `rollerdyn bench --study setup`: where the seconds of a report and of a short run go. The
// command (cli/BenchCommand.cpp) times each repetition's phases (io/PhaseClock.h); this file takes
// their medians and writes setup.csv and setup.md.
//
//   process start   `rollerdyn --version` started through a shell: exec, dynamic loading of the
//                   shared libraries, static initialisation
//   short run       scene file, multibody model set-up and integration (the integration's own CPU
//                   time beside it), summary and files, at simulation.t_end = kSetupShortRunEnd
//   report          `rollerdyn report` on the scene: run, modal analysis (steady motion and Floquet
//                   multipliers of both models, Campbell diagram, stability charts, order
//                   spectrum), summary and files, figures (gnuplot), page
#pragma once

#include <string>
#include <vector>

#include "io/PhaseClock.h"

namespace rollerdyn::bench {

constexpr double kSetupShortRunEnd = 0.05;  // [s] simulated time of the short run

// One timed repetition of one task ("process start", "short run", "report").
struct SetupSample {
  std::string task;
  std::vector<PhaseTime> phases;
};

// Median over the repetitions of each (task, phase), in the order first seen; NaN stays NaN
// (a phase without a wall time of its own).
struct SetupRow {
  std::string task, phase;
  int repeats = 0;
  double wall = 0, cpu = 0, child_cpu = 0;  // medians [s]
};
std::vector<SetupRow> setupRows(const std::vector<SetupSample>& samples);

std::string setupCsv(const std::vector<SetupRow>& rows);
// `machine`: a line on the machine and its load while timed.
std::string setupReport(const std::string& scene_name, const std::vector<SetupRow>& rows, const std::string& machine);
std::vector<std::string> writeSetupStudy(const std::string& out_dir, const std::string& scene_name,
                                         const std::vector<SetupRow>& rows, const std::string& machine);

}  // namespace rollerdyn::bench
