// The reducer's load spectrum and its application factor K_A after ISO 6336-6:2019 (calculation of
// service life under variable load), from the torque the reducer's output shaft transmits: the
// coupling torque (the reducer sits between the motor and the coupling, docs/models.md), at the
// crank axis like coupling.stiffness.
//
//   spectrum      the torque at each output interval, |T| binned into classes of width ΔT
//                 (class (k-1)·ΔT < |T| <= k·ΔT, represented by its upper limit k·ΔT, so T_eq errs
//                 high by less than one class width); the load cycles of a class are the
//                 revolutions of the output shaft (crank revolutions, |Δφ|/2π) spent in it. T > 0
//                 loads the drive flank, T < 0 (the crank driving the motor) the other flank of
//                 the teeth: a spectrum of its own.
//   T_eq          per flank, Miner's rule on the torque S-N curve T^p·N = const:
//                 T_eq = (Σ n_i·T_i^p / N_L)^(1/p) (ISO 6336-6 Annex A), N_L = all revolutions of the
//                 window (both flanks), so T_eq is the constant torque that does that flank's damage
//                 in the same running time. The elementary Miner rule (every class damages, no
//                 endurance limit) errs on the safe side. T_eq is a ratio of sums: the same for the
//                 pinion, whose cycles are a fixed multiple of the wheel's.
//   duty hour     with sizing.starts_per_hour = N: one hour = N starts (switch-on to the start's end,
//                 t_D each) and 3600 s - N·t_D of steady running (the steady window's spectrum
//                 scaled); without it continuous running (the steady window alone).
//   K_A           = max over both flanks of T_eq / T_n, T_n = u·η·M_n the torque at the crank when
//                 the motor delivers its nominal torque M_n (DriveSizing.h, nominalMotorTorque).
// Checks (SignOffChecks.cpp): K_A <= the designer's K_A (sizing.reducer.application_factor);
// T_eq <= T_2N (sizing.reducer.rated_torque: the constant output torque the reducer carries for its
// design life at service factor 1; the same life assumed for the duty); the largest |T| of the
// start and the steady window <= T_2max (sizing.reducer.max_torque).
#pragma once

#include <string>
#include <vector>

#include "analysis/SteadyState.h"

namespace rollerdyn {

struct Scene;
struct RunResult;
struct StartUp;
struct Table;

// Torque classes of each flank's spectrum over [0, the largest |T| of the start and steady window].
inline constexpr int kGearTorqueClasses = 40;

struct TorqueClass {
  double torque = 0;  // the class's upper limit T_i [N·m]
  double cycles = 0;  // n_i, load cycles: output-shaft (crank) revolutions in the class [-]
};

// T_eq = (Σ n_i·T_i^p / N_L)^(1/p) [N·m]; NaN when N_L <= 0.
double equivalentTorque(const std::vector<TorqueClass>& classes, double p, double total_cycles);

struct FlankSpectrum {
  std::vector<TorqueClass> classes;  // the classes that hold cycles, ascending torque
  double cycles = 0;                 // Σ n_i of this flank [-]
  double equivalent_torque = 0;      // T_eq with N_L = the window's revolutions (both flanks) [N·m]
};

struct GearSpectrum {
  bool applies = false;
  std::string not_applicable;        // why not, and what to do
  double t_begin = 0, t_end = 0;     // [s]
  double revolutions = 0;            // N_L, all crank revolutions of the window [-]
  FlankSpectrum drive, coast;        // T > 0 and T < 0
};

// The spectrum of rows [b, e) of a table with t, phi_crank and coupling_torque, classes of width
// `class_width` [N·m]; each output interval counts at the mean torque of its two rows.
GearSpectrum loadSpectrum(const Table& ts, std::size_t b, std::size_t e, double class_width, double p);

struct GearDuty {
  bool requested = false;            // any of sizing.reducer.application_factor, rated_torque, max_torque
  double exponent = 0;               // p (sizing.reducer.sn_exponent) [-]
  double class_width = 0;            // ΔT [N·m]
  double nominal_torque = 0;         // T_n = u·η·M_n at the crank [N·m]; NaN: M_n not known
  std::string nominal_source;        // where M_n comes from
  double assumed_application_factor = 0;  // sizing.reducer.application_factor; NaN: not given
  double rated_torque = 0, max_torque = 0;  // T_2N, T_2max [N·m]; NaN: not given
  GearSpectrum start, steady;        // the start from rest (switch-on to its end) and the steady window
  double starts_per_hour = 0;        // N of the duty [1/h]; 0: continuous running
  bool duty_applies = false;         // the duty hour's T_eq is known
  std::string duty_not_applicable;   // why not, and what to do
  std::string duty_basis;            // what the hour holds, in words
  double hour_revolutions = 0;       // N_L of one hour of the duty [-]
  double equivalent_torque_drive = 0, equivalent_torque_coast = 0;  // T_eq of the duty hour [N·m]
  double equivalent_torque = 0;      // the larger [N·m]
  std::string deciding_flank;        // "drive flank" or "other flank (reversed torque)"
  double application_factor = 0;     // K_A = T_eq / T_n [-]
  double peak = 0, t_peak = 0;       // largest |T| of the start and the steady window [N·m], when [s]
  double application_ratio = 0;      // K_A / assumed K_A [-]
  double rated_ratio = 0;            // T_eq / T_2N [-]
  double max_ratio = 0;              // peak / T_2max [-]
};

GearDuty computeGearDuty(const Scene& scene, const RunResult& run, const SteadyState& window, const StartUp* start_up);

}  // namespace rollerdyn
