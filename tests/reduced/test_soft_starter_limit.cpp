// A current-limited soft start run by the reduced model on the shipped balanced drive with its
// catalogue motor as the equivalent circuit (a quasi-static law: while the limit acts, the stator
// current is exactly I_lim): the limit holds after the ramp until the rotor reaches ω_lim, where
// the law's steady current at the rated voltage equals the limit, the voltage reaching U_n
// continuously there; and the start-up answers report the limit. ω_lim is found here by a scan of
// the law's steadyCurrent of its own (20 000 speeds, linear interpolation), not by Supply's.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "analysis/StartUp.h"
#include "motor/MotorLawFactory.h"
#include "reduced/ReducedModel.h"
#include "scene/SceneParser.h"

namespace rollerdyn {
namespace {

Scene softStart(const std::vector<std::string>& more) {
  std::vector<std::string> o = {"motor.model=circuit", "motor.start.method=soft_starter",
                                "motor.start.initial_voltage=0.35", "simulation.output_step=0.001"};
  o.insert(o.end(), more.begin(), more.end());
  return parseSceneFile(std::string(ROLLERDYN_SOURCE_DIR) + "/model/balanced-4cart.yaml", o);
}

// The highest rotor speed in [0, ω0] at which I_1(U_n, ω) > I_lim, interpolated linearly.
double limitSpeedByScan(const MotorLaw& law, double limit) {
  const double w0 = law.synchronousSpeed();
  constexpr int kN = 20000;
  double w_lim = 0;
  for (int i = 0; i < kN; ++i) {
    const double wa = w0 * i / kN, wb = w0 * (i + 1) / kN;
    const double Ia = law.steadyCurrent({}, wa), Ib = law.steadyCurrent({}, wb);
    if (Ia > limit && Ib <= limit) w_lim = wa + (Ia - limit) / (Ia - Ib) * (wb - wa);
  }
  return w_lim;
}

struct Rows {
  std::vector<double> t, U, I, w_rotor;
};

Rows rowsOf(const Scene& s, const RunResult& run) {
  Rows r;
  const Table& ts = run.timeseries;
  r.t = ts.column("t");
  r.U = ts.column("supply_voltage_ratio");
  r.I = ts.column("stator_current");
  r.w_rotor = ts.column("omega_motor");
  for (double& w : r.w_rotor) w *= s.reducer.ratio;
  return r;
}

constexpr double kLimit = 180.0;  // [A]: breaks the 4-cart drive away, and holds after a 0.5 s ramp

TEST(SoftStarterLimit, HoldsAfterTheRampUntilTheRatedVoltageCurrentIsTheLimit) {
  const Scene s = softStart({"motor.start.ramp_time=0.5", "motor.start.current_limit=" + std::to_string(kLimit),
                             "simulation.t_end=4"});
  const std::unique_ptr<MotorLaw> law = makeMotorLaw(s);
  const double w_lim = limitSpeedByScan(*law, kLimit);
  ASSERT_GT(w_lim, 0.0);
  const RunResult run = runReducedModel(s);
  ASSERT_TRUE(run.stats.complete) << run.stats.status;
  const Rows r = rowsOf(s, run);
  const double t_ramp_end = s.motor_start.t_on + s.motor_start.ramp_time;
  std::size_t limited_after_ramp = 0, bypass_row = 0;
  double largest_step = 0;
  for (std::size_t i = 1; i < r.t.size(); ++i) {
    if (r.t[i] > t_ramp_end + 1e-9 && r.U[i] < 1.0) {
      ++limited_after_ramp;
      // The limit holds: the quasi-static circuit draws exactly I_lim.
      EXPECT_NEAR(r.I[i], kLimit, 1e-6 * kLimit) << "t = " << r.t[i];
      EXPECT_LT(r.w_rotor[i], w_lim * (1 + 1e-9)) << "t = " << r.t[i];
    }
    if (r.t[i] > t_ramp_end + 1e-9 && r.U[i] == 1.0 && bypass_row == 0) bypass_row = i;
    if (r.t[i] > t_ramp_end - 1e-9) largest_step = std::max(largest_step, std::abs(r.U[i] - r.U[i - 1]));
  }
  std::printf("  rows limited after the ramp %zu, bypass at row t = %.4g s, ω_lim %.6g rad/s, rotor there %.6g, "
              "largest voltage step between rows after the ramp %.3g\n",
              limited_after_ramp, bypass_row ? r.t[bypass_row] : NAN, w_lim,
              bypass_row ? r.w_rotor[bypass_row] : NAN, largest_step);
  EXPECT_GT(limited_after_ramp, 10u);  // before the fix: none, full voltage at t_on + t_ramp
  ASSERT_GT(bypass_row, 0u) << "the bypass never closed";
  // The bypass closes where the rotor crosses ω_lim (between these two rows) ...
  EXPECT_GE(r.w_rotor[bypass_row], w_lim * (1 - 1e-6));
  EXPECT_LT(r.w_rotor[bypass_row - 1], w_lim);
  // ... and the voltage gets there continuously: no step between 1 ms rows beyond what the rotor's
  // acceleration over one row gives (before the fix: a jump to U_n at the ramp's end).
  EXPECT_LT(largest_step, 0.02);
  EXPECT_GT(r.U[bypass_row - 1], 0.98);

  // The start-up answers report the limit (the circuit law's answers need no loads' data).
  const StartUp a = computeStartUp(s, run, law.get(), nullptr);
  const StartUpCurrentLimit& c = a.current_limit;
  ASSERT_TRUE(c.applies);
  EXPECT_EQ(c.outcome, "bypass");
  EXPECT_NEAR(c.bypass_speed, w_lim, 1e-6 * w_lim);
  EXPECT_DOUBLE_EQ(c.limit, kLimit);
  // The bypass time: the rows' crossing of the scan's ω_lim, interpolated here.
  const std::size_t k = bypass_row;
  const double t_cross =
      r.t[k - 1] + (w_lim - r.w_rotor[k - 1]) / (r.w_rotor[k] - r.w_rotor[k - 1]) * (r.t[k] - r.t[k - 1]);
  EXPECT_NEAR(c.end_time, t_cross, 1e-6);
  EXPECT_NEAR(c.held_time, t_cross - s.motor_start.t_on, 1e-6);
  EXPECT_NEAR(c.current_peak, kLimit, 1e-6 * kLimit);  // the peak is the limit itself
  // At standstill the limit allows U = I_lim/I_1(0); the voltage it held never went below that
  // (I_1 falls as the rotor speeds up) nor reached U_n.
  const double U_standstill = kLimit / law->steadyCurrent({}, 0.0);
  EXPECT_NEAR(c.standstill_voltage, U_standstill, 1e-12);
  EXPECT_GE(c.voltage_min, U_standstill * (1 - 1e-9));
  EXPECT_LT(c.voltage_min, 1.0);
  EXPECT_TRUE(std::isfinite(c.binding_from));
  EXPECT_FALSE(c.stopped_the_start);
}

// A limit whose voltage at standstill gives less torque than the load at the start angle holds the
// motor at rest: the starter trips at t_on + max_start_time and the run ends there, a failed start.
// The six-cart trial's design (six carts of 1200 kg at 60°, μ_r = 0.1: 1416 N·m at the start angle)
// under the trial's 150 A, which allows 0.56·U_n at standstill, 779 N·m at the crank.
TEST(SoftStarterLimit, ALimitThatCannotBreakTheMotorAwayTripsTheStarter) {
  constexpr double kWeak = 150.0;  // [A]
  const Scene s = softStart({"carts.count=6", "crank.offset_deg=60", "carts.mass=1200", "loads.rolling_resistance=0.1",
                             "motor.start.ramp_time=1", "motor.start.current_limit=" + std::to_string(kWeak),
                             "motor.start.max_start_time=2", "simulation.t_end=4"});
  const std::unique_ptr<MotorLaw> law = makeMotorLaw(s);
  const RunResult run = runReducedModel(s);
  EXPECT_FALSE(run.stats.complete);
  EXPECT_EQ(run.stats.status.rfind("the soft starter tripped at t = 2 s", 0), 0u) << run.stats.status;
  const Rows r = rowsOf(s, run);
  EXPECT_NEAR(r.t.back(), 2.0, 1e-9);  // the run ends at the trip
  EXPECT_EQ(r.U.back(), 0.0);          // the motor disconnected
  const StartUp a = computeStartUp(s, run, law.get(), nullptr);
  EXPECT_FALSE(a.starts);
  EXPECT_EQ(a.verdict.rfind("the drive does not start: the soft starter tripped at t = 2 s", 0), 0u) << a.verdict;
  const StartUpCurrentLimit& c = a.current_limit;
  EXPECT_EQ(c.outcome, "tripped");
  EXPECT_TRUE(c.stopped_the_start);
  EXPECT_DOUBLE_EQ(c.end_time, 2.0);
  EXPECT_DOUBLE_EQ(c.held_time, 2.0);
  EXPECT_NEAR(c.current_peak, kWeak, 1e-6 * kWeak);
  // Held at (nearly) standstill: the voltage is the limit's at standstill, I_lim/I_1(0).
  EXPECT_NEAR(c.voltage_min, kWeak / law->steadyCurrent({}, 0.0), 1e-3);
}

}  // namespace
}  // namespace rollerdyn
