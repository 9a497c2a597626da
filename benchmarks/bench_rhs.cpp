// One right-hand-side evaluation of each model (issue #4): the unit of work every integrator
// repeats. Multibody: a state realized to Acceleration after its Position (or only Velocity)
// cache is invalidated, i.e. what an integrator stage costs after changing q and u (or only u).
// Reduced: ReducedModel::derivatives (Loveikin, Pochka, Romasevych (2018) eq. (58) / Loveikin and Pochka (2007) eq. (1)). Argument: number of
// carts n (Loveikin, Pochka, Romasevych (2018) machine with the cranks spread evenly, 360°/n apart).
#include <benchmark/benchmark.h>

#include "bench_fixture.h"
#include "multibody/MultibodyModel.h"

namespace {

using namespace rollerdyn;
using namespace rollerdyn::bench_fixture;

void multibodyRhs(benchmark::State& state, SimTK::Stage invalidated) {
  const MultibodyModel model(sceneWithCarts(int(state.range(0))));
  SimTK::State s = model.assembledState(kPhi, kOmega, kTwist);
  const SimTK::MultibodySystem& system = model.system();
  for (auto _ : state) {
    s.invalidateAllCacheAtOrAbove(invalidated);
    system.realize(s, SimTK::Stage::Acceleration);
    benchmark::DoNotOptimize(s.getUDot()[0]);
  }
  state.counters["carts"] = double(state.range(0));
}

void BM_MultibodyRhsPosition(benchmark::State& state) { multibodyRhs(state, SimTK::Stage::Position); }
void BM_MultibodyRhsVelocity(benchmark::State& state) { multibodyRhs(state, SimTK::Stage::Velocity); }

void BM_ReducedRhs(benchmark::State& state) {
  const ReducedModel model(sceneWithCarts(int(state.range(0))));
  const Eigen::VectorXd y = runningState(model);
  for (auto _ : state) {
    Eigen::VectorXd d = model.derivatives(0.0, y);
    benchmark::DoNotOptimize(d.data());
  }
  state.counters["carts"] = double(state.range(0));
}

}  // namespace

BENCHMARK(BM_MultibodyRhsPosition)->Arg(1)->Arg(4)->Arg(32)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_MultibodyRhsVelocity)->Arg(1)->Arg(4)->Arg(32)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ReducedRhs)->Arg(1)->Arg(4)->Arg(32)->Unit(benchmark::kMicrosecond);
