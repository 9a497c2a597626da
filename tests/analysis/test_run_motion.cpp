// The motion of a run is named once (RunMotion.h) and carried everywhere: a stalled and a rocking
// run get null δ, H, k_p, their motion in summary.json and the terminal text, and a stalled run
// says why with the motor's starting and breakdown torques at the crank, computed here by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "analysis/RunMotion.h"
#include "analysis/SizingSummary.h"
#include "analysis/StartUp.h"
#include "analysis/Summary.h"
#include "motor/SharedMotorLaw.h"
#include "support/KlossMotorScene.h"

using namespace rollerdyn;
using nlohmann::json;

namespace {

Scene motorScene() { return test_scenes::klossMotorScene(); }

// Crank creeping at 0.001 rad/s (below 1 % of ω0/u = 10 rad/s) for 3 s.
RunResult creepingRun() {
  RunResult r;
  r.model = "multibody";
  r.timeseries.columns = {"t", "phi_crank", "omega_crank", "omega_motor", "motor_torque"};
  for (int i = 0; i <= 300; ++i) {
    const double t = 0.01 * i;
    r.timeseries.rows.push_back({t, 0.5 + 1e-3 * t, 1e-3, 1e-3, 1600});
  }
  r.reactions.columns = {"t"};
  return r;
}

}  // namespace

TEST(RunMotion, StartingAndBreakdownTorqueAtTheCrank) {
  const Scene s = motorScene();
  const RunResult r = creepingRun();
  const StartUp u = computeStartUp(s, r, sharedMotorLaw(s).get(), nullptr, "stalled");
  // Kloss at slip 1: 2·M_kr·s_kr/(1 + s_kr²) = 2·500·0.2/1.04, times u·η = 9; direct on line holds
  // the rated supply, so the held torques are the rated ones.
  EXPECT_NEAR(u.starting_torque_crank, 2 * 500 * 0.2 / 1.04 * 9, 1e-9);
  EXPECT_NEAR(u.starting_torque_held_crank, 2 * 500 * 0.2 / 1.04 * 9, 1e-9);
  EXPECT_NEAR(u.largest_torque_crank, 500 * 9, 1e-9);
  EXPECT_NEAR(u.largest_torque_held_crank, 500 * 9, 1e-9);
  EXPECT_EQ(u.can_start_from_rest, -1);  // no loads given
}

TEST(RunMotion, StalledRunIsNamedExplainedAndHasNoCoefficients) {
  const Scene s = motorScene();
  RunResult r = creepingRun();
  r.stats.complete = false;
  r.stats.status = "motor stalled at t = 0 s";
  const StartLoad load{2000.0, 6000.0};  // mean load above the breakdown torque 4500 N·m
  const json j = makeSummary(s, r, &load);
  EXPECT_EQ(j["motion"], "stalled");
  EXPECT_EQ(j["crank_motion"], "stalled");
  EXPECT_TRUE(j["delta"].is_null());
  EXPECT_TRUE(j["H"].is_null());
  EXPECT_TRUE(j["k_p"].is_null());
  EXPECT_TRUE(j["sizing"]["flywheel"]["kinetic_energy_swing"].is_null());
  ASSERT_TRUE(j["stall"].is_object());
  EXPECT_NEAR(j["stall"]["starting_torque_crank"].get<double>(), 2 * 500 * 0.2 / 1.04 * 9, 1e-9);
  EXPECT_EQ(j["stall"]["load_torque_mean"].get<double>(), 6000.0);
  const std::string why = j["stall"]["explanation"];
  EXPECT_NE(why.find("1731"), std::string::npos) << why;  // 1730.8 N·m starting torque, %.4g
  EXPECT_NE(why.find("4500"), std::string::npos) << why;
  EXPECT_NE(why.find("no steady running is possible"), std::string::npos) << why;
  const std::string status = j["status"];
  EXPECT_NE(status.find("the drive stalled: "), std::string::npos) << status;
  const std::string text = summaryText(j);
  EXPECT_NE(text.find("motion       stalled"), std::string::npos) << text;
  EXPECT_NE(text.find("δ (unevenness) n/a"), std::string::npos) << text;
  // Not a numerical failure: nothing is listed as non-finite.
  EXPECT_TRUE(j["non_finite"].empty()) << j["non_finite"].dump();
}

