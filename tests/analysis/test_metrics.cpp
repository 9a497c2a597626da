// Metrics over a steady-state window: a synthetic sinusoid with hand-computed values, and the
// Loveikin and Pochka (2007) table as a check of the δ, H, k_p formulas (eq. (12)-(14)).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "analysis/Metrics.h"
#include "analysis/SteadyState.h"

using namespace rollerdyn;

namespace {

constexpr double kPi = 3.14159265358979323846;

// Steady crank motion ω(t) = ω0 + A·sin(2ω0·t) (two speed ripples per revolution, as with two
// carts), with coupling quantities in phase with it:
//   φ(t) = ω0·t + A/(2ω0)·(1 - cos(2ω0·t)),  ε = 2ω0·A·cos(2ω0·t),
//   twist = B·sin(2ω0·t), twist_rate, twist_accel its derivatives, coupling torque C0 + M·sin(2ω0·t).
struct Sinusoid {
  double w0 = 10.0, A = 0.5, B = 1e-3, C0 = 300.0, M = 150.0;
  double omega(double t) const { return w0 + A * std::sin(2 * w0 * t); }
  double phi(double t) const { return w0 * t + A / (2 * w0) * (1 - std::cos(2 * w0 * t)); }
  double eps(double t) const { return 2 * w0 * A * std::cos(2 * w0 * t); }

  void addRow(Table& ts, double t) const {
    const double s = std::sin(2 * w0 * t), c = std::cos(2 * w0 * t), W = 2 * w0;
    ts.rows.push_back({t, phi(t), omega(t), eps(t), B * s, W * B * c, -W * W * B * s, C0 + M * s});
  }
  Table emptyTable() const {
    Table ts;
    ts.columns = {"t", "phi_crank", "omega_crank", "eps_crank", "twist", "twist_rate",
                  "twist_accel", "coupling_torque"};
    return ts;
  }
  // Output rows every h seconds.
  Table uniformInTime(double t_end, double h) const {
    Table ts = emptyTable();
    for (int i = 0; i * h <= t_end + 1e-12; ++i) addRow(ts, i * h);
    return ts;
  }
  // Output rows every dphi of crank angle (as the Baranov scheme gives, Loveikin and Pochka (2007) eq. (4)):
  // denser in time where the crank is slow, so a sample mean of ω is biased upwards.
  Table uniformInAngle(double t_end, double dphi) const {
    Table ts = emptyTable();
    double t = 0;
    for (int i = 0;; ++i) {
      const double target = i * dphi;
      for (int it = 0; it < 50; ++it) t -= (phi(t) - target) / omega(t);  // Newton
      if (t > t_end) break;
      addRow(ts, t);
    }
    return ts;
  }
};

}  // namespace

TEST(MotionCoefficients, MatchHandComputedValues) {
  // ω_min 9, ω_max 11, ω_mean 10, |ε|max 20: δ = 0.2, H = 0.2, k_p = 0.04 + 0.2.
  const MotionCoefficients c = motionCoefficients(9.0, 11.0, 10.0, 20.0);
  EXPECT_DOUBLE_EQ(c.delta, 0.2);
  EXPECT_DOUBLE_EQ(c.H, 0.2);
  EXPECT_DOUBLE_EQ(c.k_p, 0.24);
}

