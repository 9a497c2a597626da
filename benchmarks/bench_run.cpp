// A whole 1 s run of each model on the seed 000 machine (issue #4): model building excluded,
// integration and output rows included, at the scene's accuracy 1e-6 and output step 5 ms
// (multibody RungeKuttaMerson, reduced CVODE). Starts at a running speed (10.4 rad/s) so the
// second is representative of operation, not of the start-up. Argument: number of carts n.
// The "real_time_factor" counter is simulated seconds per CPU second.
#include <benchmark/benchmark.h>

#include <cmath>

#include "multibody/MultibodySimulation.h"
#include "reduced/ReducedModel.h"
#include "support/Seed000Scene.h"

namespace {

using namespace rollerdyn;

Scene runScene(int n) {
  Scene s = test_scenes::seed000Scene();
  s.carts.count = n;
  s.carts.side.assign(n, 1);
  s.crank.offset = n > 1 ? 2.0 * M_PI / n : 0.0;
  s.motor.breakdown_torque *= std::max(1.0, n / 4.0);  // the motor grows with the machine
  s.simulation.t_end = 1.0;
  s.initial.crank_speed = 10.4;
  return s;
}

void BM_MultibodyRun1s(benchmark::State& state) {
  const MultibodyModel model(runScene(int(state.range(0))));
  double cpu = 0;
  for (auto _ : state) {
    RunResult r = simulateMultibody(model);
    cpu += r.stats.cpu_seconds;
    benchmark::DoNotOptimize(r.timeseries.rows.data());
  }
  state.counters["real_time_factor"] = cpu > 0 ? double(state.iterations()) / cpu : 0.0;
  state.counters["carts"] = double(state.range(0));
}

void BM_ReducedRun1s(benchmark::State& state) {
  const Scene scene = runScene(int(state.range(0)));
  double cpu = 0;
  for (auto _ : state) {
    RunResult r = runReducedModel(scene);
    cpu += r.stats.cpu_seconds;
    benchmark::DoNotOptimize(r.timeseries.rows.data());
  }
  state.counters["real_time_factor"] = cpu > 0 ? double(state.iterations()) / cpu : 0.0;
  state.counters["carts"] = double(state.range(0));
}

}  // namespace

BENCHMARK(BM_MultibodyRun1s)->Arg(4)->Arg(32)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ReducedRun1s)->Arg(4)->Arg(32)->Unit(benchmark::kMillisecond);
