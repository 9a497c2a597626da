// The machine and the running state the hot-path benchmarks share (bench_rhs, bench_output,
// bench_run), so their timings describe the same work and compare across files.
#pragma once

#include <cmath>

#include "reduced/ReducedModel.h"
#include "support/Loveikin2018Scene.h"

namespace rollerdyn::bench_fixture {

// The Loveikin, Pochka, Romasevych (2018) machine with n carts on one side, cranks spread evenly (360°/n apart),
// in the equations the benchmarks have timed: the multibody model's constrained formulation with the
// lagged guide-friction normals, the reduced model's quasi-static guide normals (not the defaults).
inline Scene sceneWithCarts(int n) {
  Scene s = test_scenes::loveikin2018Scene();
  s.simulation.formulation = Formulation::Constrained;
  s.loads.guide_normal_force = GuideNormalForce::Lagged;
  s.reduced.guide_normals = ReducedGuideNormals::QuasiStatic;
  s.carts.count = n;
  s.carts.side.assign(n, 1);
  s.crank.offset = n > 1 ? 2.0 * M_PI / n : 0.0;
  return s;
}

// A running state: crank at 0.3 rad, near synchronous speed (motor slip ~2 %), small twist.
constexpr double kPhi = 0.3, kOmega = 10.4, kTwist = 1e-3;

// The reduced model's state vector at that running state.
inline Eigen::VectorXd runningState(const ReducedModel& model) {
  Eigen::VectorXd y = model.initialState();
  y(model.iPhi()) = kPhi;
  y(model.iOmega()) = kOmega;
  y(model.iTwist()) = kTwist;
  return y;
}

}  // namespace rollerdyn::bench_fixture
