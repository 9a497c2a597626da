// The run-up time of the start-up answers on a table built by hand: the crank at rest until the
// switch-on t_on, its speed rising linearly to ω_s over T_r, then constant. The steady mean crank
// speed is ω_s, 95 % of it is reached at t_on + 0.95·T_r, so the run-up time, counted from the
// switch-on, is 0.95·T_r whatever t_on is.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "analysis/StartUp.h"
#include "motor/KlossLaw.h"
#include "support/KlossMotorScene.h"

namespace rollerdyn {
namespace {

// A Kloss motor (ω0 = 100 rad/s) through a reducer u = 10, rigid coupling; built in code.
Scene klossScene(double t_on) {
  Scene s = test_scenes::klossMotorScene();
  s.initial.crank_speed = 0.0;
  s.motor_start.method = StartMethod::DirectOnLine;
  s.motor_start.t_on = t_on;
  return s;
}

// Rows every h from 0 to t_end: ω = 0 before t_on, ω_s·(t − t_on)/T_r during the ramp, ω_s after;
// φ its exact integral from φ0.
RunResult rampRun(double t_on, double ramp, double w_s, double h, double t_end, double phi0) {
  RunResult r;
  r.model = "reduced";
  r.timeseries.columns = {"t", "phi_crank", "omega_crank", "omega_motor", "motor_torque"};
  const int n = static_cast<int>(std::lround(t_end / h));
  for (int i = 0; i <= n; ++i) {
    const double t = i * h;
    double w = 0, phi = phi0;
    if (t >= t_on + ramp) {
      w = w_s;
      phi = phi0 + w_s * ramp / 2 + w_s * (t - t_on - ramp);
    } else if (t > t_on) {
      w = w_s * (t - t_on) / ramp;
      phi = phi0 + w_s * (t - t_on) * (t - t_on) / (2 * ramp);
    }
    r.timeseries.rows.push_back({t, phi, w, 10 * w, t >= t_on ? 1500.0 : 0.0});
  }
  r.reactions.columns = {"t"};
  return r;
}

TEST(StartUpRunUp, IsCountedFromTheSwitchOnToNinetyFivePercentOfTheSteadySpeed) {
  const double ramp = 1.0, w_s = 9.0;  // T_r [s], ω_s [rad/s]: a revolution takes 0.698 s
  for (double t_on : {0.0, 0.5, 1.3}) {
    const Scene s = klossScene(t_on);
    const KlossLaw law(s.motor);
    // Rows 4 ms apart: t_on + 0.95 s lies between two rows for every t_on here (interpolated).
    const RunResult run = rampRun(t_on, ramp, w_s, 0.004, t_on + 12.0, 0.5);
    const StartUp su = computeStartUp(s, run, &law, nullptr);
    ASSERT_TRUE(su.applicable) << "t_on " << t_on;
    ASSERT_TRUE(su.steady_reached) << "t_on " << t_on;
    EXPECT_TRUE(su.from_rest);
    EXPECT_NEAR(su.t_on, t_on, 1e-15);
    EXPECT_NEAR(su.steady_mean_speed, w_s, 1e-9 * w_s) << "t_on " << t_on;
    ASSERT_TRUE(su.starts) << su.verdict;
    EXPECT_NEAR(su.run_up_time, 0.95 * ramp, 1e-9)
        << "t_on = " << t_on << " s: 95 % of ω_s = " << w_s << " rad/s is reached at t = " << t_on + 0.95 * ramp
        << " s, " << 0.95 * ramp << " s after the switch-on";
  }
}

}  // namespace
}  // namespace rollerdyn
