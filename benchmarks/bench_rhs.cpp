// One right-hand-side evaluation of each model (issue #4): the unit of work every integrator
// repeats. Multibody: a state realized to Acceleration after its Position (or only Velocity)
// cache is invalidated, i.e. what an integrator stage costs after changing q and u (or only u).
// Reduced: ReducedModel::derivatives (seed 000 eq. (58) / seed 004 eq. (1)). Argument: number of
// carts n (seed 000 machine with the cranks spread evenly, 360°/n apart).
#include <benchmark/benchmark.h>

#include <cmath>

#include "multibody/MultibodyModel.h"
#include "reduced/ReducedModel.h"
#include "support/Seed000Scene.h"

namespace {

using namespace rollerdyn;

Scene sceneWithCarts(int n) {
  Scene s = test_scenes::seed000Scene();
  s.carts.count = n;
  s.carts.side.assign(n, 1);
  s.crank.offset = n > 1 ? 2.0 * M_PI / n : 0.0;
  return s;
}

// A running state: crank at 0.3 rad, near synchronous speed (motor slip ~2 %), small twist.
constexpr double kPhi = 0.3, kOmega = 10.4, kTwist = 1e-3;

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
  Eigen::VectorXd y = model.initialState();
  y(model.iPhi()) = kPhi;
  y(model.iOmega()) = kOmega;
  y(model.iTwist()) = kTwist;
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
