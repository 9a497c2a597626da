#include "scene/SceneSchema.h"

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "scene/DidYouMean.h"
#include "scene/SchemaBuilders.h"

namespace rollerdyn {

namespace {

using namespace schema_builders;

std::vector<KeySpec> buildSchema() {
  using P = Presence;
  const std::string L2018 = "Loveikin, Pochka, Romasevych (2018)";
  const std::string L2007 = "Loveikin and Pochka (2007)";
  const std::string CAM = "Loveikin and Pochka (cam drive paper)";
  const std::string EB = "the energy-balanced drive paper";
  std::vector<KeySpec> keys = {
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

      number("initial.crank_angle_deg", "deg", P::Optional, anyFinite(), 0.0,
             "crank angle φ of cart 1's crank at t = 0, from +x"),
      number("initial.crank_speed", "rad/s", P::Optional, anyFinite(), 0.0,
             "crank speed at t = 0; the motor starts at the same speed reduced to the crank axis"),
      number("initial.twist", "rad", P::Optional, anyFinite(), 0.0,
             "coupling twist φ1 − φ2 at t = 0"),

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

      KeySpec{"motor.enabled", KeyKind::Flag, "-", P::Optional, anyFinite(), 1.0, "", {},
              "whether the motor torque is applied (false: the machine runs free from its initial "
              "speed)"},
      number("motor.omega_sync", "rad/s", P::Required, positive(), 0.0,
             "synchronous rotor speed ω0")
          .from(L2018 + " eq. (37)"),
      number("motor.breakdown_torque", "N·m", P::Conditional, positive(), 0.0,
             "breakdown (critical) torque M_kr at the rotor, Kloss's formula")
          .from(L2018 + " eq. (37); " + L2007 + " eq. (7)")
          .when("required unless motor.catalogue is given (then M_k/M_n·P_n/ω_n of the catalogue)"),
      number("motor.critical_slip", "-", P::Conditional, between(0.0, false, 1.0, false), 0.0,
             "critical slip s_kr of the Kloss formula (way 1 of 3)")
          .from(L2018 + " eq. (37)")
          .when("give the critical slip exactly one way"),
      number("motor.omega_critical", "rad/s", P::Conditional, positive(), 0.0,
             "critical rotor speed ω_kr < ω0; s_kr = 1 − ω_kr/ω0 (way 2 of 3)")
          .from(L2007 + " eq. (7)")
          .when("give the critical slip exactly one way"),
      number("motor.omega_nominal", "rad/s", P::Conditional, positive(), 0.0,
             "nominal rotor speed ω_n < ω0, s_n = 1 − ω_n/ω0 (way 3 of 3, with motor.overload_ratio)")
          .from(L2018 + " eq. (37)")
          .when("give the critical slip exactly one way"),
      number("motor.overload_ratio", "-", P::Conditional, between(1.0, false, kInf, false), 0.0,
             "λ = M_kr/M_n (way 3 of 3, with motor.omega_nominal); s_kr = s_n·(λ + √(λ² − 1)) < 1")
          .from(L2018 + " eq. (37)")
          .when("with motor.omega_nominal"),
      number("motor.rotor_inertia", "kg·m²", P::Required, positive(), 0.0,
             "rotor inertia J_p")
          .from(L2018 + " eq. (1)"),
      choice("motor.model", P::Optional, {"kloss", "kloss_dynamic", "circuit", "park"}, "kloss",
             "law of the motor torque: kloss, the static Kloss formula; kloss_dynamic, the Kloss torque "
             "lagging by T_e; circuit, the steady-state equivalent circuit (single or double cage); "
             "park, the space-phasor machine with its flux linkages as states (motor.md)")
          .from(L2018 + " eq. (37) (kloss); Klyuchev (1985) (kloss_dynamic); Pedra (2008) fig. 1 "
                "(circuit); Krause, Wasynczuk, Sudhoff, ch. 6 (park)"),
      number("motor.torque_time_constant", "s", P::Conditional, positive(), 0.0,
             "T_e of the dynamic Kloss characteristic T_e·dM/dt + M = M_static")
          .from("Klyuchev (1985)")
          .when("1/(2π·f_n·s_kr)"),
      number("motor.voltage", "V", P::Conditional, positive(), 0.0,
             "U_n, rated line-to-line RMS voltage")
          .when("required for motor.model circuit and park, and with motor.circuit or motor.catalogue"),
      number("motor.frequency", "Hz", P::Optional, positive(), 50.0,
             "f_n, rated supply frequency"),
      choice("motor.connection", P::Optional, {"star", "delta"}, "star",
             "stator winding connection at the rated voltage; the circuit's values are per phase of "
             "the equivalent star either way, delta allows a star-delta start"),
      integer("motor.pole_pairs", P::Conditional, between(1.0, true, 64.0, true), 0.0,
              "p, pole pairs; ω0 must equal 2π·f_n/p where the machine's data are used")
          .when("round(2π·f_n/ω0)"),
      number("motor.circuit.R_s", "Ω", P::Conditional, nonNegative(), 0.0,
             "stator resistance per phase of the equivalent star")
          .from("Pedra (2008) fig. 1")
          .when("the five running-cage values together, or none"),
      number("motor.circuit.L_sigma_s", "H", P::Conditional, positive(), 0.0,
             "stator leakage inductance per phase of the equivalent star")
          .from("Pedra (2008) fig. 1")
          .when("the five running-cage values together, or none"),
      number("motor.circuit.L_m", "H", P::Conditional, positive(), 0.0,
             "magnetizing inductance per phase of the equivalent star")
          .from("Pedra (2008) fig. 1")
          .when("the five running-cage values together, or none"),
      number("motor.circuit.R_r", "Ω", P::Conditional, positive(), 0.0,
             "rotor (first cage) resistance referred to the stator, per phase")
          .from("Pedra (2008) fig. 1")
          .when("the five running-cage values together, or none"),
      number("motor.circuit.L_sigma_r", "H", P::Conditional, positive(), 0.0,
             "rotor (first cage) leakage inductance referred to the stator, per phase")
          .from("Pedra (2008) fig. 1")
          .when("the five running-cage values together, or none"),
      number("motor.circuit.R_r2", "Ω", P::Conditional, positive(), 0.0,
             "second rotor cage's resistance (double cage), referred to the stator, per phase")
          .from("Pedra (2008) fig. 1")
          .when("with motor.circuit.L_sigma_r2, or neither (single cage)"),
      number("motor.circuit.L_sigma_r2", "H", P::Conditional, positive(), 0.0,
             "second rotor cage's leakage inductance (double cage), referred to the stator, per phase")
          .from("Pedra (2008) fig. 1")
          .when("with motor.circuit.R_r2, or neither (single cage)"),
      number("motor.catalogue.power", "W", P::Conditional, positive(), 0.0, "P_n, rated shaft power")
          .from("the motor's data sheet")
          .when("the eight catalogue values together, or none"),
      number("motor.catalogue.omega_nominal", "rad/s", P::Conditional, positive(), 0.0,
             "ω_n, rated rotor speed (< ω0)")
          .from("the motor's data sheet")
          .when("the eight catalogue values together, or none"),
      number("motor.catalogue.current", "A", P::Conditional, positive(), 0.0,
             "I_n, rated line current at motor.voltage")
          .from("the motor's data sheet")
          .when("the eight catalogue values together, or none"),
      number("motor.catalogue.power_factor", "-", P::Conditional, between(0.0, false, 1.0, false), 0.0,
             "cos φ_n at the rated point")
          .from("the motor's data sheet")
          .when("the eight catalogue values together, or none"),
      number("motor.catalogue.efficiency", "-", P::Conditional, between(0.0, false, 1.0, false), 0.0,
             "η_n at the rated point")
          .from("the motor's data sheet")
          .when("the eight catalogue values together, or none"),
      number("motor.catalogue.starting_torque_ratio", "-", P::Conditional, positive(), 0.0,
             "M_s/M_n, torque at standstill over the rated torque")
          .from("the motor's data sheet")
          .when("the eight catalogue values together, or none"),
      number("motor.catalogue.breakdown_torque_ratio", "-", P::Conditional,
             between(1.0, false, kInf, false), 0.0, "M_k/M_n, largest torque over the rated torque")
          .from("the motor's data sheet")
          .when("the eight catalogue values together, or none"),
      number("motor.catalogue.starting_current_ratio", "-", P::Conditional,
             between(1.0, false, kInf, false), 0.0, "I_s/I_n, current at standstill over the rated current")
          .from("the motor's data sheet")
          .when("the eight catalogue values together, or none"),
      integer("motor.catalogue.cages", P::Optional, between(1.0, true, 2.0, true), 2.0,
              "rotor cages of the circuit fitted to the catalogue (2 honours the starting torque)")
          .from("Pedra (2008)"),

      // Starting method and switch-off (scene/MotorSwitching.h, motor/Supply.h).
      choice("motor.start.method", P::Optional,
             {"direct_on_line", "star_delta", "soft_starter", "frequency_converter"}, "direct_on_line",
             "how the motor is switched on and brought up to speed"),
      number("motor.start.t_on", "s", P::Optional, nonNegative(), 0.0, "switch-on time"),
      number("motor.start.phase_deg", "deg", P::Optional, anyFinite(), 0.0,
             "point on the wave at switch-on: angle of the supply voltage phasor (phase a at its peak = 0)"),
      number("motor.start.changeover_time", "s", P::Conditional, positive(), 0.0,
             "star-delta: changeover to delta at this time")
          .when("star_delta: this or motor.start.changeover_speed"),
      number("motor.start.changeover_speed", "rad/s", P::Conditional, positive(), 0.0,
             "star-delta: changeover to delta when the rotor reaches this speed")
          .when("star_delta: this or motor.start.changeover_time"),
      number("motor.start.changeover_gap", "s", P::Optional, nonNegative(), 0.0,
             "star-delta: dead time of the open transition, stator disconnected"),
      number("motor.start.ramp_time", "s", P::Conditional, positive(), 0.0,
             "soft starter, frequency converter: duration t_ramp of the voltage or frequency ramp")
          .when("required with soft_starter and frequency_converter"),
      number("motor.start.initial_voltage", "-", P::Conditional, between(0.0, false, 1.0, true), 0.0,
             "soft starter: U_0/U_n at switch-on")
          .when("required with soft_starter"),
      number("motor.start.current_limit", "A", P::Optional, nonNegative(), 0.0,
             "soft starter: RMS stator phase current I_lim the start is held to, during the ramp and after it, "
             "until the motor draws no more than I_lim at the rated voltage (then the bypass closes: U reaches "
             "U_n continuously); 0 = none (motor models with a current only)"),
      number("motor.start.max_start_time", "s", P::Optional, nonNegative(), 20.0,
             "soft starter with a current limit: a start still current-limited this long after the switch-on "
             "trips the starter (the motor is disconnected, a failed start); must exceed the ramp time; 0 = never "
             "trips. Default 20 s: a typical starter's factory setting of its excess-start-time protection (e.g. "
             "the Digistart D4's), and of the order of a motor's permitted locked-rotor time; set it slightly "
             "longer than a healthy start"),
      number("motor.start.initial_frequency", "Hz", P::Conditional, positive(), 0.0,
             "frequency converter: f_0 at switch-on (< the rated frequency)")
          .when("required with frequency_converter"),
      number("motor.start.boost", "-", P::Optional, between(0.0, true, 1.0, false), 0.0,
             "frequency converter: voltage boost U/U_n at zero frequency, U/U_n = boost + (1 - boost)·f/f_n"),
      number("motor.stop.t_off", "s", P::Optional, positive(), kInf,
             "switch-off time (coast-down); absent = never"),
      number("motor.stop.brake_torque", "N·m", P::Optional, nonNegative(), 0.0,
             "mechanical brake torque on the motor shaft after switch-off, at the rotor; 0 = no brake"),
      number("motor.stop.brake_delay", "s", P::Optional, nonNegative(), 0.0,
             "the brake engages this long after the switch-off"),
      number("motor.stop.t_restart", "s", P::Optional, positive(), kInf,
             "reconnection direct on line at the rated supply after a switch-off (brake released); absent = never"),

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

      number("flywheel.inertia", "kg·m²", P::Optional, nonNegative(), 0.0,
             "flywheel about its own shaft; 0 = none")
          .from(EB + " Table 1"),
      choice("flywheel.location", P::Optional, {"crankshaft", "motor_shaft"}, "crankshaft",
             "shaft carrying the flywheel (on the motor shaft it counts u² times)"),

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
  for (KeySpec& k : signOffSchemaKeys()) keys.push_back(std::move(k));
  std::vector<KeySpec> reduced = {
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
  keys.insert(keys.end(), std::make_move_iterator(reduced.begin()), std::make_move_iterator(reduced.end()));
  return keys;
}

// One sentence per map of the schema, for the reference's section headings.
const std::vector<std::pair<std::string, std::string>>& mapDescriptions() {
  static const std::vector<std::pair<std::string, std::string>> d = {
      {"simulation", "How the run is integrated and what it writes."},
      {"initial", "The state at t = 0."},
      {"crank", "The crankshaft and its cranks."},
      {"crankshaft",
       "The crankshaft as a beam along its axis: where each crank throw and each main bearing sits "
       "(optional; without it the main bearings are known only as their resultant)."},
      {"rods", "The connecting rods, crank pin to cart hinge B."},
      {"drive", "Crank-slider or cam drive of the carts."},
      {"cam", "The cam drive of Loveikin and Pochka (cam drive paper), used when drive.type is cam."},
      {"carts", "The carts, all alike."},
      {"carts.geometry",
       "Measured from the rod hinge B in the cart's own direction (+x' away from the shaft; "
       "mirrored for an opposite cart), Loveikin, Pochka, Romasevych (2018) fig. 3."},
      {"motor",
       "The induction motor: Kloss's formula of the papers, or the law motor.model names (motor.md); "
       "Kloss's critical slip is given exactly one of three ways."},
      {"motor.circuit",
       "The equivalent circuit per phase of the equivalent star (circuit and park models); left out, "
       "it is fitted to motor.catalogue."},
      {"motor.catalogue", "The motor's data sheet at the rated supply, to which the circuit is fitted."},
      {"reducer", "The reducer between motor and crankshaft."},
      {"coupling", "The coupling between motor side and crank side, reduced to the crank axis."},
      {"flywheel", "An optional flywheel."},
      {"loads", "Technological loads on the compacting rollers, guide friction and gravity."},
      {"loads.guide_friction", "Friction of the guide rollers from the dynamic guide reactions."},
      {"sizing",
       "Ratings and targets the run is compared with (the drive-sizing answers); they change "
       "nothing in the simulation, and a figure whose rating is left out is null (n/a)."},
      {"sizing.bearing_rating", "Basic dynamic load ratings C of the joints' bearings."},
      {"sizing.fatigue",
       "S-N curves of the parts for the fatigue damage per start and per hour (rainflow counting after "
       "ASTM E1049-85 and Miner's rule)."},
      {"sizing.fatigue.coupling_torque", "S-N curve of the coupling, in amplitudes of its torque at the crank axis."},
      {"sizing.fatigue.rod_force", "S-N curve of a connecting rod, in amplitudes of its axial force."},
      {"sizing.coupling",
       "Catalogue ratings and selection factors of a flexible coupling, checked by the manufacturers' method "
       "after DIN 740-2."},
      {"reduced", "Settings of the papers' reduced-mass model only."},
  };
  return d;
}

std::string joinChoices(const std::vector<std::string>& words) {
  std::string s;
  for (size_t i = 0; i < words.size(); ++i) s += (i ? ", " : "") + words[i];
  return s;
}

std::string describeRange(const Range& r) {
  const bool has_lo = std::isfinite(r.lo);
  const bool has_hi = std::isfinite(r.hi);
  if (has_lo && has_hi) {
    return std::string("in ") + (r.lo_inclusive ? "[" : "(") + formatNumber(r.lo) + ", " +
           formatNumber(r.hi) + (r.hi_inclusive ? "]" : ")");
  }
  if (has_lo) return std::string(r.lo_inclusive ? ">= " : "> ") + formatNumber(r.lo);
  if (has_hi) return std::string(r.hi_inclusive ? "<= " : "< ") + formatNumber(r.hi);
  return "";
}

}  // namespace

const std::vector<KeySpec>& sceneSchema() {
  static const std::vector<KeySpec> schema = buildSchema();
  return schema;
}

const KeySpec* findSceneKey(const std::string& path) {
  for (const KeySpec& k : sceneSchema())
    if (k.path == path) return &k;
  return nullptr;
}

const KeySpec* findSceneKeyOrElement(const std::string& path, int* element) {
  if (element) *element = -1;
  if (const KeySpec* k = findSceneKey(path)) return k;
  // "key[i]": digits only between the brackets, at the end of the path.
  const size_t open = path.rfind('[');
  if (open == std::string::npos || open == 0 || path.back() != ']' || open + 2 > path.size() - 1) return nullptr;
  const std::string digits = path.substr(open + 1, path.size() - open - 2);
  if (digits.empty() || digits.size() > 6 || digits.find_first_not_of("0123456789") != std::string::npos)
    return nullptr;
  const KeySpec* k = findSceneKey(path.substr(0, open));
  if (!k || !k->per_cart) return nullptr;
  if (element) *element = std::stoi(digits);
  return k;
}

bool isSceneMap(const std::string& path) {
  if (path.empty()) return true;
  const std::string prefix = path + ".";
  for (const KeySpec& k : sceneSchema())
    if (k.path.compare(0, prefix.size(), prefix) == 0) return true;
  return false;
}

std::vector<std::string> sceneChildKeys(const std::string& map_path) {
  const std::string prefix = map_path.empty() ? "" : map_path + ".";
  std::vector<std::string> children;
  for (const KeySpec& k : sceneSchema()) {
    if (k.path.compare(0, prefix.size(), prefix) != 0) continue;
    const std::string rest = k.path.substr(prefix.size());
    const std::string child = rest.substr(0, rest.find('.'));
    bool seen = false;
    for (const std::string& c : children) seen = seen || c == child;
    if (!seen) children.push_back(child);
  }
  return children;
}

std::string describeExpected(const KeySpec& spec) {
  const std::string unit = (spec.unit.empty() || spec.unit == "-") ? "" : " [" + spec.unit + "]";
  switch (spec.kind) {
    case KeyKind::Number: {
      const std::string range = describeRange(spec.range);
      return (range.empty() ? "a finite number" : "a number " + range) + unit;
    }
    case KeyKind::Integer: {
      const std::string range = describeRange(spec.range);
      return range.empty() ? "an integer" : "an integer " + range;
    }
    case KeyKind::Text: return "a text scalar";
    case KeyKind::Choice: return "one of: " + joinChoices(spec.choices);
    case KeyKind::Flag: return "true or false";
    case KeyKind::Sides:
      return "a list of same/opposite with one entry per cart, or one of the words "
             "same, opposite, alternate";
    case KeyKind::NumberList: {
      const std::string range = describeRange(spec.range);
      return "a list of numbers" + (range.empty() ? std::string() : " " + range) + unit;
    }
  }
  return "?";
}

std::string describeExpectedList(const KeySpec& spec, int count) {
  const std::string unit = (spec.unit.empty() || spec.unit == "-") ? "" : " [" + spec.unit + "]";
  const std::string range = describeRange(spec.range);
  return "a list of " + std::to_string(count) + " numbers" + (range.empty() ? "" : " " + range) + unit +
         ", one per cart (carts.count = " + std::to_string(count) + ")";
}

std::string sceneMapDescription(const std::string& map_path) {
  for (const auto& [path, text] : mapDescriptions())
    if (path == map_path) return text;
  return "";
}

std::string describeAllowed(const KeySpec& spec) {
  switch (spec.kind) {
    case KeyKind::Number: {
      const std::string range = describeRange(spec.range);
      const std::string one = range.empty() ? "any finite number" : range;
      if (spec.path == "crank.angles_deg") return "a list of carts.count values " + one + ", one per cart, the first 0";
      if (spec.path == "crankshaft.throw_positions") return "a list of carts.count values " + one + ", one per cart";
      return spec.per_cart ? one + "; or a list of carts.count such values, one per cart" : one;
    }
    case KeyKind::Integer: {
      const std::string range = describeRange(spec.range);
      return range.empty() ? "an integer" : "an integer " + range;
    }
    case KeyKind::Text: return "text";
    case KeyKind::Choice: return "one of: " + joinChoices(spec.choices);
    case KeyKind::Flag: return "true or false";
    case KeyKind::Sides: return "a list of same/opposite (one per cart), or same, opposite, alternate";
    case KeyKind::NumberList: return "a list of two or more numbers, ascending";
  }
  return "?";
}

std::string defaultText(const KeySpec& spec) {
  if (spec.presence != Presence::Optional) return "";
  const Range& r = spec.range;
  const double d = spec.default_number;
  switch (spec.kind) {
    case KeyKind::Number:
    case KeyKind::Integer:
      // A default the key's own range refuses (0 for a rating that must be > 0) stands for "absent":
      // shown as a value, a user would type it and be refused.
      if (!((d > r.lo || (r.lo_inclusive && d == r.lo)) && (d < r.hi || (r.hi_inclusive && d == r.hi))))
        return "not given";
      return formatNumber(d);
    case KeyKind::Flag: return spec.default_number != 0 ? "true" : "false";
    default: return spec.default_text;
  }
}

void requireSceneKey(const std::string& what, const std::string& key) {
  if (findSceneKey(key)) return;
  std::vector<std::string> keys;
  for (const KeySpec& k : sceneSchema()) keys.push_back(k.path);
  throw std::invalid_argument(what + ": expected a key of the scene schema (docs/scene-reference.md), got an "
                              "unknown key" + didYouMean(key, keys));
}

std::string formatNumber(double v) {
  std::ostringstream os;
  os.precision(12);
  os << v;
  return os.str();
}

}  // namespace rollerdyn
