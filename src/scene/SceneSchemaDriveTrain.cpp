// Scene keys of the drive train between motor and crankshaft: reducer, coupling, flywheel; part of
// the scene schema (SceneSchema.cpp).
#include "scene/SchemaSections.h"

namespace rollerdyn {

using namespace schema_builders;

// reducer.*.
std::vector<KeySpec> reducerSchemaKeys() {
  using P = Presence;
  return {
      number("reducer.ratio", "-", P::Required, positive(), 0.0, "u = ω_rotor/ω_crank")
          .from(L2018 + " eq. (1), (37)"),
      number("reducer.efficiency", "-", P::Required, between(0.0, false, 1.0, true), 0.0,
             "η, multiplies the motor torque at the crank")
          .from(L2018 + " eq. (37); " + L2007 + " eq. (8)"),
      choice("reducer.losses", P::Optional, {"papers", "power_flow"}, "papers",
             "law of the reducer's losses: papers, the torque at the crank is M·u·η whichever way the "
             "power flows (so a crank driving the motor gains energy in the reducer); power_flow, the "
             "loss is (1 − η)·|P| while the motor side drives and (1/η_r − 1)·|P| while the crank side "
             "drives (P the power at the reducer's motor side), blended smoothly over 1 % of the "
             "breakdown torque M_kr·u around zero torque")
          .from(L2018 + " eq. (37) (papers); Modelica Standard Library, Rotational.Components.LossyGear "
                "(power_flow)"),
      number("reducer.efficiency_reverse", "-", P::Conditional, between(0.0, false, 1.0, true), 0.0,
             "η_r, the efficiency while the crank side drives the motor side (reducer.losses: "
             "power_flow; no effect under papers)")
          .from("Modelica Standard Library, Rotational.Components.LossyGear")
          .when("= reducer.efficiency"),
      number("reducer.inertia", "kg·m²", P::Optional, nonNegative(), 0.0,
             "J_red referred to the motor shaft")
          .from(L2007 + " (I_o = I_motor + I_m + I_red)"),
      number("reducer.delta", "-", P::Optional, positive(), 1.0,
             "δ, factor on the motor-side inertia (J_p + J_m + J_red)·δ·u²")
          .from(L2018 + " eq. (1)"),
      number("reducer.backlash", "rad", P::Optional, nonNegative(), 0.0,
             "total backlash (free play) of the drive train between motor side and crankshaft, at the "
             "crank axis: the twist φ1 − φ2 moves backlash/2 either way without torque before the teeth "
             "meet; in contact the coupling's c and k act beyond the gap, and the damping never pulls the "
             "teeth together. Needs coupling.type: elastic (the contact stiffness is coupling.stiffness); "
             "0 = the teeth never part. E.g. 0.1° = 0.0017453 rad")
          .from("Modelica Standard Library, Rotational.Components.ElastoBacklash"),
  };
}

// coupling.*.
std::vector<KeySpec> couplingSchemaKeys() {
  using P = Presence;
  return {
      choice("coupling.type", P::Required, {"elastic", "rigid"}, "",
             "elastic: two-mass model with a torsional spring-damper; rigid: one mass")
          .from(L2018 + " eq. (58) (elastic); " + L2007 + ", " + EB + " (rigid)"),
      number("coupling.stiffness", "N·m/rad", P::Conditional, positive(), 0.0,
             "c, reduced to the crank axis (ignored when rigid)")
          .from(L2018 + " eq. (58)")
          .when("required when coupling.type is elastic"),
      number("coupling.damping", "N·m·s/rad", P::Optional, nonNegative(), 0.0,
             "k, reduced to the crank axis (ignored when rigid)")
          .from(L2018 + " eq. (58), Table 1"),
      number("coupling.inertia", "kg·m²", P::Optional, nonNegative(), 0.0,
             "J_m, coupling hub on the motor shaft")
          .from(L2018 + " eq. (1)"),
  };
}

// flywheel.*.
std::vector<KeySpec> flywheelSchemaKeys() {
  using P = Presence;
  return {
      number("flywheel.inertia", "kg·m²", P::Optional, nonNegative(), 0.0,
             "flywheel about its own shaft; 0 = none")
          .from(EB + " Table 1"),
      choice("flywheel.location", P::Optional, {"crankshaft", "motor_shaft"}, "crankshaft",
             "shaft carrying the flywheel (on the motor shaft it counts u² times)"),
  };
}

}  // namespace rollerdyn
