#include "analysis/RunMotion.h"

#include <cmath>
#include <cstdio>

#include "analysis/StallDetector.h"
#include "physics/KlossMotor.h"

namespace rollerdyn {

std::string classifyMotion(const Scene& sc, const RunResult& run, const WindowMetrics& m, double window_advance,
                           bool steady_reached) {
  // The models end a hopeless run with the detector's own status line (StallDetector.h); the
  // same rule applied to the rows catches a table that was not produced by a model run.
  if (!run.stats.complete) {
    const std::string from_status = StallDetector::motionOfStatus(run.stats.status);
    if (!from_status.empty()) return from_status;
  }
  const Table& ts = run.timeseries;
  if (sc.motor.enabled && sc.reducer.ratio > 0 && ts.has("t") && ts.has("omega_crank") && ts.has("phi_crank")) {
    StallDetector d(true, sc.motor.omega_sync / sc.reducer.ratio);
    const int it = ts.index("t"), ip = ts.index("phi_crank"), ic = ts.index("omega_crank");
    const int im = ts.has("omega_motor") ? ts.index("omega_motor") : ic;
    for (const auto& row : ts.rows)
      if (d.update(row[it], row[ip], row[ic], row[im]))
        return d.kind() == StallKind::RockingWithoutGain ? "rocking" : "stalled";
  }
  if (!std::isfinite(m.omega_min) || !std::isfinite(m.omega_max)) return "unknown";
  if (m.omega_min < 0 && m.omega_max > 0) {
    if (!(std::abs(window_advance) >= 2.0 * M_PI)) return "rocking";
    if (!steady_reached) return "starting";
  }
  if (m.omega_min == 0 && m.omega_max == 0) return "at_rest";
  return "turning";
}

double startingTorqueAtCrank(const Scene& sc) {
  return klossCrankTorque(sc.motor, sc.reducer.ratio, sc.reducer.efficiency, 0.0);
}

double breakdownTorqueAtCrank(const Scene& sc) {
  return sc.motor.breakdown_torque * sc.reducer.ratio * sc.reducer.efficiency;
}

std::string stallExplanation(const Scene& sc, const StartLoad* load) {
  const double M_start = startingTorqueAtCrank(sc), M_kr = breakdownTorqueAtCrank(sc);
  char buf[640];
  if (!std::isfinite(M_start) || !(M_kr > 0)) return "the scene gives no motor data to compare the loads with";
  if (!load || !std::isfinite(load->at_start_angle) || !std::isfinite(load->revolution_mean)) {
    std::snprintf(buf, sizeof buf,
                  "the motor gives %.4g N·m at the crank when starting (Kloss torque at slip 1 × u·η) "
                  "and at most %.4g N·m (breakdown torque M_kr·u·η); the load torques were not "
                  "evaluated",
                  M_start, M_kr);
    return buf;
  }
  const double L0 = load->at_start_angle, Lm = load->revolution_mean;
  const char* verdict =
      Lm >= M_kr   ? "the load averaged over a revolution exceeds even the breakdown torque, so "
                     "no steady running is possible"
      : L0 >= M_start ? "the starting torque is below the load at the start angle, so the drive "
                        "cannot break away from rest there"
                      : "the motor can start and carry the mean load, so the stall comes from the "
                        "load peaks near a dead centre together with the inertia";
  std::snprintf(buf, sizeof buf,
                "starting torque at the crank %.4g N·m (Kloss torque at slip 1 × u·η) against a "
                "load torque of %.4g N·m at the start angle %.4g deg; breakdown torque at the crank "
                "%.4g N·m (M_kr·u·η) against a load torque of %.4g N·m averaged over a revolution: %s",
                M_start, L0, sc.initial.crank_angle * 180.0 / M_PI, M_kr, Lm, verdict);
  return buf;
}

}  // namespace rollerdyn
