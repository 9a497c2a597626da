#include "scene/Plausibility.h"
#include "scene/MotorModels.h"

#include <cmath>
#include <cstdio>

namespace rollerdyn {
namespace {

// A length typed in millimetres under a key in metres.
void lengthsInMillimetres(const Scene& s, std::vector<std::string>& out) {
  const struct {
    const char* key;
    double value;
  } lengths[] = {
      {"crank.radius", s.crank.radius},          {"rods.length", s.rods.length},
      {"carts.geometry.a", s.carts.geometry.a},  {"carts.geometry.b", s.carts.geometry.b},
      {"carts.geometry.p", s.carts.geometry.p},  {"carts.geometry.e", s.carts.geometry.e},
      {"carts.geometry.D", s.carts.geometry.D},  {"carts.geometry.d", s.carts.geometry.d},
      {"carts.geometry.com_height", s.carts.geometry.com_height},
      {"cam.stroke", s.cam.stroke},              {"cam.pusher_distance", s.cam.pusher_distance},
  };
  for (const auto& l : lengths) {
    if (!(l.value > kImplausibleLength)) continue;
    char buf[300];
    std::snprintf(buf, sizeof buf,
                  "%s = %g m is implausible for a roller forming installation (above %g m): scene lengths are in "
                  "metres; if you meant %g mm, write %g",
                  l.key, l.value, kImplausibleLength, l.value, l.value / 1000.0);
    out.push_back(buf);
  }
}

// A crank angle typed in radians under a key in degrees: a value below 2π that is not a whole
// number of degrees (1.0472 is 60° typed as radians; 3 or 5 degrees are whole and stay silent).
void degreesTypedAsRadians(const Scene& s, std::vector<std::string>& out) {
  auto radiansTyped = [&out](const std::string& key, double v) {
    if (!(v > 0.0 && v < 2 * M_PI + 1e-3)) return;
    const double deg = v * 180.0 / M_PI;
    // Any fractional value below 2π: crank offsets are tens of degrees, and a radian value typed
    // with two or three decimals (3.14, 2.09, 0.52) lands near no round angle (the fourth trial).
    if (std::abs(v - std::round(v)) < 1e-9) return;
    char buf[300];
    std::snprintf(buf, sizeof buf,
                  "%s = %g is read as %g° (the key is in degrees); as radians it would be %.4g°: if you meant "
                  "%g rad, write %.4g",
                  key.c_str(), v, v, deg, v, deg);
    out.push_back(buf);
  };
  if (s.crank.angles.empty())
    radiansTyped("crank.offset_deg", s.crank.offset * 180.0 / M_PI);
  else
    for (std::size_t j = 1; j < s.crank.angles.size(); ++j)
      radiansTyped("crank.angles_deg[" + std::to_string(j) + "]", s.crank.angles[j] * 180.0 / M_PI);
}

// A cart mass typed in tonnes: the papers' carts weigh 1000 kg; a forming cart below 10 kg is no
// cart (near-zero masses, as a test of a massless cart, are left alone).
void cartMassInTonnes(const Scene& s, std::vector<std::string>& out) {
  for (int j = 0; j < s.carts.count; ++j) {
    const double m = s.cartMass(j);
    if (!(m >= 0.05 && m < kImplausibleCartMass)) continue;
    const std::string key = s.carts.masses.empty() ? "carts.mass" : "carts.mass[" + std::to_string(j) + "]";
    char buf[300];
    std::snprintf(buf, sizeof buf,
                  "%s = %g kg is implausible for a forming cart (below %g kg; the papers' carts weigh 1000 kg): "
                  "masses are in kilograms; if you meant %g t, write %g",
                  key.c_str(), m, kImplausibleCartMass, m, m * 1000.0);
    out.push_back(buf);
    if (s.carts.masses.empty()) break;
  }
}

// Output rows too sparse for the metrics: δ, the torque peaks and the steady-state detection are
// read from the output rows, and a row grid of N per crank revolution misses the peak of
// harmonic k by up to a phase of π·k/N, a relative error of about (π·k/N)²/2 (order 2 at 50
// rows: 0.8 %; the trial's 0.1 s step, 6 rows, read δ 12 % low). The revolution is taken at
// the synchronous crank speed ω0/u, a little shorter than the running one.
void sparseOutputRows(const Scene& s, std::vector<std::string>& out) {
  char buf[400];
  if (s.motor.enabled && s.motor.omega_sync > 0 && s.reducer.ratio > 0 && s.simulation.output_step > 0) {
    const double t_rev = 2.0 * M_PI * s.reducer.ratio / s.motor.omega_sync;
    const double rows = t_rev / s.simulation.output_step;
    if (rows < kFewestRowsPerRevolution) {
      std::snprintf(buf, sizeof buf,
                    "simulation.output_step = %g s gives about %.3g output rows per crank revolution (%.3g s at the "
                    "synchronous crank speed); δ, the peaks and the steady state are read from the rows and need at "
                    "least %g: write %.2g or less",
                    s.simulation.output_step, rows, t_rev, kFewestRowsPerRevolution, t_rev / kFewestRowsPerRevolution);
      out.push_back(buf);
    }
  }
}

// The Kloss data against the catalogue of the same motor: M_kr = (M_k/M_n)·P_n/ω_n (a catalogue
// law has its own breakdown point, and the key is named as without effect there).
void klossAgainstCatalogue(const Scene& s, std::vector<std::string>& out) {
  char buf[400];
  const MotorCatalogue& cat = s.induction.catalogue;
  const bool kloss = hasKlossCurve(s.induction.model);
  if (kloss && s.motor.enabled && cat.given() && cat.omega_nominal > 0 && cat.breakdown_torque_ratio > 0 &&
      s.motor.breakdown_torque > 0) {
    const double M_kr = cat.breakdown_torque_ratio * cat.power / cat.omega_nominal;
    if (std::abs(s.motor.breakdown_torque / M_kr - 1.0) > 0.1) {
      std::snprintf(buf, sizeof buf,
                    "motor.breakdown_torque = %g N·m disagrees with the catalogue of the same motor: "
                    "(M_k/M_n)·P_n/ω_n = %g × %g W / %g rad/s = %.4g N·m (motor.catalogue.*); one of them is mistyped",
                    s.motor.breakdown_torque, cat.breakdown_torque_ratio, cat.power, cat.omega_nominal, M_kr);
      out.push_back(buf);
    }
  }
}

// The initial crank speed typed as the rotor's (102 rad/s for 10.4: slip -8.5, a rod force of
// 2617 kN in the second trial): the crank turns at about ω0/u.
void crankSpeedTypedAsRotorSpeed(const Scene& s, std::vector<std::string>& out) {
  char buf[400];
  if (s.motor.omega_sync > 0 && s.reducer.ratio > 1 &&
      std::abs(s.initial.crank_speed) > 1.5 * s.motor.omega_sync / s.reducer.ratio) {
    const double w_crank = s.motor.omega_sync / s.reducer.ratio;
    std::snprintf(buf, sizeof buf,
                  "initial.crank_speed = %g rad/s is %.3g times the synchronous crank speed ω0/u = %.4g rad/s: the "
                  "crank turns at the rotor speed divided by the reducer ratio; if you meant a rotor speed of %g "
                  "rad/s, write %.4g",
                  s.initial.crank_speed, std::abs(s.initial.crank_speed) / w_crank, w_crank, s.initial.crank_speed,
                  s.initial.crank_speed / s.reducer.ratio);
    out.push_back(buf);
  }
}

// A switch-off after the run's end never happens (the third trial's t_off = 20 s in a 10 s run
// printed a run-out "so far").
void switchOffAfterTheEnd(const Scene& s, std::vector<std::string>& out) {
  char buf[400];
  if (std::isfinite(s.motor_stop.t_off) && s.motor_stop.t_off >= s.simulation.t_end) {
    std::snprintf(buf, sizeof buf,
                  "motor.stop.t_off = %g s is at or after simulation.t_end = %g s: the run holds no switch-off "
                  "(raise simulation.t_end to see the stop)",
                  s.motor_stop.t_off, s.simulation.t_end);
    out.push_back(buf);
  }
}

void gravityNotTheEarths(const Scene& s, std::vector<std::string>& out) {
  char buf[400];
  if (s.loads.gravity > 0 && std::abs(s.loads.gravity - 9.81) > 0.1) {
    std::snprintf(buf, sizeof buf,
                  "loads.gravity = %g m/s² is not the Earth's 9.81 m/s² (give 0 to leave gravity out)", s.loads.gravity);
    out.push_back(buf);
  }
}

void targetDeltaInPercent(const Scene& s, std::vector<std::string>& out) {
  char buf[400];
  if (s.sizing.target_delta >= 1.0) {
    std::snprintf(buf, sizeof buf,
                  "sizing.target_delta = %g: δ = (ω_max - ω_min)/ω_mean is a fraction, 0.05 for 5 %%; if you meant "
                  "%g %%, write %g",
                  s.sizing.target_delta, s.sizing.target_delta, s.sizing.target_delta / 100.0);
    out.push_back(buf);
  }
}

}  // namespace

std::vector<std::string> plausibilityWarnings(const Scene& s) {
  std::vector<std::string> out;
  for (auto check : {lengthsInMillimetres, degreesTypedAsRadians, cartMassInTonnes, sparseOutputRows, klossAgainstCatalogue,
                     crankSpeedTypedAsRotorSpeed, switchOffAfterTheEnd, gravityNotTheEarths, targetDeltaInPercent})
    check(s, out);
  return out;
}

}  // namespace rollerdyn
