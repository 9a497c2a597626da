// A simulated run against the Floquet prediction: the reduced model (its own CVODE integrator, not
// the Floquet code's) started on the periodic steady motion at the crank angle where the twist
// rate vanishes (the model's start state has ψ̇ = 0), for R revolutions. The twist's departure
// from the periodic motion, sampled once per revolution at that angle, grows or decays by the
// largest multiplier modulus per revolution (the seed is the integrator's own error). Its order
// spectrum over the last revolutions shows the growing mode's frequency as a peak between whole
// orders (half an order for a multiplier below -1).
#pragma once

#include <string>
#include <vector>

#include "modes/OrderSpectrum.h"
#include "scene/Scene.h"

namespace rollerdyn::modes {

struct GrowthMeasurement {
  bool ok = false;
  std::string failure;
  double predicted_modulus = 0;      // max |μ| of the Floquet analysis
  double predicted_order = 0;        // the growing mode's frequency / mean crank speed (NaN: unresolved)
  double measured_growth = 0;        // per revolution, fitted over the linear part of the run
  int revolutions_fitted = 0;
  std::vector<double> deviation;     // |ψ(φ* + 2πn) - ψ*| per revolution [rad]
  double start_angle = 0;            // φ* [rad]
  OrderSpectrum spectrum;            // coupling torque and twist over the last revolutions
  double peak_order = 0;             // strongest component of the twist not at a whole order (NaN: none)
  double whole_order_share = 1;      // of the twist's spectrum
};

GrowthMeasurement measureGrowth(const Scene& scene, int revolutions, int spectrum_revolutions);

}  // namespace rollerdyn::modes