TEST(RunMotion, StarvedStartIsExplainedByTheStartAngleLoad) {
  const Scene s = motorScene();
  RunResult r = creepingRun();
  r.stats.complete = false;
  r.stats.status = "motor stalled at t = 0 s";
  const StartLoad load{2500.0, 1000.0};  // start-angle load above the 1731 N·m starting torque
  const json j = makeSummary(s, r, &load);
  const std::string why = j["stall"]["explanation"];
  EXPECT_NE(why.find("cannot turn the crank forwards"), std::string::npos) << why;
  EXPECT_NE(why.find("28.65 deg"), std::string::npos) << why;  // 0.5 rad
  EXPECT_NE(makeSummary(s, r)["stall"]["explanation"].get<std::string>().find("not evaluated"), std::string::npos);
}

TEST(RunMotion, TheStallRuleAppliedToTheRowsNamesACompletedCreepingRun) {
  // A table that was not cut short by a model (e.g. read back) is still named by the same rule.
  const Scene s = motorScene();
  RunResult r = creepingRun();
  const json j = makeSummary(s, r);
  EXPECT_EQ(j["motion"], "stalled");
  EXPECT_NE(j["stall"]["explanation"].get<std::string>().find("not evaluated"), std::string::npos);
}

TEST(RunMotion, RockingRunIsNamedAndHasNoCoefficients) {
  Scene s = motorScene();
  s.motor.enabled = false;  // the stall rule does not apply without a motor
  RunResult r;
  r.timeseries.columns = {"t", "phi_crank", "omega_crank"};
  for (int i = 0; i * 1e-3 <= 10.0; ++i) {
    const double t = i * 1e-3;
    r.timeseries.rows.push_back({t, 0.3 * std::sin(3 * t), 0.9 * std::cos(3 * t)});
  }
  const json j = makeSummary(s, r);
  EXPECT_EQ(j["motion"], "rocking");
  EXPECT_TRUE(j["delta"].is_null());
  EXPECT_TRUE(j["stall"].is_null());
  EXPECT_NE(summaryText(j).find("motion       rocking"), std::string::npos);
}

namespace {

// Rows of a drive with a starting method, in stages: each `duration` seconds at the crank speed
// `omega` (1e-3 rad/s creeps inside the rest band of 1 % of ω0/u = 0.1 rad/s) under the supply
// voltage ratio `u` (0: switched off). The supply columns are those a switching supply writes.
struct Stage {
  double duration, omega, u;
};
RunResult supplyRun(const std::vector<Stage>& stages) {
  RunResult r;
  r.model = "reduced";
  r.timeseries.columns = {"t", "phi_crank", "omega_crank", "omega_motor", "motor_torque",
                          "supply_voltage_ratio", "supply_frequency_ratio"};
  double phi = 0.5, t = 0.0;
  const double dt = 0.01;
  for (const Stage& st : stages)
    for (int i = 0; i < int(std::lround(st.duration / dt)); ++i, t += dt, phi += st.omega * dt)
      r.timeseries.rows.push_back({t, phi, st.omega, st.omega, st.u > 0 ? 1000.0 : 0.0, st.u, st.u > 0 ? 1.0 : 0.0});
  r.reactions.columns = {"t"};
  return r;
}

const double kStar = 1.0 / std::sqrt(3.0);  // U/U_n of a delta-rated winding in star

}  // namespace

// The stall rule counts only the time at the rated supply: a drive may be slow in star (U/U_n =
// 1/√3) for longer than the rule's second and then turn once in delta.
TEST(RunMotion, TheStallRuleCountsOnlyTheTimeAtTheRatedSupply) {
  const Scene s = motorScene();
  const json star_then_delta = makeSummary(s, supplyRun({{2.0, 1e-3, kStar}, {4.0, 10.0, 1.0}}));
  EXPECT_EQ(star_then_delta["motion"], "turning") << star_then_delta["status"];
  // The same rows at the rated supply throughout: held for 2 s, a stall.
  const json rated = makeSummary(s, supplyRun({{2.0, 1e-3, 1.0}, {4.0, 10.0, 1.0}}));
  EXPECT_EQ(rated["motion"], "stalled") << rated["status"];
}

// A drive still held at rest when the run ends, with the motor connected in a stage the stall
// rule skips (star that never changes over, a ramp longer than the run), has not started in this
// run: "stalled", as its start-up answer says, not "turning" with a creeping speed.
TEST(RunMotion, ADriveHeldInStarUntilTheRunEndsHasNotStarted) {
  const Scene s = motorScene();
  const json j = makeSummary(s, supplyRun({{3.0, 1e-3, kStar}}));
  EXPECT_EQ(j["motion"], "stalled") << j["status"];
  EXPECT_TRUE(j["delta"].is_null());
  // A machine at rest after a switch-off (U = 0) did not stall.
  const json off = makeSummary(s, supplyRun({{4.0, 10.0, 1.0}, {2.0, 1e-3, 0.0}}));
  EXPECT_NE(off["motion"], "stalled") << off["status"];
}

