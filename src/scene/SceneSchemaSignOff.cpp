// Scene keys of the fatigue (Fatigue.h) and coupling-selection (CouplingSelection.h) sign-off and
// of the reducer's and the motor's duty, part of the scene schema (SceneSchema.cpp).
#include <iterator>

#include "scene/SchemaBuilders.h"

namespace rollerdyn {

using namespace schema_builders;

namespace {

// The fatigue check: each loaded part's S-N curve and the life the parts must reach.
std::vector<KeySpec> fatigueSchemaKeys() {
  using P = Presence;
  return {
      number("sizing.fatigue.coupling_torque.endurance_amplitude", "N·m", P::Optional, positive(), 0.0,
             "S_D, amplitude of the coupling torque (at the crank axis) at the knee of its S-N curve (the fatigue strength at N_D cycles); "
             "with knee_cycles and slope it turns the run's rainflow cycles into damage per start and per hour")
          .from("ASTM E1049-85 (rainflow), Miner's rule"),
      number("sizing.fatigue.coupling_torque.knee_cycles", "-", P::Optional, positive(), 0.0,
             "N_D, cycles at the knee of the coupling torque (at the crank axis)'s S-N curve, e.g. 1e6 or 2e6"),
      number("sizing.fatigue.coupling_torque.slope", "-", P::Optional, positive(), 0.0,
             "m, exponent of the sloped branch: N = N_D·(S_D/S_a)^m above the knee"),
      number("sizing.fatigue.coupling_torque.ultimate", "N·m", P::Optional, positive(), 0.0,
             "S_u, ultimate value of the coupling torque (at the crank axis) for Goodman's mean-stress correction "
             "S_ar = S_a/(1 - |S_m|/S_u); left out: no mean correction")
          .from("Goodman's line"),
      number("sizing.fatigue.rod_force.endurance_amplitude", "N", P::Optional, positive(), 0.0,
             "S_D, amplitude of the rod force (each rod) at the knee of its S-N curve (the fatigue strength at N_D cycles); "
             "with knee_cycles and slope it turns the run's rainflow cycles into damage per start and per hour")
          .from("ASTM E1049-85 (rainflow), Miner's rule"),
      number("sizing.fatigue.rod_force.knee_cycles", "-", P::Optional, positive(), 0.0,
             "N_D, cycles at the knee of the rod force (each rod)'s S-N curve, e.g. 1e6 or 2e6"),
      number("sizing.fatigue.rod_force.slope", "-", P::Optional, positive(), 0.0,
             "m, exponent of the sloped branch: N = N_D·(S_D/S_a)^m above the knee"),
      number("sizing.fatigue.rod_force.ultimate", "N", P::Optional, positive(), 0.0,
             "S_u, ultimate value of the rod force (each rod) for Goodman's mean-stress correction "
             "S_ar = S_a/(1 - |S_m|/S_u); left out: no mean correction")
          .from("Goodman's line"),
      choice("sizing.fatigue.below_knee", P::Optional, {"haibach", "cutoff"}, "haibach",
             "S-N curve below its knee S_D: Haibach's extension with slope 2m - 1 (haibach: small cycles still "
             "damage once large ones have lowered the endurance limit) or the plain cut-off (cutoff: no damage "
             "below S_D)")
          .from("Haibach, Betriebsfestigkeit (modified Miner rule)"),
      number("sizing.fatigue.required_starts", "-", P::Optional, positive(), 0.0,
             "starts the parts must take: the fatigue check of a start compares it with 1/(damage per start)"),
      number("sizing.fatigue.required_hours", "h", P::Optional, positive(), 0.0,
             "hours of steady running the parts must take: the check compares it with 1/(damage per hour)"),
  };
}

// The coupling's catalogue values and service factors (DIN 740-2).
std::vector<KeySpec> couplingSelectionSchemaKeys() {
  using P = Presence;
  return {
      number("sizing.coupling.rated_torque", "N·m", P::Optional, positive(), 0.0,
             "T_KN, the coupling's rated torque from its catalogue, reduced to the crank axis; checked "
             "against the steady peak T_N·S_t")
          .from("DIN 740-2 (KTR coupling selection)"),
      number("sizing.coupling.max_torque", "N·m", P::Optional, positive(), 0.0,
             "T_Kmax, the coupling's maximum torque, reduced to the crank axis; checked against the "
             "largest peak of the start and the steady running T_S·S_A·S_z·S_t")
          .from("DIN 740-2 (KTR coupling selection)"),
      number("sizing.coupling.vibratory_torque", "N·m", P::Optional, positive(), 0.0,
             "T_KW, the coupling's permissible vibratory torque amplitude (catalogue value at 10 Hz), "
             "reduced to the crank axis; checked against T_W·S_t·S_f")
          .from("DIN 740-2 (KTR coupling selection)"),
      number("sizing.coupling.damping_power", "W", P::Optional, positive(), 0.0,
             "P_KW, the elastic coupling's permissible damping power (heat it sheds continuously); "
             "checked against the steady mean of k·Δω² times S_t")
          .from("DIN 740-2 (KTR coupling selection)"),
      number("sizing.coupling.temperature_factor", "-", P::Optional, between(1.0, true, 10.0, true), 1.0,
             "S_t, temperature factor of the coupling's elastomer at its working temperature (catalogue "
             "table; 1 up to about 30 °C)")
          .from("DIN 740-2 (KTR coupling selection)"),
      number("sizing.coupling.start_factor", "-", P::Optional, between(1.0, true, 10.0, true), 1.0,
             "S_z, starting factor for the starts per hour (catalogue table; 1 up to 100 starts per hour)")
          .from("DIN 740-2 (KTR coupling selection)"),
      number("sizing.coupling.shock_factor", "-", P::Optional, between(1.0, true, 10.0, true), 1.0,
             "S_A, shock factor for shocks the model does not hold (the simulated peak already holds the "
             "start's and the reversals' shocks; 1 unless the process adds others)")
          .from("DIN 740-2 (KTR coupling selection)"),
  };
}

// The reducer's design values against the run's load spectrum (ISO 6336).
std::vector<KeySpec> reducerDutySchemaKeys() {
  using P = Presence;
  return {
      number("sizing.reducer.application_factor", "-", P::Optional, between(1.0, true, 10.0, true), 0.0,
             "K_A the reducer's gears were designed with, from the table of the driving and driven machine "
             "(e.g. 1.75 for an electric motor driving a machine with heavy shocks); checked against the run's "
             "K_A = T_eq/T_n, T_eq the Miner-equivalent torque of the load spectrum, T_n = u·η·M_n")
          .from("ISO 6336-1:2019 Annex B Table B.1; ISO 6336-6:2019 (load spectrum, equivalent torque)"),
      number("sizing.reducer.rated_torque", "N·m", P::Optional, positive(), 0.0,
             "T_2N, the reducer's rated output torque at service factor 1 (the constant torque it carries for its "
             "design life), at the crank axis; checked against the equivalent torque T_eq of the run's load spectrum")
          .from("ISO 6336-6:2019 (equivalent torque)"),
      number("sizing.reducer.max_torque", "N·m", P::Optional, positive(), 0.0,
             "T_2max, the reducer's permissible peak output torque (catalogue, for starts and rare peaks), at the "
             "crank axis; checked against the largest |T| of the start and the steady running"),
      number("sizing.reducer.sn_exponent", "-", P::Optional, between(1.0, true, 50.0, true), 6.61,
             "p, exponent of the gears' torque S-N curve T^p·N = const in the equivalent torque "
             "T_eq = (Σ n_i·T_i^p / N_L)^(1/p), n_i the crank revolutions at the torque T_i, N_L all of them: 6.61 for the flanks (pitting) of case-hardened steel, 8.74 for "
             "their tooth root (both from the life factors Z_NT and Y_NT of ISO 6336-2 and -3)")
          .from("ISO 6336-6:2019 Annex A; ISO 6336-2:2019 and ISO 6336-3:2019 (life factors)"),
  };
}

// The motor's catalogue limits for starting (IEC 60034-1 duty S4).
std::vector<KeySpec> motorDutySchemaKeys() {
  using P = Presence;
  return {
      number("sizing.motor.locked_rotor_time", "s", P::Optional, positive(), 0.0,
             "t_E, the motor's permissible locked-rotor (stall) time from the warm state, from its catalogue; a "
             "start may put at most the heat of t_E at standstill, t_E·M_s·ω0, into the rotor")
          .from("IEC 60034-1 (duty S4)"),
      number("sizing.motor.no_load_starts", "1/h", P::Optional, positive(), 0.0,
             "Z_0, the motor's permissible starts per hour without load torque and load inertia, from its catalogue; "
             "scaled to this load by the rotor heat of one start: Z = Z_0·(½·J_M·ω0²)/Q_start·(1 − P_steady/P_n,rotor)")
          .from("IEC 60034-1 (duty S4)")
  };
}

}  // namespace

std::vector<KeySpec> signOffSchemaKeys() {
  std::vector<KeySpec> keys;
  for (auto part : {fatigueSchemaKeys, couplingSelectionSchemaKeys, reducerDutySchemaKeys, motorDutySchemaKeys}) {
    std::vector<KeySpec> k = part();
    keys.insert(keys.end(), std::make_move_iterator(k.begin()), std::make_move_iterator(k.end()));
  }
  return keys;
}

}  // namespace rollerdyn
