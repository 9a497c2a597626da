#include "physics/ReducerLosses.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace rollerdyn {

namespace {
constexpr double kTorqueBandShare = 0.01;  // T_b / (M_kr·u), ReducerLosses.h
constexpr double kSpeedBandShare = 1e-3;   // ω_b / (ω0/u)
}  // namespace

ReducerLaw reducerLaw(const Scene& sc, double breakdown_torque) {
  ReducerLaw law;
  law.model = sc.reducer.losses;
  law.ratio = sc.reducer.ratio;
  law.eta_forward = sc.reducer.efficiency;
  law.eta_reverse = sc.reducer.reverseEfficiency();
  law.torque_band = std::max(kTorqueBandShare * breakdown_torque * sc.reducer.ratio, 1e-6);
  const double w_sync = sc.reducer.ratio > 0 ? sc.motor.omega_sync / sc.reducer.ratio : 0.0;
  law.speed_band = std::max(kSpeedBandShare * w_sync, 1e-9);
  return law;
}

double reducerLossTorque(const ReducerLaw& law, double M, double w) {
  const double T = M * law.ratio;
  if (law.model == ReducerLossModel::Papers) return T - T * law.eta_forward;
  const double sigma = std::tanh(w / law.speed_band);
  const double a = T * std::tanh(T / law.torque_band);
  const double k_f = 1.0 - law.eta_forward, k_r = 1.0 / law.eta_reverse - 1.0;
  const double wgt = 0.5 * (1.0 + std::tanh(sigma * T / law.torque_band));
  return sigma * a * (k_f * wgt + k_r * (1.0 - wgt));
}

double reducerCrankTorque(const ReducerLaw& law, double M, double w) {
  // Papers: exactly eq. (37)'s M·u·η, evaluated in that order (bit-identical to the runs before
  // the law had a second setting).
  if (law.model == ReducerLossModel::Papers) return M * law.ratio * law.eta_forward;
  return M * law.ratio - reducerLossTorque(law, M, w);
}

double reducerShaftTorque(const ReducerLaw& law, double crank_torque, double loss_torque) {
  if (law.model == ReducerLossModel::Papers) return crank_torque / (law.ratio * law.eta_forward);
  return (crank_torque + loss_torque) / law.ratio;
}

std::string reducerLossWords(const ReducerLaw& law) {
  std::ostringstream o;
  o.precision(4);
  if (law.model == ReducerLossModel::Papers) {
    o << "loss law: the papers' constant η = " << law.eta_forward
      << " both ways (M·u·η, Loveikin, Pochka, Romasevych (2018) eq. (37)): while the crank side drives the "
         "motor the reducer gains (1 − η)·|P| instead of losing it";
  } else {
    o << "loss law: by the direction of the power flow (Modelica's LossyGear), (1 − η_f)·|P| while the motor "
         "drives, (1/η_r − 1)·|P| while the crank side drives, η_f = "
      << law.eta_forward << ", η_r = " << law.eta_reverse << ", blended over |M·u| < " << law.torque_band << " N·m";
  }
  o << " (P power at the motor shaft, M motor torque, u reducer ratio)";
  return o.str();
}

}  // namespace rollerdyn
