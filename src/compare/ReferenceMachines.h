// Published induction machines the motor laws are validated against (data only).
#pragma once

#include <cmath>

#include "motor/InductionMachine.h"

namespace rollerdyn::reference {

// The Modelica Standard Library's default squirrel-cage machine
// (Modelica.Electrical.Machines.Utilities.ParameterRecords.IM_SquirrelCageData, used by the
// example Modelica.Electrical.Machines.Examples.InductionMachines.IMC_DOL): R_s 0.03 Ω,
// R_r 0.04 Ω, L_σs = L_σr = 3(1 − √(1 − 0.0667))/(2π·50) H, L_m = 3√(1 − 0.0667)/(2π·50) H,
// 2 pole pairs, 100 V per phase, 50 Hz, J_r 0.29 kg·m². Rated point 161.4 N·m at 1440.45 rpm, 100 A.
inline InductionMachineParameters mslSquirrelCage() {
  InductionMachineParameters m;
  const double w = 2 * M_PI * 50, k = std::sqrt(1 - 0.0667);
  m.R_s = 0.03;
  m.L_sigma_s = 3 * (1 - k) / w;
  m.L_m = 3 * k / w;
  m.cages = 1;
  m.R_r[0] = 0.04;
  m.L_sigma_r[0] = 3 * (1 - k) / w;
  m.pole_pairs = 2;
  m.phase_voltage = 100;
  m.frequency = 50;
  return m;
}
inline constexpr double kMslRotorInertia = 0.29;        // J_r [kg·m²]
inline constexpr double kMslLoadInertia = 0.29;         // IMC_DOL's JLoad [kg·m²]
inline constexpr double kMslRatedTorque = 161.4;        // TLoad [N·m]
inline constexpr double kMslRatedSpeedRpm = 1440.45;    // wLoad [rpm]
inline constexpr double kMslRatedCurrent = 100.0;       // IsNominal [A]

// Krause's 3 hp machine (Krause, Wasynczuk, Sudhoff, "Analysis of Electric Machinery and Drive
// Systems", free-acceleration example): 220 V line-to-line, 60 Hz, 4 poles, r_s 0.435 Ω,
// X_ls = X'_lr 0.754 Ω, X_M 26.13 Ω, r'_r 0.816 Ω, J 0.089 kg·m².
inline InductionMachineParameters krause3hp() {
  InductionMachineParameters m;
  const double w = 2 * M_PI * 60;
  m.R_s = 0.435;
  m.L_sigma_s = 0.754 / w;
  m.L_m = 26.13 / w;
  m.cages = 1;
  m.R_r[0] = 0.816;
  m.L_sigma_r[0] = 0.754 / w;
  m.pole_pairs = 2;
  m.phase_voltage = 220 / std::sqrt(3.0);
  m.frequency = 60;
  return m;
}
inline constexpr double kKrause3hpInertia = 0.089;  // J [kg·m²]

}  // namespace rollerdyn::reference