// Loveikin and Pochka (2007), table "Результати розрахунків": Δφ, ω_min, ω_max, ω_mean, δ, |ε|max, H, k_p as
// printed. δ, H, k_p are recomputed from the printed ω and ε: this checks eq. (12)-(14), not a
// simulation. Tolerance 1.5e-3 covers the rounding of the printed inputs (the 0° row prints
// δ = 0.5, H = 0.78, k_p = 1.03 with fewer digits; the 10° row's δ = 0.4888 is 0.48859).
TEST(MotionCoefficients, ReproduceLoveikinPochka2007Table) {
  struct Row { double dphi, wmin, wmax, wmean, delta, eps, H, kp; };
  const std::vector<Row> table = {
      {0, 7.91, 13.19, 10.55, 0.5, 86.9, 0.78, 1.03},
      {10, 7.95, 13.09, 10.52, 0.4888, 83.3, 0.7527, 0.9916},
      {20, 8.07, 13.05, 10.56, 0.4716, 73.6, 0.66, 0.8824},
      {30, 8.26, 12.97, 10.615, 0.4437, 60.1, 0.5334, 0.7302},
      {40, 8.51, 12.84, 10.675, 0.4056, 46.7, 0.4098, 0.5743},
      {50, 8.8, 12.64, 10.72, 0.3582, 42, 0.3655, 0.4938},
      {60, 9.13, 12.38, 10.755, 0.3022, 36.4, 0.3147, 0.406},
      {70, 9.47, 12.05, 10.76, 0.2398, 30.2, 0.2608, 0.3183},
      {80, 9.8, 11.67, 10.735, 0.1742, 23.5, 0.2039, 0.2342},
      {90, 9.67, 11.25, 10.46, 0.151, 16.76, 0.1532, 0.176},
      {100, 9.29, 11.17, 10.23, 0.1838, 25.4, 0.2427, 0.2765},
      {110, 8.95, 11.56, 10.255, 0.2545, 34.34, 0.3265, 0.3913},
      {120, 8.66, 11.94, 10.3, 0.3184, 42.58, 0.4014, 0.5027},
      {130, 8.43, 12.3, 10.365, 0.3734, 50.75, 0.4724, 0.6118},
      {140, 8.25, 12.62, 10.435, 0.4188, 59.1, 0.5427, 0.7181},
      {150, 8.14, 12.9, 10.52, 0.4525, 66.1, 0.5973, 0.802},
      {160, 8.09, 13.11, 10.6, 0.4736, 71.1, 0.6328, 0.8571},
      {170, 8.1, 13.25, 10.675, 0.4824, 73.5, 0.645, 0.8777},
      {180, 8.12, 13.34, 10.73, 0.4865, 75.25, 0.6536, 0.8903}};
  for (const Row& r : table) {
    SCOPED_TRACE("dphi = " + std::to_string(r.dphi));
    const MotionCoefficients c = motionCoefficients(r.wmin, r.wmax, r.wmean, r.eps);
    EXPECT_NEAR(c.delta, r.delta, 1.5e-3);
    EXPECT_NEAR(c.H, r.H, 1.5e-3);
    EXPECT_NEAR(c.k_p, r.kp, 1.5e-3);
  }
  // Δφ = 90°, worked in the text: δ = 1.58/10.46 = 0.15105 (text prints 0.1512),
  // H = 16.76/10.46² = 0.15318 (eq. (13): 0.1532), k_p = 0.02282 + 0.15318 = 0.1760 (eq. (14)).
  const MotionCoefficients c90 = motionCoefficients(9.67, 11.25, 10.46, 16.76);
  EXPECT_NEAR(c90.delta, 0.15105, 5e-5);
  EXPECT_NEAR(c90.H, 0.1532, 5e-5);
  EXPECT_NEAR(c90.k_p, 0.1760, 5e-5);
}

TEST(ColumnStats, TimeWeightedMeanOnUnevenGrid) {
  // y = t on t = {0, 1, 3}: ∫y dt / 3 = 4.5/3 = 1.5, while the sample mean is 4/3.
  const std::vector<double> t{0, 1, 3}, y{0, 1, 3};
  const ColumnStats s = columnStats(t, y, 0, 3);
  EXPECT_DOUBLE_EQ(s.mean, 1.5);
  EXPECT_DOUBLE_EQ(s.min, 0);
  EXPECT_DOUBLE_EQ(s.max, 3);
  EXPECT_DOUBLE_EQ(s.swing(), 3);
  const std::vector<double> yn{-5, 1, 3};
  EXPECT_DOUBLE_EQ(columnStats(t, yn, 0, 3).abs_max, 5);
}