// A machine without a motor that friction has stopped is "at_rest" by the same rule the models
// end such a run with (RestDetector.h): every cart slower than v_s for a second, read from the rows
// of a table whose run completed, and from the detector's status line of a run it ended.
TEST(RunMotion, AMachineThatFrictionStoppedIsAtRest) {
  Scene s = motorScene();
  s.motor.enabled = false;
  s.loads.velocity_smoothing = 1e-3;
  RunResult r;
  r.model = "reduced";
  r.timeseries.columns = {"t", "phi_crank", "omega_crank", "v_cart_1", "v_cart_2"};
  // 1 s turning at 5 rad/s, then creeping backwards at 4e-5 rad/s (carts at 1e-5 m/s) for 1.5 s.
  for (int i = 0; i <= 250; ++i) {
    const double t = 0.01 * i;
    const bool moving = t < 1.0;
    r.timeseries.rows.push_back({t, moving ? 5 * t : 5.0 - 4e-5 * (t - 1), moving ? 5.0 : -4e-5,
                                 moving ? 0.5 : 1e-5, moving ? -0.5 : -1e-5});
  }
  r.reactions.columns = {"t"};
  r.stats.complete = true;
  const json rows = makeSummary(s, r);
  EXPECT_EQ(rows["motion"], "at_rest") << rows["status"];
  EXPECT_TRUE(rows["delta"].is_null());
  // The same rows cut short by the detector in a model run: its status line decides.
  r.stats.complete = false;
  r.stats.status = "the machine came to rest at t = 1 s: with the motor off, friction and loads hold it";
  EXPECT_EQ(makeSummary(s, r)["motion"], "at_rest");
  // Carts faster than v_s throughout: not at rest.
  for (auto& row : r.timeseries.rows) row[3] = row[4] = 0.01;
  r.stats.complete = true;
  r.stats.status = "ok";
  EXPECT_NE(makeSummary(s, r)["motion"], "at_rest");
}

// Finding of the 6-cart trial: a run that ended during a slow run-up (a 5000 kg·m² flywheel, 17 s
// to 95 % of a speed still far below synchronous) was "turning" and its heating FAILed on a window
// that was no steady state. A crank turning one way whose revolutions keep getting faster, in a run
// that never settled, is still "starting"; one that turns at a steady mean speed is "turning".
TEST(RunMotion, ACrankStillGainingSpeedRevolutionAfterRevolutionIsStarting) {
  const Scene s = motorScene();
  auto run = [](double alpha) {  // ω = 2 + α·t rad/s for 20 s
    RunResult r;
    r.model = "reduced";
    r.timeseries.columns = {"t", "phi_crank", "omega_crank", "omega_motor"};
    for (int i = 0; i <= 2000; ++i) {
      const double t = 0.01 * i;
      r.timeseries.rows.push_back({t, 0.5 + 2 * t + 0.5 * alpha * t * t, 2 + alpha * t, 2 + alpha * t});
    }
    return r;
  };
  WindowMetrics m;
  m.omega_min = 2.0;
  m.omega_max = 6.0;
  EXPECT_EQ(classifyMotion(s, run(0.2), m, 20.0, /*steady_reached=*/false), "starting");
  EXPECT_EQ(classifyMotion(s, run(0.0), m, 20.0, /*steady_reached=*/false), "turning");
  EXPECT_EQ(classifyMotion(s, run(0.2), m, 20.0, /*steady_reached=*/true), "turning");
  // Slowing down as steadily, with the motor on (the third trial's initial.crank_speed = 102 rad/s:
  // "turning" with δ = 0.04 of a crank falling from 102 to 50 rad/s): not settled either.
  RunResult down;
  down.model = "reduced";
  down.timeseries.columns = {"t", "phi_crank", "omega_crank", "omega_motor"};
  for (int i = 0; i <= 2000; ++i) {  // ω = 6 - 0.2·t
    const double t = 0.01 * i;
    down.timeseries.rows.push_back({t, 0.5 + 6 * t - 0.1 * t * t, 6 - 0.2 * t, 6 - 0.2 * t});
  }
  EXPECT_EQ(classifyMotion(s, down, m, 20.0, /*steady_reached=*/false), "starting");
}

