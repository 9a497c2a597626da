// One output step of each model: what the run loops do per output row on top of the
// integration. Multibody: MultibodyModel::observe (time series + joint reactions through
// calcMobilizerReactionForces) and the constraint error, on a state already realized to
// Acceleration, as MultibodySimulation's record() sees it. Reduced: ReducedModel::evaluate (the
// whole right-hand side with per-cart statics, which is what an output row is built from).
// Argument: number of carts n.
#include <benchmark/benchmark.h>

#include <vector>

#include "bench_fixture.h"
#include "multibody/MultibodyModel.h"

namespace {

using namespace rollerdyn;
using namespace rollerdyn::bench_fixture;

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
  const Eigen::VectorXd y = runningState(model);
  for (auto _ : state) {
    ModelEvaluation e = model.evaluate(y);
    benchmark::DoNotOptimize(e.carts.data());
  }
  state.counters["carts"] = double(state.range(0));
}

}  // namespace

BENCHMARK(BM_MultibodyOutputStep)->Arg(1)->Arg(4)->Arg(32)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ReducedOutputStep)->Arg(1)->Arg(4)->Arg(32)->Unit(benchmark::kMicrosecond);
