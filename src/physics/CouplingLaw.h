// The law of the coupling between the motor side and the crankshaft, reduced to the crank axis:
// the one place both models (the multibody model's coupling force, the reduced model's
// right-hand side and their potential energies) read it.
//
// Twist Δφ = φ1 − φ2 [rad], twist rate Δω = φ̇1 − φ̇2 [rad/s], torque τ on the crankshaft
// (−τ on the motor side) [N·m].
//
// Without backlash (reducer.backlash = 0): the papers' elastic, damped coupling
//   τ = c·Δφ + k·Δω                                    (Loveikin, Pochka, Romasevych (2018) eq. (58))
//   V = ½·c·Δφ²,  dissipation P_d = k·Δω² ≥ 0.
//
// With a total backlash 2·b > 0 (b = reducer.backlash/2), the law of Modelica Standard Library,
// Rotational.Components.ElastoBacklash (backlash in series with the spring-damper):
//   |Δφ| ≤ b (teeth apart):   τ = 0
//   Δφ > b  (drive flank):    τ_c = c·(Δφ − b),  τ_d = k·Δω,
//                             τ = 0 if τ_c + τ_d ≤ 0, else τ_c + min(τ_c, τ_d)
//   Δφ < −b (reverse flank):  τ_c = c·(Δφ + b),  τ = 0 if τ_c + τ_d ≥ 0, else τ_c + max(τ_c, τ_d)
// so the damping torque never pulls the teeth together (τ keeps τ_c's sign or is 0) and is
// limited to |τ_d| ≤ |τ_c|: at the instant of contact τ_c = 0, hence τ = 0, and the torque is
// continuous in time (only its slope jumps). V = ½·c·(|Δφ| − b)² outside the gap, 0 inside, and
// the dissipation is what the coupling takes in minus what its spring stores,
// P_d = (τ − τ_c)·Δω ≥ 0 on every branch (min(τ_c, τ_d)·Δω ≥ 0; clipped: −τ_c·Δω ≥ 0).
#pragma once

#include <algorithm>
#include <cmath>

namespace rollerdyn {

struct Scene;

// Which flank of the teeth is in contact [-].
enum class ToothContact : int {
  Reverse = -1,  // Δφ < −b: the crank side drives the motor side
  Gap = 0,       // |Δφ| ≤ b: teeth apart, no torque
  Drive = 1,     // Δφ > b: the motor side drives the crank side
};

struct CouplingLaw {
  double stiffness = 0;  // c [N·m/rad]
  double damping = 0;    // k [N·m·s/rad]
  double half_gap = 0;   // b = backlash/2 [rad]; 0: the teeth never part
  bool hasBacklash() const { return half_gap > 0.0; }
};

// The scene's law: coupling.stiffness, coupling.damping, reducer.backlash/2 (elastic coupling).
CouplingLaw couplingLaw(const Scene& scene);

struct CouplingTorque {
  double torque = 0;         // τ on the crankshaft [N·m]
  double spring_torque = 0;  // τ_c [N·m]
  double damping_power = 0;  // P_d ≥ 0 [W]
};

// Contact state at the twist Δφ [rad] (without backlash: Drive, or Reverse for Δφ < 0).
inline ToothContact toothContact(const CouplingLaw& law, double twist) {
  if (twist > law.half_gap) return ToothContact::Drive;
  if (twist < -law.half_gap) return ToothContact::Reverse;
  return law.hasBacklash() ? ToothContact::Gap : ToothContact::Drive;
}

inline CouplingTorque couplingTorque(const CouplingLaw& law, double twist, double twist_rate) {
  CouplingTorque r;
  if (!law.hasBacklash()) {  // the papers' law, evaluated as it always was (bit for bit)
    r.spring_torque = law.stiffness * twist;
    r.torque = law.stiffness * twist + law.damping * twist_rate;
    r.damping_power = law.damping * twist_rate * twist_rate;
    return r;
  }
  const double b = law.half_gap, td = law.damping * twist_rate;
  if (twist > b) {
    r.spring_torque = law.stiffness * (twist - b);
    r.torque = r.spring_torque + td <= 0.0 ? 0.0 : r.spring_torque + std::min(r.spring_torque, td);
  } else if (twist < -b) {
    r.spring_torque = law.stiffness * (twist + b);
    r.torque = r.spring_torque + td >= 0.0 ? 0.0 : r.spring_torque + std::max(r.spring_torque, td);
  } else {
    return r;  // in the gap: nothing
  }
  r.damping_power = (r.torque - r.spring_torque) * twist_rate;
  return r;
}

// Potential energy stored in the coupling at the twist Δφ [J].
inline double couplingPotential(const CouplingLaw& law, double twist) {
  if (!law.hasBacklash()) return 0.5 * law.stiffness * twist * twist;
  const double d = std::max(0.0, std::abs(twist) - law.half_gap);
  return 0.5 * law.stiffness * d * d;
}

}  // namespace rollerdyn