TEST(ColumnStats, NaNWhenEmptyOrNonFinite) {
  const std::vector<double> t{0, 1, 2}, y{1, NAN, 3};
  EXPECT_TRUE(std::isnan(columnStats(t, y, 0, 3).max));
  EXPECT_TRUE(std::isnan(columnStats(t, y, 1, 1).mean));
  EXPECT_DOUBLE_EQ(columnStats(t, y, 2, 3).max, 3);
}

TEST(Metrics, SinusoidMatchesHandComputedValues) {
  const Sinusoid s;
  const double T = 2 * kPi / s.w0;  // one revolution
  RunResult run;
  run.timeseries = s.uniformInTime(10 * T + 0.3, 1e-3);
  // Reactions on their own, coarser grid; a start-up spike before the window must not count.
  run.reactions.columns = {"t", "N_front_1", "friction_1"};
  for (int i = 0; i * 2e-3 <= 10 * T + 0.3; ++i) {
    const double t = i * 2e-3;
    run.reactions.rows.push_back(
        {t, t < 1.0 ? 1e6 : 1000.0 + 200.0 * std::sin(2 * s.w0 * t), -50.0});
  }

  const SteadyState ss = detectSteadyState(run.timeseries, 3);
  ASSERT_TRUE(ss.reached);
  ASSERT_EQ(ss.window_revolutions, 3);
  EXPECT_NEAR(ss.t_end, 10 * T, 1e-6);
  EXPECT_NEAR(ss.t_begin, 7 * T, 1e-6);

  const WindowMetrics m = computeMetrics(run, ss);
  EXPECT_NEAR(m.omega_mean, s.w0, 2e-6);   // 3·2π / 3T, crossings interpolated
  EXPECT_NEAR(m.omega_min, s.w0 - s.A, 1e-4 * s.A);
  EXPECT_NEAR(m.omega_max, s.w0 + s.A, 1e-4 * s.A);
  EXPECT_NEAR(m.eps_abs_max, 2 * s.w0 * s.A, 1e-4 * 2 * s.w0 * s.A);
  EXPECT_FALSE(m.eps_from_difference);
  // δ = 2A/ω0 = 0.1, H = 2ω0A/ω0² = 0.1, k_p = 0.01 + 0.1 = 0.11.
  EXPECT_NEAR(m.coefficients.delta, 0.1, 1e-5);
  EXPECT_NEAR(m.coefficients.H, 0.1, 1e-5);
  EXPECT_NEAR(m.coefficients.k_p, 0.11, 1e-5);
  // Swings: twist 2B, rate 2·(2ω0)B, accel 2·(2ω0)²B, torque 2M.
  EXPECT_NEAR(m.twist_swing, 2 * s.B, 1e-4 * 2 * s.B);
  EXPECT_NEAR(m.twist_rate_swing, 4 * s.w0 * s.B, 1e-4 * 4 * s.w0 * s.B);
  EXPECT_NEAR(m.twist_accel_swing, 8 * s.w0 * s.w0 * s.B, 1e-4 * 8 * s.w0 * s.w0 * s.B);
  EXPECT_NEAR(m.coupling_torque_swing, 2 * s.M, 1e-4 * 2 * s.M);
  EXPECT_TRUE(m.missing_columns.empty());

  ASSERT_EQ(m.reactions.size(), 2u);
  EXPECT_EQ(m.reactions[0].first, "N_front_1");
  const ColumnStats& n = m.reactions[0].second;
  EXPECT_NEAR(n.max, 1200.0, 0.1);  // the 1e6 spike lies before the window
  EXPECT_NEAR(n.min, 800.0, 0.1);
  EXPECT_NEAR(n.mean, 1000.0, 0.5);  // whole periods; the grid does not end exactly on t_end
  EXPECT_NEAR(n.abs_max, 1200.0, 0.1);
  EXPECT_EQ(m.reactions[1].first, "friction_1");
  EXPECT_DOUBLE_EQ(m.reactions[1].second.abs_max, 50.0);
  EXPECT_NEAR(m.reactions[1].second.mean, -50.0, 1e-9);
}

