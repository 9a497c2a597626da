// One right-hand-side evaluation of each model: the unit of work every integrator
// repeats. Multibody: a state realized to Acceleration after its Position (or only Velocity)
// cache is invalidated, i.e. what an integrator stage costs after changing q and u (or only u).
// Reduced: ReducedModel::derivatives (Loveikin, Pochka, Romasevych (2018) eq. (58) / Loveikin and Pochka (2007) eq. (1)). Argument: number of
// carts n (Loveikin, Pochka, Romasevych (2018) machine with the cranks spread evenly, 360°/n apart).
#include <benchmark/benchmark.h>

#include "bench_fixture.h"
#include "multibody/MinimalCoordinates.h"
#include "multibody/MinimalDynamics.h"
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

// The minimal formulation's right-hand side (README "Multibody formulations"): all q and u from
// the closed forms, realization to Velocity, applied forces summed, projected equations, guide-reaction pass.
void BM_MinimalRhs(benchmark::State& state) {
  const MultibodyModel model(sceneWithCarts(int(state.range(0))));
  SimTK::State s = model.assembledState(kPhi, kOmega, kTwist);
  MinimalCoordinates coords(model, s);
  MinimalDynamics dyn(model, s);
  IndependentState x = coords.extract(s);
  for (auto _ : state) {
    coords.apply(0.0, x, s);
    dyn.evaluate(s, coords);
    benchmark::DoNotOptimize(dyn.guideNormals(s)[0]);
  }
  state.counters["carts"] = double(state.range(0));
}

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
BENCHMARK(BM_MinimalRhs)->Arg(1)->Arg(4)->Arg(32)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ReducedRhs)->Arg(1)->Arg(4)->Arg(32)->Unit(benchmark::kMicrosecond);
