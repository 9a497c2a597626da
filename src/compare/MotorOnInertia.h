// A motor law driving an inertia against an optional load torque: the stand-alone test bench of
// the motor validation (Modelica Standard Library's direct-on-line start, Krause's free
// acceleration, the energy audit). Not a drive model: no coupling, reducer or carts.
//   J·dω/dt = M(ω, x) − M_L(ω),   dx/dt from the law,
// integrated with CVODE's BDF method (stiff: electrical time constants of milliseconds), with
// the energy integrals E_el = ∫P_el dt, E_cu = ∫P_cu dt, W_M = ∫M·ω dt, W_L = ∫M_L·ω dt as
// further states, so the audit is E_el = E_cu + W_M + ΔW_mag (electrical side) and
// W_M = W_L + ΔE_kin (mechanical side).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "motor/MotorLaw.h"

namespace rollerdyn {

struct InertiaRunOptions {
  double inertia = 0;                          // J, rotor and load together [kg·m²]
  std::function<double(double)> load_torque;   // M_L(ω) opposing the motion [N·m]; empty: none
  SupplyState supply;                          // constant supply from t = 0 (connected)
  double omega_start = 0;                      // rotor speed at t = 0 [rad/s]
  bool steady_start = false;                   // law states steady at t = 0 (else de-energised)
  double t_end = 1;                            // [s]
  double output_step = 1e-3;                   // spacing of the rows [s]
  double rtol = 1e-8;                          // CVODE relative tolerance [-]
};

struct InertiaRunRow {
  double t = 0, omega = 0, torque = 0, load_torque = 0, current = 0;
  double electrical_power = 0, copper_loss = 0, magnetic_energy = 0;
};

struct InertiaRun {
  bool complete = false;
  std::string error;
  std::vector<InertiaRunRow> rows;
  long steps = 0, rhs_evaluations = 0;
  // Energy integrals over the run [J] (0 where the law has no such output).
  double electrical_energy = 0, copper_energy = 0, motor_work = 0, load_work = 0;
  double magnetic_energy_change = 0, kinetic_energy_change = 0;
  // E_el − E_cu − W_M − ΔW_mag [J], and W_M − W_L − ΔE_kin [J].
  double electrical_residual() const {
    return electrical_energy - copper_energy - motor_work - magnetic_energy_change;
  }
  double mechanical_residual() const { return motor_work - load_work - kinetic_energy_change; }
};

InertiaRun runMotorOnInertia(const MotorLaw& law, const InertiaRunOptions& options);

}  // namespace rollerdyn