TEST(Metrics, MeanSpeedIsTimeWeightedNotSampleMean) {
  // Rows equally spaced in crank angle: the sample mean of ω is ∫ω² dt / ∫ω dt
  // = ω0 + A²/(2ω0) = 10.0125, the true mean speed is ω0 = 10.
  const Sinusoid s;
  const double T = 2 * kPi / s.w0;
  RunResult run;
  run.timeseries = s.uniformInAngle(6 * T + 0.1, 2 * kPi / 720);
  const SteadyState ss = detectSteadyState(run.timeseries, 4);
  ASSERT_EQ(ss.window_revolutions, 4);
  const WindowMetrics m = computeMetrics(run, ss);
  EXPECT_NEAR(m.omega_mean, s.w0, 2e-6);

  const std::vector<double> w = run.timeseries.column("omega_crank");
  double sample_mean = 0;
  for (std::size_t i = ss.row_begin; i < ss.row_end; ++i) sample_mean += w[i];
  sample_mean /= static_cast<double>(ss.row_end - ss.row_begin);
  EXPECT_NEAR(sample_mean, s.w0 + s.A * s.A / (2 * s.w0), 2e-4);  // the bias the metric avoids
  EXPECT_GT(std::abs(sample_mean - m.omega_mean), 1e-2);

  // Nor the midrange (ω_min + ω_max)/2, which a symmetric sinusoid cannot tell from the mean:
  // ω = ω0 + a·sin(ω0·t) + b·cos(2·ω0·t) has mean ω0 over each revolution (φ(t + 2π/ω0) = φ(t) + 2π)
  // but, with a = 1, b = 0.5, extremes ω0 + 0.75 and ω0 - 1.5: midrange ω0 - 0.375 rad/s.
  const double w0 = 10.0, a = 1.0, b = 0.5;
  RunResult skew;
  skew.timeseries.columns = {"t", "phi_crank", "omega_crank"};
  for (double t = 0; t <= 8 * 2 * kPi / w0; t += 1e-3)
    skew.timeseries.rows.push_back({t, w0 * t - (a / w0) * std::cos(w0 * t) + (b / (2 * w0)) * std::sin(2 * w0 * t),
                                    w0 + a * std::sin(w0 * t) + b * std::cos(2 * w0 * t)});
  const SteadyState sk = detectSteadyState(skew.timeseries, 4);
  const WindowMetrics ms = computeMetrics(skew, sk);
  EXPECT_NEAR(ms.omega_mean, w0, 1e-6);
  EXPECT_NEAR(ms.omega_midrange, w0 - 0.375, 1e-3);  // Loveikin and Pochka's (2007) printed "mean"
}

TEST(Metrics, RigidDriveWithoutCouplingColumnsReportsZeroSwings) {
  const Sinusoid s;
  Table full = s.uniformInTime(8 * 2 * kPi / s.w0, 1e-3);
  RunResult run;
  run.timeseries.columns = {"t", "phi_crank", "omega_crank"};  // no eps_crank either
  for (const auto& r : full.rows) run.timeseries.rows.push_back({r[0], r[1], r[2]});
  const SteadyState ss = detectSteadyState(run.timeseries, 3);
  const WindowMetrics m = computeMetrics(run, ss);
  EXPECT_EQ(m.coupling_torque_swing, 0.0);
  EXPECT_EQ(m.twist_swing, 0.0);
  EXPECT_EQ(m.twist_rate_swing, 0.0);
  EXPECT_EQ(m.twist_accel_swing, 0.0);
  EXPECT_EQ(m.missing_columns.size(), 4u);
  // ε from central differences of ω when eps_crank is absent.
  EXPECT_TRUE(m.eps_from_difference);
  EXPECT_NEAR(m.eps_abs_max, 2 * s.w0 * s.A, 1e-3 * 2 * s.w0 * s.A);
  EXPECT_TRUE(m.reactions.empty());
}
