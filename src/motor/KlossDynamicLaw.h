// The dynamic mechanical characteristic of the induction motor (motor.model: kloss_dynamic):
// the torque lags the static Kloss torque by a first-order electromagnetic time constant,
//   T_e·dM/dt + M = M_static(s),       T_e = 1/(ω1·s_kr),  ω1 = 2π·f_n,
// Klyuchev, "Theory of Electric Drive" (Klyuchev V.I., Teoriya elektroprivoda, Moscow:
// Energoatomizdat, 1985; 2nd ed. 2001), the dynamic mechanical characteristic of the induction
// motor with its electromagnetic time constant T_e = 1/(ω0el·s_k). Note: the ω there is the
// supply's (electrical) angular frequency ω1 = 2π·f_n = p·ω0, not the mechanical ω0 (for the
// papers' six-pole motors the mechanical ω0 would make T_e three times too long). Why, from the
// circuit: with R_s = 0 the rotor's transient time constant is σL_r/R_r = L_σ/R_r and the
// circuit's critical slip is s_kr = R_r/(ω1·L_σ), so 1/(ω1·s_kr) = L_σ/R_r: the lag with which the
// rotor current (and torque) follows a change of slip near synchronous speed. A test checks it
// against the space-phasor model's torque response (tests/motor).
// One state, the torque M [N·m]. The supply scales M_static as KlossLaw does (KlossLaw.h);
// T_e = 1/(ω1'·s_kr') does not change with f (ω1'·s_kr' = ω1·s_kr). What it neglects besides
// Kloss's own approximations: the supply-frequency torque oscillation after switching on (the
// flux builds up in the real machine; here only the lag), and the dependence of the lag on slip.
#pragma once

#include "motor/MotorLaw.h"
#include "scene/Scene.h"

namespace rollerdyn {

class KlossDynamicLaw : public MotorLaw {
 public:
  // time_constant: T_e [s] (> 0).
  KlossDynamicLaw(const KlossMotor& motor, double time_constant);
  // T_e = 1/(2π·f_n·s_kr) of the dynamic characteristic [s].
  static double defaultTimeConstant(const KlossMotor& motor, double rated_frequency);

  std::string description() const override;
  double synchronousSpeed() const override { return motor_.omega_sync; }
  int stateCount() const override { return 1; }
  std::vector<std::string> stateNames() const override { return {"M_dynamic[N·m]"}; }
  std::vector<double> stateScales() const override { return {motor_.breakdown_torque}; }
  double fastestTimeConstant() const override { return time_constant_; }
  double timeConstant() const { return time_constant_; }

  // steady: M = M_static(ω_r) under `supply` (0 when disconnected); else 0.
  void initialState(const SupplyState& supply, double omega_rotor, bool steady, double* x) const override;
  void evaluate(const SupplyState& supply, double omega_rotor, const double* x, MotorEvaluation& out,
                double* xdot) const override;
  // Switch-off: the stator current, and with it the torque, falls to zero at once (M := 0).
  void switchStates(const SupplyState& before, const SupplyState& after, double omega_rotor,
                    double* x) const override;
  double steadyTorque(const SupplyState& supply, double omega_rotor) const override;

 private:
  KlossMotor motor_;
  double time_constant_;
};

}  // namespace rollerdyn
