// One output step of each model (issue #4): what the run loops do per output row on top of the
// integration. Multibody: MultibodyModel::observe (time series + joint reactions through
// calcMobilizerReactionForces) and the constraint error, on a state already realized to
// Acceleration, as MultibodySimulation's record() sees it. Reduced: ReducedModel::evaluate (the
// whole right-hand side with per-cart statics, which is what an output row is built from).
// Argument: number of carts n.
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

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

constexpr double kPhi = 0.3, kOmega = 10.4, kTwist = 1e-3;

void BM_MultibodyOutputStep(benchmark::State& state) {
  const MultibodyModel model(sceneWithCarts(int(state.range(0))));
  const SimTK::State s = model.assembledState(kPhi, kOmega, kTwist);  // realized to Acceleration
  std::vector<double> ts, re;
  for (auto _ : state) {
    model.observe(s, ts, re);
    benchmark::DoNotOptimize(model.constraintError(s));
    benchmark::DoNotOptimize(re.data());
  }
  state.counters["carts"] = double(state.range(0));
}

void BM_ReducedOutputStep(benchmark::State& state) {
  const ReducedModel model(sceneWithCarts(int(state.range(0))));
  Eigen::VectorXd y = model.initialState();
  y(model.iPhi()) = kPhi;
  y(model.iOmega()) = kOmega;
  y(model.iTwist()) = kTwist;
  for (auto _ : state) {
    ModelEvaluation e = model.evaluate(y);
    benchmark::DoNotOptimize(e.carts.data());
  }
  state.counters["carts"] = double(state.range(0));
}

}  // namespace

BENCHMARK(BM_MultibodyOutputStep)->Arg(1)->Arg(4)->Arg(32)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ReducedOutputStep)->Arg(1)->Arg(4)->Arg(32)->Unit(benchmark::kMicrosecond);
