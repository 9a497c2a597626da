// A scene built in code around a Kloss motor (ω0 = 100 rad/s, M_kr = 500 N·m, s_kr = 0.2) through
// a reducer u = 10, η = 0.9, rigid coupling, massless rods, crank at 0.5 rad: for the tests that
// judge hand-built tables with the motor law's torques (starting torque at the crank 2·500·0.2/1.04·9).
#pragma once

#include "scene/Scene.h"

namespace rollerdyn::test_scenes {

inline Scene klossMotorScene() {
  Scene s{};
  s.name = "synthetic";
  s.simulation.steady_window_revolutions = 3;
  s.motor.enabled = true;
  s.motor.omega_sync = 100;
  s.motor.breakdown_torque = 500;
  s.motor.critical_slip = 0.2;
  s.motor.rotor_inertia = 0.1;
  s.reducer.ratio = 10;
  s.reducer.efficiency = 0.9;
  s.reducer.delta = 1;
  s.rods.model = RodModel::Massless;
  s.coupling.type = CouplingType::Rigid;
  s.initial.crank_angle = 0.5;
  return s;
}

}  // namespace rollerdyn::test_scenes
