// A flexible coupling checked by the manufacturers' selection method after DIN 740-2 (as KTR
// publishes it in "Coupling selection according to DIN 740 part 2"; Flender and Mayr print the same
// checks with their own factor tables), on the torques of the run instead of the method's estimates:
//   rated torque      T_KN   >= T_N · S_t           T_N: the steady window's peak |T| (it recurs every
//                                                   revolution, so it is no rare maximum)
//   maximum torque    T_Kmax >= T_S · S_A · S_z · S_t   T_S: the largest |T| of the start and the
//                                                   steady window (the simulated peak holds the
//                                                   drive's start and reversal shocks the method
//                                                   estimates with its mass factor; S_A is for shocks
//                                                   the model does not have, default 1)
//   vibratory torque  T_KW   >= T_W · S_t · S_f      T_W = (max T - min T)/2 over the steady window;
//                                                   S_f = 1 up to 10 Hz, √(f/10 Hz) above, f the
//                                                   frequency of the coupling torque's largest crank
//                                                   order (CrankOrders.h)
//   damping power     P_KW   >= P_W · S_t            P_W = mean of k·Δω² over the steady window, the
//                                                   damper's loss of the model (k = coupling.damping,
//                                                   Δω = twist_rate); the energy audit integrates the
//                                                   same power over the whole run
// Torques at the crank axis (coupling_torque), ratings reduced to it like coupling.stiffness.
#pragma once

#include <string>

#include "analysis/SteadyState.h"

namespace rollerdyn {

struct Scene;
struct RunResult;
struct StartUp;

// S_f of DIN 740-2 at the excitation frequency f [Hz]: 1 for f <= 10 Hz, √(f/10) above.
double frequencyFactor(double f_hz);

struct CouplingSelection {
  bool requested = false;           // any of sizing.coupling.rated_torque, max_torque, vibratory_torque,
                                    // damping_power given
  double rated_torque = 0, max_torque = 0, vibratory_torque = 0, damping_power = 0;  // T_KN, T_Kmax,
                                    // T_KW [N·m], P_KW [W]; NaN when not given
  double S_t = 1, S_z = 1, S_A = 1; // the factors [-]
  bool start_in_run = false;        // the run starts the machine from rest
  bool steady_reached = false;
  double start_peak = 0;            // max |T| from the switch-on to the start's end [N·m]; NaN: no start
  double steady_peak = 0;           // max |T| over the steady window [N·m]
  double steady_amplitude = 0;      // T_W [N·m]
  int excitation_order = 0;         // the crank order of largest amplitude (0: not known)
  double excitation_frequency = 0;  // f [Hz]
  double S_f = 1;                   // [-]
  double damping_power_run = 0;     // P_W [W]; NaN when the coupling is rigid or Δω is missing
  std::string damping_basis;        // how P_W was obtained, or why not
  double rated_ratio = 0;           // T_N·S_t/T_KN [-]
  double max_ratio = 0;             // T_S·S_A·S_z·S_t/T_Kmax [-]
  double vibratory_ratio = 0;       // T_W·S_t·S_f/T_KW [-]
  double damping_ratio = 0;         // P_W·S_t/P_KW [-]
};

CouplingSelection computeCouplingSelection(const Scene& scene, const RunResult& run, const SteadyState& window,
                                           const StartUp* start_up);

}  // namespace rollerdyn
