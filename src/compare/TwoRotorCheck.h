// Analytic check of the multibody coupling element (src/multibody/ElasticCoupling.h) against the
// closed-form torsional response of two rotors on an elastic, damped link, Dyomin (two rotors),
// whose formulas live in physics/TwoRotorClosedForm.h: a Simbody system of two rotors on pin
// joints, joined by the coupling element, driven by the series M(t) of eq. (8), measured
// (free oscillation frequency and decay, steady harmonics, mean twist).
#pragma once

#include <vector>

#include "physics/TwoRotorClosedForm.h"

namespace rollerdyn::validation {

using rollerdyn::TwoRotorParameters;
using rollerdyn::HarmonicResponse;
using rollerdyn::naturalFrequency;
using rollerdyn::dampingRate;
using rollerdyn::dampedFrequency;
using rollerdyn::meanTwist;
using rollerdyn::driveTorque;
using rollerdyn::closedFormResponse;

// The rotors of the validation suite's check (and of its tests). Dyomin (two rotors) gives no numbers; they
// are the Loveikin, Pochka, Romasevych (2018) drive (ASSUMED): J1 = the motor side (J_p + J_m + J_red)·u² = 0.766·9.8²
// kg·m², J2 = 100 kg·m² (about the mean crank-side reduced inertia of four carts), k = c = 2e5
// N·m/rad, b = 2000 N·m·s/rad (Table 1's smaller damping), M1 = 1000 N·m, α = 30°, M_c = the
// mean drive torque M1(π - 2α)/π so the rotors keep a steady mean speed, ω = 10.68 rad/s (the
// Loveikin, Pochka, Romasevych (2018) crank speed).
TwoRotorParameters loveikin2018Drive();

// The Simbody system of the check: two Pin rotors on ground, the ElasticCoupling element
// between them, M(t) on rotor 1, -M_c on rotor 2.
struct ForcedResponseMeasurement {
  double mean_twist = 0;                       // [rad]
  std::vector<HarmonicResponse> harmonics;     // n = 1, 2, 3, 5 measured (amplitude_printed unused)
  double settle_time = 0;                      // time skipped before measuring [s]
  int periods = 0;                             // whole periods of ω measured
  int samples_per_period = 0;
  std::vector<double> t, twist;                // the measured samples (for plots)
};
// Integrates from rest (ψ = 0) for settle_time (transients decay as e^{-δ1·t}), then samples
// ψ at `samples_per_period` equally spaced times per period over `periods` periods and
// projects on 1, sin nωt, cos nωt (discrete orthogonality: exact for the harmonics n <
// samples_per_period/2 of a periodic signal).
ForcedResponseMeasurement measureForcedResponse(const TwoRotorParameters& p, double settle_time,
                                                int periods, int samples_per_period, double accuracy);

struct FreeOscillationMeasurement {
  double initial_twist = 0;        // ψ(0) [rad], rotors at rest, M = M_c = 0
  double frequency = 0;            // measured angular frequency of the oscillation [rad/s]
  double decay_rate = 0;           // measured δ from the ratio of extremes one period apart [1/s]
  double natural_frequency = 0;    // √(frequency² + decay_rate²): measured p0 [rad/s]
  int periods = 0;                 // whole periods between the first and last crossing used
  int decay_periods = 0;           // periods between the two maxima the decay rate is taken from
  std::vector<double> t, twist;    // samples (for plots)
};
// Free oscillation from an initial twist: the frequency from upward zero crossings of ψ
// (located by cubic Hermite interpolation with ψ̇ between samples), the decay from successive
// maxima (zeros of ψ̇, Hermite with ψ̈) one period apart.
FreeOscillationMeasurement measureFreeOscillation(const TwoRotorParameters& p, double initial_twist,
                                                  int periods, int samples_per_period, double accuracy);

}  // namespace rollerdyn::validation
