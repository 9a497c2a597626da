// Campbell diagram of the drive's torsional mode: its natural frequency (mean and band over the
// crank angle, frozen-angle, FrozenModes.h, along the steady motion at each speed) and the
// Floquet frequency against the orders k·ω of the crank speed that excite the drive
// (ExcitationOrders.h). Crossings:
//   forced resonance       p = k·ω      (a harmonic of the load or of the inertia's
//                                         Coriolis torque ½·J_n2'·ω² drives the coupling)
//   parametric (principal) 2p = k·ω     (the inertia's harmonic k pumps the mode at half its order)
// so a forced crossing of order k lies at the crank speed ω = p/k and a parametric one at
// ω = 2p/k, for odd k as for even k (order 9: ω = 2p/9, not p/4).
// Only where the mode oscillates: at a speed where its frozen-angle damped pair is real at some
// crank angle (ζ ≥ 1, overdamped, FrozenModes.h) it has no frequency to meet a line with, and no
// crossing is listed on either side of that speed; the diagram's note counts those speeds.
// The crank speed is varied as a frequency converter does (sceneAtCrankSpeed, DriveOrbit.h).
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "modes/ExcitationOrders.h"
#include "modes/FrozenModes.h"
#include "scene/Scene.h"

namespace rollerdyn::modes {

struct CampbellPoint {
  double omega_target = 0;     // speed asked for [rad/s]
  bool found = false;          // steady motion found
  std::string failure;
  double omega_mean = 0;       // mean crank speed of the steady motion [rad/s]
  Band frozen;                 // torsional frozen-angle frequency over a revolution [rad/s]
  Band frozen_damping;         // its damping ratio over the revolution [-]
  bool oscillates = false;     // the mode's damped pair is complex (ζ < 1) at every crank angle
  double floquet_frequency = NAN, floquet_damping_ratio = NAN, max_modulus = NAN;
};

struct CampbellCrossing {
  int order = 0;
  bool parametric = false;     // 2p = k·ω (else p = k·ω)
  double omega = 0;            // crank speed where the mean frequency meets the line [rad/s]
  double frequency = 0;        // p there [rad/s]
  double omega_band_low = NAN, omega_band_high = NAN;  // speeds where the line crosses the band's edges
};

struct CampbellDiagram {
  bool applicable = false;     // elastic coupling and a motor
  std::string note;
  std::vector<int> orders;     // excitation orders drawn
  std::vector<CampbellPoint> points;
  std::vector<CampbellCrossing> crossings;
  int overdamped_speeds = 0;   // speeds (with a steady motion) where the mode does not oscillate
};

// The crank speeds where a frequency f(ω), sampled at speeds w, meets the line slope·ω (linear
// interpolation of f - slope·ω between neighbouring samples; NaN samples break the line).
std::vector<double> lineCrossings(const std::vector<double>& w, const std::vector<double>& f, double slope);

// The slope of order k's line: k (forced, p = k·ω) or k/2 (parametric, 2p = k·ω).
inline double campbellSlope(int k, bool parametric) { return parametric ? 0.5 * k : double(k); }

CampbellDiagram campbellDiagram(const Scene& scene, double omega_operating, const std::vector<double>& speeds,
                                const std::vector<int>& orders, int angles = 36);

}  // namespace rollerdyn::modes
