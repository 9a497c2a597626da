// Scene keys of the loads on the carts: roller forces, rolling resistance, guide friction, gravity;
// part of the scene schema (SceneSchema.cpp).
#include "scene/SchemaSections.h"

namespace rollerdyn {

using namespace schema_builders;

// loads.*.
std::vector<KeySpec> loadSchemaKeys() {
  using P = Presence;
  return {
      perCart(number("loads.roller_force_front", "N", P::Optional, nonNegative(), 0.0,
                     "F_j1, horizontal force on the front compacting roller (magnitude); a list: per cart")
                  .from(L2018 + " fig. 3, eq. (10)")),
      perCart(number("loads.roller_force_rear", "N", P::Optional, nonNegative(), 0.0,
                     "F_j2, horizontal force on the rear compacting roller (magnitude); a list: per cart")
                  .from(L2018 + " fig. 3, eq. (10)")),
      perCart(number("loads.roller_normal_front", "N", P::Optional, nonNegative(), 0.0,
                     "R_j1, upward reaction of the mix on the front roller; a list: per cart")
                  .from(L2018 + " fig. 3, eq. (10)")),
      perCart(number("loads.roller_normal_rear", "N", P::Optional, nonNegative(), 0.0,
                     "R_j2, upward reaction of the mix on the rear roller; a list: per cart")
                  .from(L2018 + " fig. 3, eq. (10)")),
      choice("loads.roller_force_direction", P::Optional, {"opposes_velocity", "as_printed"},
             "opposes_velocity",
             "opposes_velocity: the roller forces resist the cart's motion (a rolling "
             "resistance); as_printed: they keep the one direction of the figure")
          .from(L2007 + " eq. (5) (opposes_velocity); " + L2018 + " fig. 3 (as_printed)"),
      perCart(number("loads.rolling_resistance", "-", P::Optional, between(0.0, true, 1.0, false), 0.0,
                     "μ_r, rolling resistance of the compacting rollers: a force μ_r·(R_j1 + R_j2) against the "
                     "cart's velocity, added to the roller forces in either direction law; the energy "
                     "compaction dissipates (loads.md); a list: per cart")),
      number("loads.guide_friction.coefficient", "-", P::Optional,
             between(0.0, true, 1.0, false), 0.0, "f, reduced guide-roller friction coefficient")
          .from(L2018 + " eq. (14)-(25)"),
      choice("loads.guide_friction.normal_force", P::Conditional, {"algebraic", "lagged"}, "",
             "normal force of the multibody model's guide friction: the guide reaction of the same "
             "instant, solved with the motion (algebraic; minimal formulation only) or followed with "
             "the lag τ_N (lagged)")
          .when("algebraic with the minimal formulation, lagged with the constrained one"),
      number("loads.guide_friction.normal_force_lag", "s", P::Optional, between(0.0, false, 1.0, true),
             2e-3,
             "τ_N of the lagged normal force: the multibody model's friction then uses a normal force "
             "that follows the actual guide reaction with this time constant (dN̂/dt = (N − N̂)/τ_N)"),
      number("loads.gravity", "m/s²", P::Optional, nonNegative(), 9.81,
             "g; 0 = no gravity"),
      number("loads.velocity_smoothing", "m/s", P::Optional, positive(), 1e-3,
             "v_s: sign(v) is replaced by tanh(v/v_s) in the load and friction laws"),
  };
}

}  // namespace rollerdyn
