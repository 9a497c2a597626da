// A seed-000-like Scene built in code (the YAML parser is another engineer's area).
// Declared in each test file as `rollerdyn::test::seed000LikeScene()`.
#include <cmath>

#include "scene/Scene.h"

namespace rollerdyn {
namespace test {

Scene seed000LikeScene() {
  Scene s;
  s.name = "seed000-like";
  s.source = "seed 000 (four carts, elastic drive), parameters after eq. (39)";
  s.simulation.t_end = 2.0;
  s.simulation.accuracy = 1e-6;
  s.simulation.integrator = "RungeKuttaMerson";
  s.simulation.output_step = 1e-3;
  s.simulation.constraint_tolerance = 1e-6;
  s.simulation.steady_window_revolutions = 5;
  s.initial.crank_angle = 0.0;
  s.initial.crank_speed = 0.0;
  s.initial.twist = 0.0;
  s.crank.radius = 0.2;
  s.crank.offset = M_PI / 2;  // Δφ = 90°
  s.crank.inertia_per_crank = 0.0;  // J'_K not given by the paper
  s.crank.shaft_inertia = 0.0;
  s.rods.model = RodModel::Split;  // seed 000 eq. (2)-(3)
  s.rods.length = 0.8;
  s.rods.mass = 64.0;
  s.rods.inertia_com = 64.0 * 0.8 * 0.8 / 12.0;
  s.carts.count = 4;
  s.carts.side = {1, 1, 1, 1};
  s.carts.mass = 1000.0;
  s.carts.geometry = {0.27, 0.37, 0.52, 0.21, 0.22, 0.046, 0.3};  // a b p e D d com_height
  s.motor.enabled = true;
  s.motor.omega_sync = 104.72;
  s.motor.breakdown_torque = 517.14;
  s.motor.critical_slip = 0.1145;
  s.motor.rotor_inertia = 0.4;
  s.reducer.ratio = 9.8;
  s.reducer.efficiency = 0.9;
  s.reducer.inertia = 0.046;
  s.reducer.delta = 1.0;
  s.coupling.type = CouplingType::Elastic;
  s.coupling.stiffness = 2e5;
  s.coupling.damping = 8000;
  s.coupling.inertia = 0.32;
  s.flywheel.inertia = 0.0;
  s.flywheel.location = FlywheelLocation::Crankshaft;
  s.loads.roller_force_front = 7962;
  s.loads.roller_force_rear = 7962;
  s.loads.roller_normal_front = 9740;
  s.loads.roller_normal_rear = 9740;
  s.loads.roller_force_direction = RollerForceDirection::AsPrinted;
  s.loads.guide_friction = 0.008;
  s.loads.gravity = 9.81;
  s.loads.velocity_smoothing = 1e-3;
  s.reduced.kinematics = KinematicsForm::Exact;
  s.reduced.integrator = ReducedIntegrator::Cvode;
  s.reduced.baranov_step = 0.5 * M_PI / 180.0;
  return s;
}

}  // namespace test
}  // namespace rollerdyn
