// The installation in motion, for the HTML report: frames taken from the run's own time series
// (crank angle φ_2, cart positions x_cart_j) and reactions (guide reactions N_front_j, N_rear_j,
// rod forces F_rod_j), with the scene's geometry so that the page draws it to scale, and the
// section of the page that draws them on a <canvas> with play/pause, a time slider and force
// arrows scaled to their values.
//
// Drawing (one lane per cart, because the carts' crank planes lie one behind the other along the
// crankshaft axis z): plane x-y of cart j, x along the guides, y up, origin on the shaft axis.
//   crank pin   A_j = r·(cos θ_j, sin θ_j),  θ_j = φ_2 + (j-1)·Δφ   (src/physics/SliderCrank.h)
//   rod hinge   B_j = (x_cart_j, 0) on the cart's guide
//   cart        extends from B_j in its own direction σ_j (+1: +x side, -1: -x side):
//               guide rollers at x' = p ∓ b (N_front, N_rear), compacting rollers at x' = p ∓ a,
//               their contact with the mix at depth e below B (Loveikin, Pochka, Romasevych
//               (2018) fig. 3, eq. (10))
// The page's script only draws these numbers; it computes no kinematics of its own.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/Table.h"
#include "scene/Scene.h"

namespace rollerdyn {

struct MechanismGeometry {
  double crank_radius = 0;       // r [m]
  double rod_length = 0;         // l [m]; 0 with a cam drive (no rods)
  double crank_offset = 0;       // Δφ between consecutive cranks [rad] (NaN: crank.angles_deg)
  std::vector<double> crank_phases;  // θ_j - φ2 of each cart's crank, Scene::crankPhase(j) [rad]
  std::vector<double> masses;    // m'_B of each cart, Scene::cartMass(j) [kg]
  std::vector<int> sides;        // σ_j = +1 (cart on the +x side) or -1, per cart [-]
  CartGeometry cart;             // a, b, p, e, D, d, com_height of every cart [m]
  bool cam_drive = false;        // carts pushed by cams on the shaft: no crank pins, no rods
  double cam_radius = 0;         // half the pusher distance b_cam/2, drawn as the cam [m]
};

// Frames of one cart; all vectors have one entry per frame.
struct CartFrames {
  std::vector<double> pin_x, pin_y;  // crank pin A_j, world frame [m] (crank drive only)
  std::vector<double> hinge_x;       // rod hinge B_j on its guide, y = 0 [m] (= x_cart_j)
  std::vector<double> N_front, N_rear;  // guide reactions, > 0 when the guide presses the roller down [N]
  std::vector<double> F_rod;         // rod (or cam) force on the cart, > 0 in tension [N]
};

struct MechanismFrames {
  MechanismGeometry geometry;
  std::vector<std::size_t> rows;  // row of the time series each frame is taken from
  std::vector<double> t;          // frame times [s]
  std::vector<double> phi_crank;  // crank angle φ_2 of the first cart's crank [rad]
  std::vector<CartFrames> carts;
  bool has_forces = false;        // reactions.csv rows matched the time series rows
  double N_abs_max = 0;           // largest |N_front|, |N_rear| over the frames [N] (arrow scale)
  double F_rod_abs_max = 0;       // largest |F_rod| over the frames [N] (arrow scale)
  bool empty() const { return t.empty(); }
};

// Frames from every `stride`-th row of `timeseries` (stride chosen so that there are at most
// `max_frames`), with the reactions of the same rows when `reactions` has them (same number of
// rows and the same times; otherwise the arrows are left out). Throws std::invalid_argument if
// the time series lacks t, phi_crank or a cart's x_cart_j, or the scene has another number of
// carts than the table.
MechanismFrames mechanismFrames(const Scene& scene, const Table& timeseries, const Table& reactions,
                                std::size_t max_frames = 2500);

// The frames as the page reads them (numbers rounded to 6 significant digits).
nlohmann::json mechanismFramesJson(const MechanismFrames& frames);

// The report section: canvas, controls, the frame data and the drawing script. It announces the
// shown time to the page as the event "rollerdyn-time" (detail.t, seconds) and seeks on
// "rollerdyn-seek" (detail.t), so the time plots can follow it and be clicked. The section
// element carries data-frame and data-t (frame index and time shown) for tests.
std::string mechanismAnimationHtml(const MechanismFrames& frames);

}  // namespace rollerdyn
