// Static Kloss formula as a motor law (motor.model: kloss), and how its three numbers follow the
// supply. At the rated supply it is exactly the papers' law (src/physics/KlossMotor.h), so the
// papers' scenes keep their numbers.
#pragma once

#include "motor/MotorLaw.h"
#include "scene/Scene.h"

namespace rollerdyn {

// Kloss's M_kr, ω0 and s_kr under a supply of U/U_n = v and f/f_n = φ (SupplyState):
//   ω0' = ω0·φ,   s_kr' = s_kr/φ,   M_kr' = M_kr·v²/φ².
// Why: Kloss's formula is the equivalent circuit with R_s = 0 and L_m → ∞ (validated in
// validation item "Kloss is the circuit's limit"); there M_kr = 3p·U_ph²/(2·ω1²·L_σ) ∝ (U/f)²,
// s_kr = R_r/(ω1·L_σ) ∝ 1/f and ω0 = ω1/p ∝ f, with ω1 = 2πf and L_σ = L_σs + L_σr. The slip speed
// at breakdown ω0'·s_kr' = ω0·s_kr does not change with f, so the curve shifts along the speed
// axis with ω0' and scales with (v/φ)².
// What it neglects: the stator resistance (at low f the stator's voltage drop takes a growing
// share of U, so the real M_kr falls below (U/f)² scaling; this is why V/f converters add a
// voltage boost), magnetic saturation (U/f above rated), the deep-bar rise of the rotor
// resistance with the rotor frequency, and every electrical transient.
KlossMotor klossAtSupply(const KlossMotor& rated, const SupplyState& supply);

class KlossLaw : public MotorLaw {
 public:
  explicit KlossLaw(const KlossMotor& motor);
  std::string description() const override { return "Kloss formula (static)"; }
  double synchronousSpeed() const override { return motor_.omega_sync; }
  void evaluate(const SupplyState& supply, double omega_rotor, const double* x, MotorEvaluation& out,
                double* xdot) const override;
  double steadyTorque(const SupplyState& supply, double omega_rotor) const override;

 private:
  KlossMotor motor_;
};

}  // namespace rollerdyn
