#include "studies/CamStudy.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "analysis/SteadyState.h"
#include "multibody/MultibodySimulation.h"
#include "physics/CamMotionLaw.h"
#include "physics/SliderCrank.h"
#include "reduced/ReducedModel.h"
#include "scene/SceneParser.h"
#include "compare/RunModel.h"

namespace rollerdyn {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Peak |x''|·ω² and |x'''|·ω³ of cart 1's kinematics over one turn at constant ω.
void kinematicPeaks(const Scene& sc, double omega, double* a_peak, double* j_peak) {
  const int n = 7200;
  const double h = 1e-4;  // [rad] for the crank's third derivative by central differences
  double a = 0, j = 0;
  for (int i = 0; i < n; ++i) {
    const double th = 2 * M_PI * i / n;
    double d2, d3;
    if (sc.hasCamDrive()) {
      const CamMotionSample c = camMotion(th, sc.cam.stroke);
      d2 = c.d2x;
      d3 = c.d3x;
    } else {
      const double r = sc.crank.radius, l = sc.rods.length;
      d2 = sliderCrankExact(th, r, l, 1).d2x_B;
      d3 = (sliderCrankExact(th + h, r, l, 1).d2x_B - sliderCrankExact(th - h, r, l, 1).d2x_B) / (2 * h);
    }
    a = std::max(a, std::abs(d2) * omega * omega);
    j = std::max(j, std::abs(d3) * omega * omega * omega);
  }
  *a_peak = a;
  *j_peak = j;
}

}  // namespace

double camReferenceSpeed(const Scene& sc) {
  return sc.initial.crank_speed > 0 ? sc.initial.crank_speed : sc.motor.omega_sync / sc.reducer.ratio;
}

Table camProfileTable(const Scene& sc, int samples) {
  if (!(sc.cam.stroke > 0)) throw std::invalid_argument("cam profile: the scene has no cam.stroke > 0");
  if (samples < 2) samples = 2;
  const double dx = sc.cam.stroke, b = sc.cam.pusher_distance > 0 ? sc.cam.pusher_distance : 2 * dx;
  const double w = camReferenceSpeed(sc);
  Table t;
  t.columns = {"theta_deg", "theta", "x", "dx_dtheta", "d2x_dtheta2", "d3x_dtheta3", "rho", "rho_opposite",
               "diameter", "t", "v", "a", "jerk"};
  for (int i = 0; i < samples; ++i) {
    const double th = 2 * M_PI * i / (samples - 1);
    const CamMotionSample c = camMotion(th, dx);
    const double rho = camProfileRadius(th, dx, b), rho_op = camProfileRadius(th + M_PI, dx, b);
    t.rows.push_back({th * 180 / M_PI, th, c.x, c.dx, c.d2x, c.d3x, rho, rho_op, rho + rho_op, th / w, c.dx * w,
                      c.d2x * w * w, c.d3x * w * w * w});
  }
  return t;
}

namespace {

// The steady window's rows [b, e): mean crank speed (from the crank angle), half-cycle time, δ and stroke.
void windowSpeedAndStroke(const Table& ts, std::size_t b, std::size_t e, DriveResponse& r) {
  const int it = ts.index("t"), iw = ts.index("omega_crank"), ix = ts.index("x_cart_1"), iphi = ts.index("phi_crank");
  double wmin = 1e300, wmax = -1e300, xmin = 1e300, xmax = -1e300;
  for (std::size_t k = b; k < e; ++k) {
    const auto& row = ts.rows[k];
    wmin = std::min(wmin, row[iw]);
    wmax = std::max(wmax, row[iw]);
    xmin = std::min(xmin, row[ix]);
    xmax = std::max(xmax, row[ix]);
  }
  const double span_t = ts.rows[e - 1][it] - ts.rows[b][it];
  r.omega_mean = (ts.rows[e - 1][iphi] - ts.rows[b][iphi]) / span_t;
  r.t3 = M_PI / r.omega_mean;
  r.delta = (wmax - wmin) / r.omega_mean;
  r.stroke = xmax - xmin;
}

// The steady window's peaks: cart velocity, acceleration and jerk (central differences of the
// acceleration), coupling torque range, largest |motor torque|.
void windowPeaks(const Table& ts, std::size_t b, std::size_t e, DriveResponse& r) {
  const int it = ts.index("t"), iv = ts.index("v_cart_1"), ia = ts.index("a_cart_1"),
            ic = ts.index("coupling_torque"), im = ts.index("motor_torque");
  r.coupling_torque_max = -1e300;
  r.coupling_torque_min = 1e300;
  for (std::size_t k = b; k < e; ++k) {
    const auto& row = ts.rows[k];
    r.velocity_peak = std::max(r.velocity_peak, std::abs(row[iv]));
    r.accel_peak = std::max(r.accel_peak, std::abs(row[ia]));
    r.coupling_torque_max = std::max(r.coupling_torque_max, row[ic]);
    r.coupling_torque_min = std::min(r.coupling_torque_min, row[ic]);
    r.motor_torque_max = std::max(r.motor_torque_max, std::abs(row[im]));
    if (k > b && k + 1 < e) {
      const auto &prev = ts.rows[k - 1], &next = ts.rows[k + 1];
      r.jerk_peak = std::max(r.jerk_peak, std::abs((next[ia] - prev[ia]) / (next[it] - prev[it])));
    }
  }
}

// The drive force (the rod's, F_rod_1) over the steady window, from the reactions.
void driveForceRange(const Table& rx, const SteadyState& ss, DriveResponse& r) {
  if (!(rx.has("t") && rx.has("F_rod_1"))) {  // simulation.reactions: false: the drive force is not computed
    r.force_max = r.force_min = r.force_abs_peak = std::nan("");
    return;
  }
  const int rt = rx.index("t"), rf = rx.index("F_rod_1");
  r.force_max = -1e300;
  r.force_min = 1e300;
  for (const auto& row : rx.rows) {
    if (row[rt] < ss.t_begin - 1e-12 || row[rt] > ss.t_end + 1e-12) continue;
    r.force_max = std::max(r.force_max, row[rf]);
    r.force_min = std::min(r.force_min, row[rf]);
  }
  r.force_abs_peak = std::max(std::abs(r.force_max), std::abs(r.force_min));
}

}  // namespace

DriveResponse driveResponse(const Scene& sc, const RunResult& run) {
  DriveResponse r;
  r.drive = toString(sc.drive);
  r.status = run.stats.status;
  r.complete = run.stats.complete;
  const SteadyState ss = detectSteadyState(run, sc.simulation.steady_window_revolutions);
  r.steady = ss.reached;
  const std::size_t b = ss.row_begin, e = ss.row_end;
  if (e <= b + 2) {
    r.status += "; no steady-state window";
    return r;
  }
  windowPeaks(run.timeseries, b, e, r);
  windowSpeedAndStroke(run.timeseries, b, e, r);
  driveForceRange(run.reactions, ss, r);
  kinematicPeaks(sc, r.omega_mean, &r.accel_peak_kinematic, &r.jerk_peak_kinematic);
  return r;
}

CamVsCrank compareCamWithCrank(const std::string& scene_path, const std::vector<std::string>& overrides,
                               const std::string& model) {
  if (model != "multibody" && model != "reduced")
    throw std::invalid_argument("cam vs crank: model must be multibody or reduced");
  CamVsCrank out;
  out.model = model;
  for (const char* drive : {"cam", "crank"}) {
    std::vector<std::string> ov = overrides;
    ov.push_back(std::string("drive.type=") + drive);
    const Scene sc = parseSceneFile(scene_path, ov);
    const RunResult run = runModel(sc, model);
    (std::string(drive) == "cam" ? out.cam : out.crank) = driveResponse(sc, run);
    if (std::string(drive) == "crank" && std::abs(2 * sc.crank.radius - sc.cam.stroke) > 1e-9)
      out.note = "strokes differ: cam.stroke = " + std::to_string(sc.cam.stroke) + " m, crank 2r = " +
                 std::to_string(2 * sc.crank.radius) + " m";
  }
  return out;
}

namespace {

// One quantity of the comparison, cam beside crank.
struct CamVsCrankRow {
  const char* name;
  const char* unit;
  double cam, crank;
};

std::vector<CamVsCrankRow> camVsCrankRows(const CamVsCrank& c) {
  const DriveResponse &a = c.cam, &b = c.crank;
  return {
      {"omega_mean", "rad/s", a.omega_mean, b.omega_mean},
      {"half_cycle_time_t3", "s", a.t3, b.t3},
      {"delta", "-", a.delta, b.delta},
      {"stroke", "m", a.stroke, b.stroke},
      {"velocity_peak", "m/s", a.velocity_peak, b.velocity_peak},
      {"accel_peak", "m/s^2", a.accel_peak, b.accel_peak},
      {"accel_peak_kinematic", "m/s^2", a.accel_peak_kinematic, b.accel_peak_kinematic},
      {"jerk_peak", "m/s^3", a.jerk_peak, b.jerk_peak},
      {"jerk_peak_kinematic", "m/s^3", a.jerk_peak_kinematic, b.jerk_peak_kinematic},
      {"coupling_torque_max", "N*m", a.coupling_torque_max, b.coupling_torque_max},
      {"coupling_torque_min", "N*m", a.coupling_torque_min, b.coupling_torque_min},
      {"motor_torque_abs_max", "N*m", a.motor_torque_max, b.motor_torque_max},
      {"drive_force_max", "N", a.force_max, b.force_max},
      {"drive_force_min", "N", a.force_min, b.force_min},
      {"drive_force_abs_peak", "N", a.force_abs_peak, b.force_abs_peak},
  };
}

}  // namespace

std::string camVsCrankCsv(const CamVsCrank& c) {
  std::ostringstream os;
  os << "quantity,unit,cam,crank,ratio_cam_over_crank\n";
  for (const CamVsCrankRow& r : camVsCrankRows(c)) {
    char buf[256];
    std::snprintf(buf, sizeof buf, "%s,%s,%.6g,%.6g,%.4g\n", r.name, r.unit, r.cam, r.crank,
                  r.crank != 0 ? r.cam / r.crank : kNaN);
    os << buf;
  }
  return os.str();
}

}  // namespace rollerdyn
