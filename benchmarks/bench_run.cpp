// A whole 1 s run of each model on the Loveikin, Pochka, Romasevych (2018) machine: model building excluded,
// integration and output rows included, at the scene's accuracy 1e-6 and output step 5 ms
// (multibody RungeKuttaMerson, reduced CVODE). Starts at a running speed (10.4 rad/s) so the
// second is representative of operation, not of the start-up. Argument: number of carts n.
// The "real_time_factor" counter is simulated seconds per CPU second.
#include <benchmark/benchmark.h>

#include <algorithm>

#include "bench_fixture.h"
#include "multibody/MultibodyModel.h"
#include "multibody/MultibodySimulation.h"

namespace {

using namespace rollerdyn;
using namespace rollerdyn::bench_fixture;

Scene runScene(int n) {
  Scene s = sceneWithCarts(n);
  s.motor.breakdown_torque *= std::max(1.0, n / 4.0);  // the motor grows with the machine
  s.simulation.t_end = 1.0;
  s.initial.crank_speed = kOmega;
  return s;
}

// One whole run per iteration. The real-time factor counts the runs' own CPU time
// (RunStats::cpu_seconds), not the benchmark's clock; a run is 1 s, so it is runs per CPU second.
template <class Run>
void timeRuns(benchmark::State& state, Run run) {
  double cpu = 0;
  for (auto _ : state) {
    RunResult r = run();
    cpu += r.stats.cpu_seconds;
    benchmark::DoNotOptimize(r.timeseries.rows.data());
  }
  state.counters["real_time_factor"] = cpu > 0 ? double(state.iterations()) / cpu : 0.0;
  state.counters["carts"] = double(state.range(0));
}

void BM_MultibodyRun1s(benchmark::State& state) {
  const MultibodyModel model(runScene(int(state.range(0))));
  timeRuns(state, [&] { return simulateMultibody(model); });
}

void BM_ReducedRun1s(benchmark::State& state) {
  const Scene scene = runScene(int(state.range(0)));
  timeRuns(state, [&] { return runReducedModel(scene); });
}

}  // namespace

BENCHMARK(BM_MultibodyRun1s)->Arg(4)->Arg(32)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ReducedRun1s)->Arg(4)->Arg(32)->Unit(benchmark::kMillisecond);
