// A scene with the parameters of Loveikin, Pochka, Romasevych (2018) (four carts, Δφ = 90°, elastic coupling), built in
// code so tests of the models do not depend on the scene parser. Values and sources as in
// model/balanced-4cart.yaml; tests change single fields from here.
#pragma once

#include <cmath>

#include "scene/Scene.h"

namespace rollerdyn::test_scenes {

inline Scene loveikin2018Scene() {
  Scene s;
  s.name = "loveikin2018-test";
  s.source = "Loveikin, Pochka, Romasevych (2018) (test copy)";
  s.simulation = {2.0, 1e-6, "RungeKuttaMerson", 0.005, 1e-6, 5.0};
  s.initial = {0.0, 0.0, 0.0};
  s.crank = {0.2, M_PI / 2, 0.5, 0.0};
  s.rods = {RodModel::Distributed, 0.8, 64.0, 64.0 * 0.8 * 0.8 / 12.0};
  s.carts.count = 4;
  s.carts.side = {1, 1, 1, 1};
  s.carts.mass = 1000.0;
  s.carts.geometry = {0.27, 0.37, 0.52, 0.21, 0.22, 0.046, 0.0};
  s.motor = {true, 104.72, 517.14, 0.025 * (2.4 + std::sqrt(2.4 * 2.4 - 1.0)), 0.4};
  s.reducer = {9.8, 0.9, 0.046, 1.0};
  s.coupling = {CouplingType::Elastic, 200000.0, 8000.0, 0.32};
  s.flywheel = {0.0, FlywheelLocation::Crankshaft};
  s.loads = {7962.0, 7962.0, 9740.0, 9740.0, RollerForceDirection::AsPrinted, 0.008, 9.81, 1e-3};
  s.reduced = {KinematicsForm::Exact, ReducedIntegrator::Cvode, M_PI / 180.0};
  return s;
}

}  // namespace rollerdyn::test_scenes
