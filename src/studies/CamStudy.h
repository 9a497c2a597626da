// Cam drive studies (Loveikin and Pochka (cam drive paper)): the cam profile of a scene, and a cam-driven cart compared with a
// crank-driven cart of equal stroke and cycle time (same scene, `drive.type` switched, so motor,
// reducer, coupling, cart and loads are identical and the cycle time 2π/ω follows from the same
// drive speed).
#pragma once

#include <string>
#include <vector>

#include "analysis/RunResult.h"
#include "io/Table.h"
#include "scene/Scene.h"

namespace rollerdyn {

// The cam's motion law and profile over one turn, `samples` rows θ = 0 ... 360° (inclusive):
// theta_deg, theta [rad], x [m] (about mid-stroke, eq. (32)-(34), (41)-(43)), dx_dtheta [m/rad],
// d2x_dtheta2 [m/rad²], d3x_dtheta3 [m/rad³], rho [m] (cam radius b/2 + x, eq. (38)-(43)),
// rho_opposite [m] (ρ(θ + π)), diameter [m] (ρ + ρ_opposite, = b), and the cart's motion at the
// constant crank speed ω_ref: t [s] = θ/ω_ref, v [m/s], a [m/s²], jerk [m/s³]. ω_ref is
// initial.crank_speed when > 0, else the synchronous crank speed ω0/u; t3 = π/ω_ref.
// Throws std::invalid_argument unless scene.cam.stroke > 0.
Table camProfileTable(const Scene& scene, int samples = 721);
double camReferenceSpeed(const Scene& scene);

// Steady-state extremes of cart 1 and the drive for one run.
struct DriveResponse {
  std::string drive;            // "cam" | "crank"
  std::string status;
  bool complete = false, steady = false;
  double omega_mean = 0;        // mean crank speed over the steady window [rad/s]
  double t3 = 0;                // half-cycle time π/ω_mean [s]
  double delta = 0;             // (ω_max - ω_min)/ω_mean, Loveikin and Pochka (2007) eq. (12)
  double stroke = 0;            // max - min of x_cart_1 [m]
  double velocity_peak = 0;     // max |v_cart_1| [m/s]
  double accel_peak = 0;        // max |a_cart_1| [m/s²]
  double jerk_peak = 0;         // max |da/dt|, central differences of a_cart_1 [m/s³]
  double coupling_torque_max = 0, coupling_torque_min = 0;  // [N·m]
  double motor_torque_max = 0;  // [N·m at the crank]
  double force_max = 0, force_min = 0;  // F_rod_1: rod force, or cam force under the cam [N]
  double force_abs_peak = 0;
  // The same peaks from the kinematics alone at constant speed ω_mean (cam: x''·ω², x'''·ω³;
  // crank: the exact slider-crank), to separate kinematics from drive dynamics.
  double accel_peak_kinematic = 0, jerk_peak_kinematic = 0;
};
DriveResponse driveResponse(const Scene& scene, const RunResult& run);

struct CamVsCrank {
  std::string model;            // multibody | reduced
  DriveResponse cam, crank;
  std::string note;             // e.g. unequal strokes
};
// Runs `scene_path` (with `overrides`) twice, with drive.type=cam and drive.type=crank.
CamVsCrank compareCamWithCrank(const std::string& scene_path, const std::vector<std::string>& overrides,
                               const std::string& model);
// One row per quantity: quantity, unit, cam, crank, ratio (cam/crank).
std::string camVsCrankCsv(const CamVsCrank& c);

}  // namespace rollerdyn
