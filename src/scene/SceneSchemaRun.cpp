// Scene keys of the run itself: the scene's source, how the run is integrated and what it writes,
// the state at t = 0, and the reduced model's own settings; part of the scene schema (SceneSchema.cpp).
#include "scene/SchemaSections.h"

namespace rollerdyn {

using namespace schema_builders;

// source and simulation.*.
std::vector<KeySpec> runSchemaKeys() {
  using P = Presence;
  return {
      KeySpec{"source", KeyKind::Text, "-", P::Optional, anyFinite(), 0.0, "", {},
              "citation of the paper the scene comes from (authors, year, title); a scene of your own "
              "may leave it out, but not give it empty"},

      number("simulation.t_end", "s", P::Required, positive(), 0.0, "simulated time span"),
      number("simulation.accuracy", "-", P::Optional, between(0.0, false, 1.0, false), 1e-6,
             "integrator relative accuracy (the minimal formulation gives CVODE accuracy/100, "
             "which makes the key mean about the same error in both formulations)"),
      choice("simulation.integrator", P::Optional,
             {"RungeKuttaMerson", "RungeKutta3", "RungeKuttaFeldberg", "RungeKutta2",
              "ExplicitEuler", "Verlet", "SemiExplicitEuler2", "CPodes"},
             "RungeKuttaMerson",
             "Simbody integrator of the multibody model's constrained formulation (the minimal "
             "formulation always uses CVODE Adams; setting this key with it is an error)"),
      choice("simulation.formulation", P::Optional, {"constrained", "minimal"}, "minimal",
             "equations of the multibody model: constrained integrates every coordinate and lets "
             "Simbody enforce the loop constraints; minimal integrates only the crank angle (and "
             "the coupling twist) with CVODE Adams and takes every other coordinate from the "
             "slider-crank or cam closed forms"),
      number("simulation.output_step", "s", P::Optional, positive(), 0.005,
             "spacing of output rows (at most t_end)"),
      KeySpec{"simulation.reactions", KeyKind::Flag, "-", P::Optional, anyFinite(), 1.0, "", {},
              "compute the joint reaction forces (guide rollers, rods, crank pins, main bearing) "
              "at every output row; false writes no reactions table and no joint loads, only the "
              "motion and the drive torques, at a fraction of the multibody cost"},
      integer("simulation.self_check_interval", P::Conditional, between(1.0, true, 1e9, true), 0.0,
              "minimal formulation: every k-th output row is also solved by Simbody's constrained "
              "solve and compared with the O(n) pass (accelerations, guide normal forces, reaction "
              "columns)")
          .when("max(50, 10 × carts.count)"),
      number("simulation.constraint_tolerance", "-", P::Conditional,
             between(0.0, false, 1.0, false), 0.0,
             "constraint projection tolerance of the constrained formulation")
          .when("= simulation.accuracy"),
      number("simulation.steady_window_revolutions", "-", P::Optional, positive(), 5.0,
             "crank revolutions at the end of the run over which the steady-state metrics are taken"),
  };
}

// initial.*.
std::vector<KeySpec> initialStateSchemaKeys() {
  using P = Presence;
  return {
      number("initial.crank_angle_deg", "deg", P::Optional, anyFinite(), 0.0,
             "crank angle φ of cart 1's crank at t = 0, from +x"),
      number("initial.crank_speed", "rad/s", P::Optional, anyFinite(), 0.0,
             "crank speed at t = 0; the motor starts at the same speed reduced to the crank axis"),
      number("initial.twist", "rad", P::Optional, anyFinite(), 0.0,
             "coupling twist φ1 − φ2 at t = 0"),
  };
}

// reduced.*.
std::vector<KeySpec> reducedModelSchemaKeys() {
  using P = Presence;
  return {
      choice("reduced.kinematics", P::Optional, {"exact", "truncated"}, "exact",
             "slider-crank kinematics of the reduced model: exact, or the truncated series")
          .from(L2018 + " eq. (40)-(47) (exact), (52)-(57) (truncated)"),
      choice("reduced.integrator", P::Optional, {"cvode", "baranov"}, "cvode",
             "integrator of the reduced model: cvode (adaptive) or the papers' fixed step in φ")
          .from(L2007 + " eq. (4), (10), (11) (Baranov's scheme)"),
      number("reduced.baranov_step_deg", "deg", P::Optional, between(0.0, false, 10.0, true),
             1.0, "crank-angle step of the Baranov scheme")
          .from(L2007 + " eq. (4)"),
      choice("reduced.guide_normals", P::Optional, {"kinetostatic", "quasi_static"}, "kinetostatic",
             "guide normal forces of the reduced model (friction, reactions): with the cart's and "
             "rod's inertial forces, solved with the motion (kinetostatic), or the papers' cart "
             "statics without them (quasi_static)")
          .from(L2018 + " eq. (14)-(25) (quasi_static)"),
  };
}

}  // namespace rollerdyn