// Finding of the 6-cart trial (90 deg offset, 300 kg·m² flywheel, 20 s): the swings grew every 2 s
// from ±1.65 to -3.95 ... +4.22 rad/s when the run ended, and the run was called "rocking ...
// instead of turning" with a FAIL. Growing swings at the end are an undecided start; swings of
// constant size are rocking.
TEST(RunMotion, RockingWithSwingsStillGrowingAtTheEndIsStarting) {
  const Scene s = motorScene();  // ω0/u = 10 rad/s, band 0.1 rad/s
  auto run = [](double growth) {  // φ = 0.5 + a(t)·sin(3t), a = 0.3·(1 + growth·t), 10 s
    RunResult r;
    r.model = "reduced";
    r.timeseries.columns = {"t", "phi_crank", "omega_crank", "omega_motor"};
    for (int i = 0; i <= 10000; ++i) {
      const double t = 1e-3 * i, a = 0.3 * (1 + growth * t);
      const double w = 0.3 * growth * std::sin(3 * t) + 3 * a * std::cos(3 * t);
      r.timeseries.rows.push_back({t, 0.5 + a * std::sin(3 * t), w, w});
    }
    return r;
  };
  WindowMetrics m;
  m.omega_min = -2.0;
  m.omega_max = 2.0;
  EXPECT_EQ(classifyMotion(s, run(0.3), m, 0.0, /*steady_reached=*/false), "starting");
  EXPECT_EQ(classifyMotion(s, run(0.0), m, 0.0, /*steady_reached=*/false), "rocking");
}

// A crank that comes to a stop at each dead centre and goes on forwards: its speed touches zero,
// by round-off -7e-20 rad/s, and never turns back. It once read "rocking" (the window's speed
// "ranges from -6.99e-20 to 8.5 rad/s") or "starting", depending only on when it was switched on
// (a generated machine of the consistency harness). A speed changes sign only when it leaves the
// stall rule's band (1 % of ω0/u) on the other side; a real swing back still does.
TEST(RunMotion, ASpeedThatTouchesZeroByRoundOffDoesNotChangeSign) {
  const Scene s = motorScene();  // ω0/u = 10 rad/s, band 0.1 rad/s
  RunResult r;  // φ̇ = 4·(1 - cos 4t) ≥ 0: stops at t = kπ/2 and goes on forwards, 10 s
  r.model = "reduced";
  r.timeseries.columns = {"t", "phi_crank", "omega_crank", "omega_motor"};
  for (int i = 0; i <= 10000; ++i) {
    const double t = 1e-3 * i, w = 4 * (1 - std::cos(4 * t));
    r.timeseries.rows.push_back({t, 4 * t - std::sin(4 * t), w, w});
  }
  WindowMetrics m;
  m.omega_min = -6.99e-20;
  m.omega_max = 8.0;
  // Advanced less than a revolution in the window (a short window): still no reversal.
  EXPECT_EQ(classifyMotion(s, r, m, 3.0, /*steady_reached=*/true), "turning");
  m.omega_min = -0.5;  // a swing back beyond the band is one
  EXPECT_EQ(classifyMotion(s, r, m, 3.0, /*steady_reached=*/true), "rocking");
}

// Finding of the 6-cart trial: the motor switched off at 10.4 rad/s, a 10 s run slowing steadily
// to 6.5 rad/s, was "turning" with δ = 0.22 (the deceleration read as unevenness) and "steady
// state NOT reached: the crank speed repeats from revolution 13 on". Without a motor, a crank that
// turns one way but never settles is coasting; with the motor on the same rows stay "turning" or
// "starting" as before, and a settled motor-off run (no losses) is still "turning".
TEST(RunMotion, AMachineWithoutMotorThatSlowsDownIsCoastingWithoutDelta) {
  Scene s = motorScene();
  s.motor.enabled = false;
  RunResult r;
  r.model = "reduced";
  r.timeseries.columns = {"t", "phi_crank", "omega_crank", "v_cart_1", "v_cart_2"};
  for (int i = 0; i <= 1000; ++i) {  // ω = 10.4 - 0.39·t for 10 s, carts well above v_s
    const double t = 0.01 * i;
    r.timeseries.rows.push_back({t, 10.4 * t - 0.195 * t * t, 10.4 - 0.39 * t, 1.0, -1.0});
  }
  r.reactions.columns = {"t"};
  r.stats.complete = true;
  const json j = makeSummary(s, r);
  EXPECT_EQ(j["motion"], "coasting");
  EXPECT_TRUE(j["delta"].is_null());
  const std::string text = summaryText(j);
  EXPECT_NE(text.find("motion       coasting  (the motor is off and the machine slows down"), std::string::npos) << text;
  EXPECT_EQ(text.find("repeats from revolution"), std::string::npos) << text;  // not while NOT reached
  WindowMetrics m;
  m.omega_min = 6.5;
  m.omega_max = 10.4;
  EXPECT_EQ(classifyMotion(s, r, m, 80.0, /*steady_reached=*/true), "turning");
}
