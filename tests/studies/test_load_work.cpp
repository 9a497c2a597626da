// What the technological load takes from the drive (src/analysis/LoadWork.h), through the one
// load law both models share (src/physics/RollerLoads.h). The 6-cart trial: with the papers'
// printed roller forces (the shipped as_printed reading) the load did 0.004 J of work in 10 s and
// nobody was told; the other reading needs ~130 kW. Now the work per cart is in every summary, a
// warning names the no-work case, and loads.rolling_resistance specifies a dissipation physically.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/LoadWork.h"
#include "analysis/Summary.h"
#include "cli/CliTestSupport.h"
#include "multibody/MultibodySimulation.h"
#include "reduced/ReducedModel.h"
#include "scene/SceneParser.h"

namespace rollerdyn {
namespace {

using test::model;

nlohmann::json summaryOf(const Scene& s, bool multibody) {
  const RunResult run = multibody ? runMultibodyModel(s) : runReducedModel(s);
  return makeSummary(s, run);
}

bool hasNoWorkWarning(const nlohmann::json& j) {
  for (const auto& w : j["warnings"])
    if (w.get<std::string>().find("almost no net work") != std::string::npos) return true;
  return false;
}

TEST(LoadWork, PrintedRollerForcesDoNoNetWorkAndSaySo) {
  const Scene s = parseSceneFile(model("balanced-4cart.yaml"), {"simulation.t_end=6", "simulation.reactions=false"});
  for (bool mb : {false, true}) {
    const nlohmann::json j = summaryOf(s, mb);
    ASSERT_TRUE(j["load"]["available"].get<bool>()) << mb;
    // A constant force gives back on the return stroke what it took: net ≈ 0 against the gross.
    EXPECT_LT(std::abs(j["load"]["net_over_gross_steady"].get<double>()), 1e-3) << mb;
    EXPECT_LT(std::abs(j["load"]["power_mean_per_cart_steady"].get<double>()), 1.0) << mb;  // W
    EXPECT_TRUE(hasNoWorkWarning(j)) << mb << " " << j["warnings"].dump();
    EXPECT_EQ(j["load"]["per_cart"].size(), 4u);
  }
}

// With the motor off there are no motor verdicts: the trial's coasting run still read "every motor
// verdict is that of an idling machine". The warning names what it falsifies there, the run-out.
TEST(LoadWork, WithTheMotorOffTheWarningSpeaksOfTheRunOutNotOfMotorVerdicts) {
  const Scene s = parseSceneFile(model("balanced-4cart.yaml"), {"simulation.t_end=6", "simulation.reactions=false",
                                                                "motor.enabled=false", "initial.crank_speed=10.4"});
  const nlohmann::json j = summaryOf(s, false);
  ASSERT_TRUE(hasNoWorkWarning(j)) << j["warnings"].dump();
  const std::string consequence = j["load"]["warning_consequence"];
  EXPECT_EQ(consequence.find("motor verdict"), std::string::npos) << consequence;
  EXPECT_NE(consequence.find("run-out"), std::string::npos) << consequence;
  EXPECT_EQ(j["load"]["warning"].get<std::string>().find("motor verdict"), std::string::npos);
  EXPECT_EQ(summaryText(j).find("motor verdict"), std::string::npos) << summaryText(j);
  // With the motor on, the motor verdicts are what it falsifies.
  const nlohmann::json on = summaryOf(parseSceneFile(model("balanced-4cart.yaml"), {"simulation.t_end=6",
                                                                                   "simulation.reactions=false"}), false);
  EXPECT_NE(on["load"]["warning_consequence"].get<std::string>().find("every motor verdict"), std::string::npos);
}

// μ_r = 0.05 on R_j1 + R_j2 = 19480 N: each cart absorbs μ_r·R·mean|v'|, where mean|v'| is the
// cart's mean speed from the run's own rows (both models, the same law). No warning.
TEST(LoadWork, RollingResistanceDissipatesInBothModels) {
  const Scene s = parseSceneFile(model("balanced-4cart.yaml"),
                                 {"simulation.t_end=6", "simulation.reactions=false", "loads.rolling_resistance=0.05"});
  double power[2] = {0, 0};
  for (int mb = 0; mb < 2; ++mb) {
    const RunResult run = mb ? runMultibodyModel(s) : runReducedModel(s);
    const nlohmann::json j = makeSummary(s, run);
    EXPECT_FALSE(hasNoWorkWarning(j)) << j["warnings"].dump();
    const double t0 = j["steady_state"]["t_begin"], t1 = j["steady_state"]["t_end"];
    // mean |v| of cart 1 over the same window, trapezoidal on the rows
    const Table& ts = run.timeseries;
    const int it = ts.index("t"), iv = ts.index("v_cart_1");
    double integral = 0;
    for (std::size_t i = 1; i < ts.rows.size(); ++i)
      if (ts.rows[i - 1][it] >= t0 - 1e-12 && ts.rows[i][it] <= t1 + 1e-12)
        integral += 0.5 * (std::abs(ts.rows[i - 1][iv]) + std::abs(ts.rows[i][iv])) * (ts.rows[i][it] - ts.rows[i - 1][it]);
    const double mean_speed = integral / (t1 - t0);
    const double expected = 0.05 * 19480.0 * mean_speed;  // W per cart; the printed F does no net work
    power[mb] = j["load"]["per_cart"][0]["power_mean_steady"].get<double>();
    EXPECT_NEAR(power[mb], expected, 0.02 * expected) << (mb ? "multibody" : "reduced");
    EXPECT_GT(j["load"]["net_over_gross_steady"].get<double>(), 0.05);
  }
  EXPECT_NEAR(power[0], power[1], 0.01 * power[1]);  // one law in both models
}

// Per-cart loads: an empty cart (no mix: no roller forces, no reactions) absorbs nothing; the
// others keep their own rolling resistance, μ_r·R·mean|v'| as above.
TEST(LoadWork, AnEmptyCartAbsorbsNothingInBothModels) {
  const Scene s = parseSceneFile(model("balanced-4cart.yaml"),
                                 {"simulation.t_end=4", "simulation.reactions=false", "loads.rolling_resistance=0.05",
                                  "loads.roller_force_front[1]=0", "loads.roller_force_rear[1]=0",
                                  "loads.roller_normal_front[1]=0", "loads.roller_normal_rear[1]=0"});
  for (bool mb : {false, true}) {
    const nlohmann::json j = summaryOf(s, mb);
    ASSERT_EQ(j["load"]["per_cart"].size(), 4u);
    EXPECT_EQ(j["load"]["per_cart"][1]["work_whole_run"].get<double>(), 0.0) << mb;
    for (int c : {0, 2, 3}) EXPECT_GT(j["load"]["per_cart"][c]["power_mean_steady"].get<double>(), 100.0) << mb << c;
    EXPECT_NE(j["load"]["reading"].get<std::string>().find("15924, 0, 15924, 15924 (carts 1 to 4)"), std::string::npos)
        << j["load"]["reading"];
  }
}

// The integral itself, on a hand-built time series whose closed form is known: rolling resistance
// alone (P = μ_r·R·|v'| once |v'| ≫ v_s), each cart's speed linear in time, v_j = j·(1 + 2t) m/s,
// on coarse rows (Δt = 0.1 s). The power is then linear in time and the trapezoid on the rows is
// exact: W_j = μ_r·R·j·(t + t²) between the rows' times. An end-point (rectangle) rule would be off
// by ½·ΔP·Δt per row, 5 % here, while on a real run's periodic power it hides in the noise.
TEST(LoadWork, TrapezoidOnTheRowsIsExactForPowerLinearInTime) {
  Scene s = parseSceneFile(model("balanced-4cart.yaml"), {"loads.rolling_resistance=0.05", "loads.roller_force_front=0",
                                                          "loads.roller_force_rear=0"});
  s.loads.velocity_smoothing = 1e-4;  // tanh(|v'|/v_s) = 1 to double precision for |v'| ≥ 1 m/s
  const double muR = 0.05 * (s.loads.roller_normal_front + s.loads.roller_normal_rear);  // N
  ASSERT_GT(muR, 0.0);
  RunResult run;
  run.timeseries.columns = {"t", "v_cart_1", "v_cart_2", "v_cart_3", "v_cart_4"};
  for (int i = 0; i <= 10; ++i) {
    const double t = 0.1 * i;
    std::vector<double> row{t};
    for (int j = 1; j <= 4; ++j) row.push_back(s.carts.side[j - 1] * j * (1 + 2 * t));
    run.timeseries.rows.push_back(row);
  }
  SteadyState window;  // rows 3 ... 8 (t = 0.3 ... 0.8 s), half-open as detectSteadyState gives it
  window.reached = true;
  window.row_begin = 3;
  window.row_end = 9;
  window.finite_rows = 11;
  const LoadWork w = computeLoadWork(s, run, window);
  ASSERT_TRUE(w.available);
  ASSERT_EQ(w.carts.size(), 4u);
  auto W = [&](int j, double t0, double t1) { return muR * j * ((t1 + t1 * t1) - (t0 + t0 * t0)); };
  for (int j = 1; j <= 4; ++j) {
    const CartLoadWork& c = w.carts[j - 1];
    EXPECT_NEAR(c.work_whole_run, W(j, 0.0, 1.0), 1e-12 * W(j, 0.0, 1.0)) << "cart " << j;
    EXPECT_NEAR(c.work_steady, W(j, 0.3, 0.8), 1e-12 * W(j, 0.3, 0.8)) << "cart " << j;
    EXPECT_NEAR(c.gross_steady, c.work_steady, 1e-12 * c.work_steady) << "a dissipating load: net = gross";
    EXPECT_NEAR(c.power_mean_steady, W(j, 0.3, 0.8) / 0.5, 1e-12 * W(j, 0.3, 0.8)) << "cart " << j;
  }
  EXPECT_NEAR(w.power_mean_per_cart_whole_run, (W(1, 0, 1) + W(2, 0, 1) + W(3, 0, 1) + W(4, 0, 1)) / 4.0,
              1e-9 * W(4, 0, 1));
  EXPECT_NEAR(w.net_over_gross_steady, 1.0, 1e-12);
  EXPECT_TRUE(w.warning.empty()) << w.warning;
}

}  // namespace
}  // namespace rollerdyn
