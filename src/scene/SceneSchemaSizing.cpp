// Scene keys of the sizing check: motor, coupling and bearing ratings the run is measured against
// (sizing.*; the fatigue and coupling-selection sign-off is SceneSchemaSignOff.cpp); part of the
// scene schema (SceneSchema.cpp).
#include "scene/SchemaSections.h"

namespace rollerdyn {

using namespace schema_builders;

// sizing.* but the sign-off.
std::vector<KeySpec> sizingSchemaKeys() {
  using P = Presence;
  return {
      number("sizing.motor_nominal_torque", "N·m", P::Optional, positive(), 0.0,
             "M_n, nominal motor torque at the rotor, the rating of the heating check "
             "(else P_n/ω_n, else M_kr/λ); at most one of this and sizing.motor_nominal_power"),
      number("sizing.motor_nominal_power", "W", P::Optional, positive(), 0.0,
             "P_n, nominal motor shaft power; M_n = P_n/ω_n (needs motor.omega_nominal)"),
      number("sizing.motor_efficiency", "-", P::Optional, between(0.0, false, 1.0, true), 0.0,
             "η_m, motor shaft power / power drawn from the line; without it the line power is "
             "the air-gap power M·ω0 (rotor copper losses only)"),
      number("sizing.starts_per_hour", "1/h", P::Optional, nonNegative(), 0.0,
             "duty: starts of the motor per hour; the heating check adds each start's rotor heat to "
             "the steady running (0: continuous running; the console then gives the starts per hour "
             "the motor allows)"),
      number("sizing.target_delta", "-", P::Optional, positive(), 0.0,
             "δ*, coefficient of unevenness the flywheel estimate should bring the run to")
          .from(L2007 + " eq. (12) (δ)"),
      number("sizing.coupling_rated_torque", "N·m", P::Optional, positive(), 0.0,
             "rated coupling torque, reduced to the crank axis like coupling.stiffness"),
      number("sizing.bearing_rating.guide_roller", "N", P::Optional, positive(), 0.0,
             "C, basic dynamic load rating of one guide-roller bearing")
          .from("ISO 281 (L10 = (C/P)³·10⁶ revolutions)"),
      number("sizing.bearing_rating.rod_end", "N", P::Optional, positive(), 0.0,
             "C of the rod's small-end bearing at the cart hinge B")
          .from("ISO 281"),
      number("sizing.bearing_rating.crank_pin", "N", P::Optional, positive(), 0.0,
             "C of the rod's big-end bearing on the crank pin")
          .from("ISO 281"),
      number("sizing.bearing_rating.main_bearing", "N", P::Optional, positive(), 0.0,
             "C of the crankshaft main bearing (one bearing carrying the whole bearing force)")
          .from("ISO 281"),
  };
}

}  // namespace rollerdyn
