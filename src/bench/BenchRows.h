// A bench study's rows as they are run (BenchStudies.h): made from a measurement, finished with
// their errors against the model's reference, logged one line each. Internal to src/bench.
#pragma once

#include <string>

#include "bench/BenchStudies.h"

namespace rollerdyn::bench {

// Ctrl-C asked the bench to stop.
bool stopRequested(const BenchOptions& o);

// One line per run to opt.log: the setting, outcome, CPU time and errors (index: the row's number).
void logRow(const BenchOptions& opt, const BenchRow& r, size_t index);

// Fills the errors against `ref` (a usable reference timeseries, or nullptr) and drops the
// row's tables.
void finishRow(BenchRow& r, const Table* ref);

BenchRow makeRow(const std::string& study, const std::string& variant, double x, const Scene& scene, Measurement m);

}  // namespace rollerdyn::bench
