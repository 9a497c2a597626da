// Scene keys of the mechanism: crank, crankshaft, rods, crank or cam drive, carts; part of the scene
// schema (SceneSchema.cpp).
#include "scene/SchemaSections.h"

namespace rollerdyn {

using namespace schema_builders;

// crank.*.
std::vector<KeySpec> crankSchemaKeys() {
  using P = Presence;
  return {
      number("crank.radius", "m", P::Required, positive(), 0.0, "crank radius r")
          .from(L2018 + " eq. (40)"),
      number("crank.offset_deg", "deg", P::Conditional, between(0.0, true, 360.0, false), 0.0,
             "angle Δφ between consecutive cranks: cart j's crank sits at φ + (j − 1)·Δφ")
          .from(L2018 + " eq. (31); " + L2007)
          .when("required unless crank.angles_deg is given"),
      perCart(number("crank.angles_deg", "deg", P::Conditional, between(0.0, true, 360.0, false), 0.0,
                     "instead of crank.offset_deg: a list with each cart's crank angle from cart 1's crank "
                     "(first entry 0), e.g. the firing order [0, 180, 90, 270] (per-cart.md)")
                  .when("(j − 1)·Δφ from crank.offset_deg; give one of the two")),
      perCart(number("crank.angle_error_deg", "deg", P::Optional, between(-180.0, false, 180.0, false), 0.0,
                     "deviation of each crank from its nominal angle (a manufacturing tolerance): a list with "
                     "one value per cart, or one value that turns every crank (per-cart.md)")),
      number("crank.inertia_per_crank", "kg·m²", P::Optional, nonNegative(), 0.0,
             "J'_K, one crank about the shaft axis")
          .from(L2018 + " eq. (2)"),
      number("crank.shaft_inertia", "kg·m²", P::Optional, nonNegative(), 0.0,
             "crankshaft without cranks, about its axis"),
  };
}

// crankshaft.*: the crankshaft as a beam along its axis.
std::vector<KeySpec> crankshaftSchemaKeys() {
  using P = Presence;
  return {
      perCart(number("crankshaft.throw_positions", "m", P::Conditional, anyFinite(), 0.0,
                     "axial position z of each cart's crank throw (the plane of its crank pin), z growing "
                     "away from the coupling (the drive torque enters at the smallest z): a list with one "
                     "value per cart. With "
                     "crankshaft.bearing_positions it splits the main bearings' resultant into each "
                     "bearing's reaction; a throw outside the outer bearings is an overhung crank")
                  .when("only with crankshaft.bearing_positions or crankshaft.torsional_stiffness; absent: the main "
                        "bearings' resultant only and a rigid crankshaft")),
      KeySpec{"crankshaft.bearing_positions", KeyKind::NumberList, "m", P::Conditional, anyFinite(), 0.0, "", {},
              "axial positions z of the main bearings, the same origin as crankshaft.throw_positions: a list "
              "of two or more, ascending; the shaft is a beam on rigid supports there"}
          .when("only with crankshaft.throw_positions; absent: the main bearings' resultant only"),
      number("crankshaft.bending_stiffness", "N·m²", P::Optional, positive(), 0.0,
             "E·I of the crankshaft, uniform along it. Without effect on the bearing reactions: with one "
             "E·I on rigid supports they do not depend on its value, also with more than two bearings "
             "(accepted, and reported as without effect)"),
      number("crankshaft.torsional_stiffness", "N·m²", P::Optional, positive(), 0.0,
             "G·I_p of the crankshaft between its throws, uniform along it: the shaft becomes a torsional "
             "chain, one body per throw in z order, the segment between neighbouring throws a spring "
             "G·I_p/Δz; the coupling drives the throw of smallest z, the shaft from the coupling to it counts "
             "as rigid (put its compliance into coupling.stiffness); each throw carries crank.inertia_per_crank "
             "and an equal share of crank.shaft_inertia, a crankshaft flywheel sits at the drive end; no "
             "material damping. Absent: a rigid crankshaft")
          .when("only with crankshaft.throw_positions (distinct), drive.type: crank and simulation.formulation: "
                "constrained; the reduced model keeps the papers' rigid crankshaft"),
      number("crankshaft.torsional_damping", "N·m²·s", P::Optional, nonNegative(), 0.0,
             "β·G·I_p of the torsional chain's shaft (Kelvin-Voigt material damping, uniform): each segment gets "
             "a damper β·G·I_p/Δz beside its spring. For a damping ratio ζ at a shaft mode of frequency p give "
             "2·ζ·G·I_p/p (steel crankshafts: ζ of a few 0.1 %). 0: undamped, and the modes a start excites ring "
             "through the whole run")
          .when("only with crankshaft.torsional_stiffness"),
  };
}

// rods.*.
std::vector<KeySpec> rodSchemaKeys() {
  using P = Presence;
  return {
      choice("rods.model", P::Required, {"distributed", "split", "massless"}, "",
             "connecting-rod mass model: distributed (uniform bar), split (half of the mass at "
             "the crank pin, half at the cart) or massless")
          .from(L2018 + " eq. (2)-(3) (split); " + L2007 + " eq. (9) (distributed)"),
      number("rods.length", "m", P::Required, positive(), 0.0,
             "rod length l, crank pin to the cart's hinge B; must exceed crank.radius (l > r)")
          .from(L2018 + " eq. (40)"),
      // Any finite number here: the parser checks the range with rods.model, so that one rule gives
      // one message (> 0, or >= 0 when the rods are massless).
      number("rods.mass", "kg", P::Conditional, anyFinite(), 0.0,
             "mass of one rod: > 0, or >= 0 when rods.model is massless")
          .from(L2018 + " eq. (3); " + L2007 + " (q·l)")
          .when("required unless rods.model is massless (then 0)"),
      number("rods.inertia_com", "kg·m²", P::Conditional, nonNegative(), 0.0,
             "rod inertia about its centre of mass")
          .from(L2007 + " eq. (9): I_s = q·l³/12")
          .when("m·l²/12"),
  };
}

// drive.type and the cam drive's cam.*.
std::vector<KeySpec> driveSchemaKeys() {
  using P = Presence;
  return {
      choice("drive.type", P::Optional, {"crank", "cam"}, "crank",
             "crank: one crank-slider per cart; cam: the constant-diameter cam pushes each cart "
             "along the optimal-reversal law (the rod keys are then unused)")
          .from(CAM),
      number("cam.stroke", "m", P::Conditional, positive(), 0.0,
             "Δx, full stroke of the cart under the cam drive")
          .from(CAM + " (Δx = 0.4 m)")
          .when("required when drive.type is cam"),
      number("cam.pusher_distance", "m", P::Conditional, positive(), 0.0,
             "b, distance between the two pushers = the cam's constant diameter (> cam.stroke); "
             "shapes the profile ρ = b/2 + x(θ) only")
          .from(CAM + " eq. (38)-(43)")
          .when("2·cam.stroke"),
  };
}

// carts.*.
std::vector<KeySpec> cartSchemaKeys() {
  using P = Presence;
  return {
      integer("carts.count", P::Required, between(1.0, true, 1000.0, true), 0.0,
              "number of carts n"),
      KeySpec{"carts.sides", KeyKind::Sides, "-", P::Conditional, anyFinite(), 0.0, "same", {},
              "side of the shaft of each cart: same runs on the +x side, opposite on the −x "
              "side; a list with one entry per cart, or one word for all (alternate: same, "
              "opposite, same, ...)"}
          .from(L2018 + " eq. (40) (same); " + L2007 + " eq. (6) (opposite)")
          .when("all same"),
      perCart(number("carts.mass", "kg", P::Required, positive(), 0.0,
                     "m'_B, one cart without its rod; a list gives each cart its own (per-cart.md)")
                  .from(L2018 + " eq. (3)")),
      number("carts.geometry.a", "m", P::Optional, nonNegative(), 0.0,
             "half distance between the two compacting rollers (they touch the mix at p ∓ a from B)")
          .from(L2018 + " fig. 3, eq. (10)"),
      number("carts.geometry.b", "m", P::Conditional, nonNegative(), 0.0,
             "half distance between the two guide rollers; the guide reactions divide by 2b")
          .from(L2018 + " eq. (18)-(25)")
          .when("0; required (> 0) when loads.guide_friction.coefficient > 0"),
      number("carts.geometry.p", "m", P::Optional, anyFinite(), 0.0,
             "horizontal distance from the hinge B to the cart's centre of mass (= roller midpoint)")
          .from(L2018 + " fig. 3"),
      number("carts.geometry.e", "m", P::Optional, anyFinite(), 0.0,
             "depth of the compacting-roller contact below B (arm of the horizontal roller forces)")
          .from(L2018 + " fig. 3"),
      number("carts.geometry.D", "m", P::Optional, nonNegative(), 0.0,
             "compacting-roller diameter (informational)")
          .from(L2018),
      number("carts.geometry.d", "m", P::Optional, nonNegative(), 0.0,
             "guide-roller diameter; friction moment arm d/2")
          .from(L2018 + " eq. (18)-(25)"),
      number("carts.geometry.com_height", "m", P::Optional, anyFinite(), 0.0,
             "height of the cart's centre of mass above B (the papers put it at B)"),
  };
}

}  // namespace rollerdyn
