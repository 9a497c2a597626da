// `rollerdyn modes`: the torsional modes and the stability of a drive in one analysis.
//   1. steady motion of the reduced model (a periodic orbit, DriveOrbit.h) at the scene's operating
//      point, its Floquet multipliers and verdict (and the multibody model's, where asked);
//   2. frozen-angle modes along that motion from both models (FrozenModes.h), side by side;
//   3. the excitation orders of the layout (ExcitationOrders.h);
//   4. the Campbell diagram over crank speed (Campbell.h) and the separation margins at the
//      operating speed (SeparationMargins.h);
//   5. stability charts over coupling stiffness × crank speed and × damping (StabilityChart.h).
// The two-mass estimate of Dyomin (two rotors) eq. (10) with the mean crank-side inertia is given
// beside it as the first, cheap estimate it is.
#pragma once

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/PhaseClock.h"
#include "io/Table.h"
#include "modes/Campbell.h"
#include "modes/DriveOrbit.h"
#include "modes/ExcitationOrders.h"
#include "modes/FrozenModes.h"
#include "modes/ChainModes.h"
#include "modes/SeparationMargins.h"
#include "modes/StabilityChart.h"
#include "scene/Scene.h"

namespace rollerdyn::modes {

struct ModesOptions {
  bool multibody = true;         // frozen-angle modes (and Floquet) of the multibody model too
  bool multibody_floquet = true; // the multibody model's own steady motion and multipliers
  int angles = 72;               // frozen-angle samples per revolution
  bool campbell = true;
  int speeds = 21;               // Campbell speeds from speed_low·ω to speed_high·ω
  double speed_low = 0.3, speed_high = 1.5;
  bool charts = true;
  int chart_c = 16, chart_y = 10;  // grid points: stiffness, speed (or damping)
  double c_low = 0.05, c_high = 5.0;  // stiffness range as factors of the scene's c (rigid: of the
                                      // stiffness that puts the two-mass p0 at 6ω)
  double chart_speed_low = 0.4, chart_speed_high = 1.3;
  std::vector<double> chart_dampings;  // c × ω charts at these k; empty: the scene's k
  std::vector<double> marked_dampings; // k values marked on the c × k chart (e.g. a paper's)
  double damping_high = 0;             // top of the c × k chart; 0: 2·max(scene k, marked, 1000)
  int max_newton = 30;                 // Newton iterations on the period map (the steady motion)
  int warmup_periods = 3;              // revolutions integrated from the first guess before Newton
  PhaseClock* clock = nullptr;         // times the analysis' phases (bench); null: not timed
};

struct ModelFrozenModes {
  std::string model;             // "reduced" | "multibody"
  bool ok = false;
  std::string failure;
  std::vector<FrozenAngle> angles;  // along the steady motion
  Band torsional;                // torsional frequency over the revolution [rad/s]
  Band torsional_damping;        // its frozen damping ratio [-]
  Band torsional_damped;         // its frozen damped frequency Im λ [rad/s] (the Floquet branch's reference;
                                 // 0 at angles where the mode is overdamped)
  Band torsional_natural;        // ω_n of its damped pair [rad/s] (the pair ζ belongs to, FrozenModes.h)
  int torsional_overdamped_angles = 0;  // crank angles where it does not oscillate (ζ ≥ 1)
  Band oscillation_damped;       // FrozenAngle::oscillation_frequency() [rad/s] (the Floquet branch's reference)
  // The other mode (rigid-body without damping) where its damped pair oscillates: ω_n, ζ, and at
  // how many crank angles (heavy non-proportional damping: the coupling mode overdamped, this one
  // oscillating).
  Band other_natural, other_damping;
  int other_oscillating_angles = 0;
  std::string torsional_name, rigid_name;
  double energy_motor_side = NAN, energy_shaft_rods = NAN, energy_carts = NAN;  // torsional mode, mean
};

struct TwoMassEstimate {
  bool applicable = false;
  double J1 = 0, J2_mean = 0, stiffness = 0, p0 = 0;  // Dyomin (two rotors) eq. (10)
};

struct ModesReport {
  std::string scene;
  bool elastic = false, motor = false;
  double cpu_seconds = 0;
  TwoMassEstimate two_mass;
  SteadyMotion steady;            // reduced model
  SteadyMotion steady_multibody;  // when asked
  bool has_multibody_steady = false;
  ExcitationOrders orders;
  std::vector<ModelFrozenModes> frozen;  // reduced first
  double model_difference = NAN;  // max relative difference of the torsional frequencies
  CampbellDiagram campbell;
  SeparationMargins separation;   // of the coupling mode from the orders that drive it (SeparationMargins.h)
  CrankshaftChainModes chain;     // the crankshaft's torsional chain's modes (ChainModes.h); not applicable
                                  // for a rigid crankshaft
  std::vector<StabilityChart> charts;
  std::vector<std::string> warnings;  // resonance warnings resting on this analysis
  std::vector<std::string> notes;     // what was not done and why
  // Approximations the analysis rests on, by name, each with what it means and where it fails
  // (e.g. "permanent tooth contact" under reducer.backlash > 0).
  std::vector<std::pair<std::string, std::string>> approximations;
  // No steady motion: the speed of the uniform rotation the frozen-angle modes are taken at (where
  // the motor's static curve carries the mean load), NaN when none (no modes at all).
  double fallback_omega = NAN;
};

// With reducer.backlash > 0 the analysis is that of the drive with its teeth permanently in
// contact (the backlash taken as 0), named in `approximations`: linear modes have no gap.
ModesReport analyseModes(const Scene& scene, const ModesOptions& options = {});

// The first estimate: J1, the crank side's mean inertia over a revolution (720 samples) and p0 of
// Dyomin (two rotors) eq. (10) (elastic coupling only).
TwoMassEstimate twoMassEstimate(const ReducedModel& model);

nlohmann::json modesJson(const ModesReport& r);
Table frozenTable(const ModesReport& r);    // frozen.csv
Table campbellTable(const ModesReport& r);  // campbell.csv
Table stabilityTable(const ModesReport& r); // stability.csv (all charts, long format)
// The console's lines. `run_stability_na`: beside a run without a steady motion (its stability
// verdict not applicable, runStabilityNotApplicable in RunModes.h), the reason, printed in place of
// the Floquet verdicts.
std::string modesText(const ModesReport& r, const std::string& run_stability_na = "");

// What `rollerdyn modes` writes into out_dir (which must exist): modes.json, frozen.csv,
// campbell.csv, stability.csv.
void writeModesFiles(const std::string& out_dir, const ModesReport& r);

// The charts' stiffness range lo ... hi [N·m/rad] (`modes --stiffness LO:HI`) as the factors of
// the scene's coupling stiffness the options hold. Throws std::invalid_argument starting with
// `what` unless 0 < lo < hi and the coupling is elastic.
void setChartStiffness(ModesOptions& o, const Scene& scene, double lo, double hi, const std::string& what);

// Resonance warnings of the analysis: the steady motion unstable (a Floquet multiplier > 1), or the
// torsional mode's Floquet frequency within 5 % of k·ω for an order k that drives the coupling mode
// (`orders.forced`: at least 1 % of the largest exciting torque harmonic, ExcitationOrders.h; none
// when the mode decays more than a million-fold per revolution: nothing can build up). A driven
// machine whose steady motion was not found gets a warning that says so and why (no verdict rests
// on the analysis then). `omega`: the crank speed the orders are taken at (a run's steady mean
// crank speed; without it the steady motion's own, with r.orders).
std::vector<std::string> modalWarnings(const ModesReport& r);
std::vector<std::string> modalWarnings(const ModesReport& r, double omega, const ExcitationOrders& orders);

}  // namespace rollerdyn::modes
