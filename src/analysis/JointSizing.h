// The loads and rating lives of the drive's joints, computed once from a run's reactions over the
// steady window (the console, summary.json and the report only render them).
//
// How each joint's bearing moves, and so how its life is counted (θ = φ2 + the cart's crank phase,
// β the rod angle of the centred crank-slider, sin β = (r/l)·sin θ, src/physics/SliderCrank.h):
//  * guide rollers roll on their guide at n = |v_cart|/(d/2); they reverse twice per crank
//    revolution but turn 4r/(π·d) revolutions per crank revolution, far beyond any critical angle,
//    so they count as rotating: L10h = L10/(n̄/2π·3600) at the mean roller speed n̄;
//  * the rod end (the rod's small end on the cart's pin B) oscillates: the cart does not turn, the
//    rod swings through ±γ, γ = β_max = asin(r/l), once per crank revolution. Its P is weighted by
//    the swing speed |β̇| = |ω_crank·dβ/dθ|, and its life follows from the basic rating life of
//    ISO 281 by the oscillating-bearing conversion (Harris and Kotzalas (2007); the SKF rolling
//    bearings catalogue; reviewed by Menck and Stammler (2024)):
//        L10_osc = L10 · 180°/(2γ)  oscillations,   L10h = L10_osc / (3600·f),
//    f = n̄_crank/2π oscillations per second. Valid only when the full swing 2γ exceeds the
//    bearing's critical angle θ_crit = 720°/(Z·(1 ± D·cos α/d_m)) ≈ 720°/Z (Z rolling elements):
//    below it the loaded zones of neighbouring rolling elements do not overlap and the conversion
//    does not hold. The scene does not give Z, so the output states the least Z = 720°/(2γ);
//  * the crank pin turns relative to the rod's big end at the crank's rotation less the rod's
//    swing, n = |ω_crank·(1 + σ·dβ/dθ)| (the rod turns at −σ·β̇, σ the cart's side). As
//    |dβ/dθ| ≤ r/l < 1 it never reverses and makes exactly one relative revolution per crank
//    revolution: a rotating bearing at the mean crank speed, with P weighted by n;
//  * the main bearings: without crankshaft.bearing_positions the reactions give only the resultant
//    force the crankshaft's supports exert (all bearings together), and its life is that of one
//    bearing carrying the whole resultant, turning at |ω_crank|. With the throws and bearings placed
//    (crankshaft.*, CrankshaftBearings.h) each bearing gets its own row from bearing_x_k, bearing_y_k,
//    turning at |ω_crank| and rated with sizing.bearing_rating.main_bearing.
// Lives apply only to joints that move in a steady running: a drive that does not turn (stalled,
// rocking, at rest), that is still starting or coasting, or a run without a steady state gets no
// life (NaN) and the reason.
#pragma once

#include <string>
#include <vector>

#include "analysis/BearingLoad.h"
#include "analysis/RunResult.h"
#include "analysis/SteadyState.h"
#include "scene/Scene.h"

namespace rollerdyn {

struct JointSizing {
  std::string joint;        // guide_roller_front, guide_roller_rear, rod_end, crank_pin, main_bearing
  std::string what;         // the joint in words (the main bearings: the resultant, said so)
  int cart = 0;             // 1-based cart number; 0 for the main bearings
  int bearing = 0;          // main bearing number k along the shaft (1 = smallest z) when the scene gives
                            // crankshaft.bearing_positions; 0: not a main bearing, or their resultant
  double position = 0;      // the main bearing's axial position z [m]; NaN unless bearing > 0
  std::string column;       // reactions column(s) the force comes from
  std::string speed_basis;  // what weights P (rotation or swing speed used, or "none")
  JointLoad load;           // mean, amplitude, peak, equivalent dynamic load P, mean speed
  double rating = 0;        // C [N]; NaN when not given
  bool oscillating = false; // the rod end: swings through 2γ instead of turning
  double oscillation_angle = 0;      // full swing 2γ, end to end [rad]; NaN unless oscillating
  double oscillation_frequency = 0;  // oscillations per second f [1/s]; NaN unless oscillating
  double rolling_elements_min = 0;   // least number Z of rolling elements for which 2γ ≥ 720°/Z,
                                     // i.e. the conversion holds [-]; NaN unless oscillating
  double life_revolutions = 0;   // L10 = (C/P)³·10⁶ [-], ISO 281's basic rating life in revolutions
  double life_oscillations = 0;  // L10_osc = L10·180°/(2γ) [-]; NaN unless oscillating
  double life_hours = 0;         // L10h [h]
  std::string life_basis;        // how the life in hours follows, with its source and validity
  std::string life_reason;       // why the life is n/a (and what to do); "" when it is given
};

// The joints' loads and lives over the steady window `w`. `motion`: the crank's motion
// (RunMotion.h); lives only for "turning" with w.reached.
std::vector<JointSizing> sizeJoints(const Scene& scene, const RunResult& run, const SteadyState& w,
                                    const std::string& motion);

// Why no joint has a life in this run ("" when lives apply): the drive does not turn, is still
// starting, coasts, or the run reached no steady state.
std::string jointLifeNotApplicable(const std::string& motion, bool steady_reached);

}  // namespace rollerdyn
