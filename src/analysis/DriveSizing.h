// The answers a drive is sized with, computed once from a RunResult (so the multibody and the
// reduced model get the same figures from the same columns) over the steady-state window
// (SteadyState.h): motor torques, powers and slip against the motor's nominal and breakdown
// torque, the flywheel that would bring the coefficient of unevenness δ to a target, the coupling
// torque against its rating, and the bearing loads of every joint (BearingLoad.h).
//
// Notation: u reducer ratio, η reducer efficiency, ω0 synchronous rotor speed, ω_r rotor speed,
// M motor torque at the rotor shaft, M·u·η the same at the crank (the `motor_torque` column),
// s = 1 - ω_r/ω0 slip, M_kr breakdown torque, M_n nominal torque, λ = M_kr/M_n.
#pragma once

#include <string>
#include <vector>

#include "analysis/BearingLoad.h"
#include "analysis/RunResult.h"
#include "analysis/SteadyState.h"
#include "scene/Scene.h"

namespace rollerdyn {

// Every double is NaN when it cannot be computed (column absent, no motor, nothing given).
struct MotorSizing {
  bool available = false;          // motor on and the run has motor_torque and omega_motor
  double torque_shaft_mean = 0, torque_shaft_rms = 0, torque_shaft_peak = 0;  // M at the rotor [N·m]
  double torque_crank_mean = 0, torque_crank_rms = 0, torque_crank_peak = 0;  // M·u·η at the crank [N·m]
  double nominal_torque = 0;       // M_n at the rotor [N·m]
  std::string nominal_source;      // where M_n comes from (scene key or the Kloss data)
  double breakdown_torque = 0;     // M_kr at the rotor [N·m]
  double rms_over_nominal = 0;     // thermal check: RMS torque / M_n [-], passes when ≤ 1
  double peak_over_breakdown = 0;  // peak |M| / M_kr [-], passes when < 1
  double power_shaft_mean = 0, power_shaft_peak = 0;  // M·ω_r: mean and max [W]
  double power_line_mean = 0, power_line_peak = 0;    // drawn from the line [W]
  std::string line_power_basis;    // the efficiency assumption behind the line power
  double slip_min = 0, slip_max = 0;  // s over the window [-]
  double energy_per_revolution = 0;   // ∫ M·ω_r dt per crank revolution [J]; NaN unless turning
};

struct FlywheelSizing {
  double kinetic_energy_swing = 0;  // ΔT, largest max - min of the machine's kinetic energy over
                                    // one steady crank revolution [J]
  double inertia_effective = 0;     // J, time mean of 2T/ω_crank² over the window [kg·m²] (crank axis)
  double delta = 0;                 // δ of the run [-]
  double target_delta = 0;          // the target δ* [-]; NaN when not given
  double added_inertia_crank = 0;   // ΔJ = J·(δ/δ* - 1), ≥ 0, on the crankshaft [kg·m²]
  double flywheel_crankshaft = 0;   // flywheel on the crankshaft reaching δ* (present + ΔJ) [kg·m²]
  double flywheel_motor_shaft = 0;  // the same on the motor shaft: ΔJ/(δ_red·u²) + present [kg·m²]
};

struct CouplingSizing {
  bool available = false;          // the run has a coupling_torque column
  double mean = 0, peak = 0, swing = 0;  // coupling torque at the crank axis: mean, max |M|, max - min [N·m]
  double rating = 0;               // sizing.coupling_rated_torque [N·m]; NaN when not given
  double peak_over_rating = 0;     // [-], passes when ≤ 1
};

struct JointSizing {
  std::string joint;        // guide_roller_front, guide_roller_rear, rod_end, crank_pin, main_bearing
  int cart = 0;             // 1-based cart number; 0 for the main bearing
  std::string column;       // reactions column(s) the force comes from
  std::string speed_basis;  // what weights P (rotation speed used, or "none")
  JointLoad load;           // mean, amplitude, peak, equivalent dynamic load P, mean speed
  double rating = 0;        // C [N]; NaN when not given
  double life_revolutions = 0;  // L10 [-]
  double life_hours = 0;        // L10h [h]
};

struct DriveSizing {
  double t_begin = 0, t_end = 0;  // window [s]
  double revolutions = 0;         // crank revolutions in the window [-]
  MotorSizing motor;
  FlywheelSizing flywheel;
  CouplingSizing coupling;
  std::vector<JointSizing> joints;  // per cart: guide rollers, rod end, crank pin; then main bearing
  // The most loaded joint of each kind (largest P, else largest peak); nullptr when none.
  const JointSizing* worst(const std::string& joint) const;
};

// Nominal motor torque M_n at the rotor [N·m]: sizing.motor_nominal_torque, else
// sizing.motor_nominal_power/ω_n, else M_kr/λ from the Kloss data (motor.omega_nominal and
// motor.overload_ratio); NaN when none is given. `source` receives which, in words.
double nominalMotorTorque(const Scene& scene, std::string* source = nullptr);

// `turning`: whether the crank turns in the window (per-revolution figures are NaN otherwise);
// `delta`: the run's coefficient of unevenness (Metrics.h).
DriveSizing computeDriveSizing(const Scene& scene, const RunResult& run, const SteadyState& window,
                               bool turning, double delta);

// The machine's kinetic energy at each timeseries row [J], rigid-body parts at the crank axis:
//   T = ½J_n1·ω_motor² + ½J_c·ω_crank² + Σ_j ½(m'_B + m_rod/2)·v_j² + n·½(m_rod/2)·r²·ω_crank²,
// the rod counted half at the cart and half at the crank pin (Loveikin, Pochka, Romasevych (2018)
// eq. (2)-(3)); exact for split rods, within the rod's own rotation for distributed ones.
std::vector<double> kineticEnergy(const Scene& scene, const Table& timeseries);

}  // namespace rollerdyn
