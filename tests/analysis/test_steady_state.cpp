// Steady-state detection on synthetic crank motions: a start-up that settles, a ramp that never
// does, a stalled crank, too few revolutions, a backward-turning crank and a run that blows up.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "analysis/SteadyState.h"

using namespace rollerdyn;

namespace {

constexpr double kPi = 3.14159265358979323846;

// Table with t, phi_crank, omega_crank sampled every h seconds up to t_end.
Table motion(const std::function<double(double)>& phi, const std::function<double(double)>& omega,
             double t_end, double h) {
  Table ts;
  ts.columns = {"t", "phi_crank", "omega_crank"};
  for (int i = 0; i * h <= t_end + 1e-12; ++i) {
    const double t = i * h;
    ts.rows.push_back({t, phi(t), omega(t)});
  }
  return ts;
}

// Start-up ω = ω_s(1 - e^{-t/τ}) + a·sin(2ω_s t): exponential approach plus the two-per-revolution
// ripple of the loads; φ is its exact integral.
struct StartUp {
  double ws = 10.0, tau = 2.0, a = 0.3;
  double omega(double t) const { return ws * (1 - std::exp(-t / tau)) + a * std::sin(2 * ws * t); }
  double phi(double t) const {
    return ws * (t - tau * (1 - std::exp(-t / tau))) + a / (2 * ws) * (1 - std::cos(2 * ws * t));
  }
  Table table(double t_end, double h = 2e-3) const {
    return motion([this](double t) { return phi(t); }, [this](double t) { return omega(t); }, t_end, h);
  }
};

}  // namespace

TEST(SteadyState, StartUpTransientEndFoundWithinOneRevolution) {
  const StartUp s;
  const double T = 2 * kPi / s.ws;  // steady revolution time
  const SteadyState ss = detectSteadyState(s.table(40.0), 5);
  ASSERT_TRUE(ss.reached) << ss.note;
  ASSERT_GE(ss.after_revolutions, 0);
  // The per-revolution mean lags ω_s by ≈ ω_s·e^{-t/τ}, between e^{-(t_k+T)/τ} and e^{-t_k/τ}
  // relative; it drops below the tolerance at t* = τ·ln(1/tol) = 13.8 s, so the first settled
  // revolution starts within one revolution of t*.
  const double t_star = s.tau * std::log(1.0 / ss.relative_tolerance);
  EXPECT_NEAR(ss.t_settled, t_star, T);
  EXPECT_NEAR(ss.revolutions[ss.after_revolutions].t_begin, ss.t_settled, 1e-12);
  // Every revolution before it is out of tolerance, every one after within.
  const double final_mean = ss.revolutions.back().omega_mean;
  EXPECT_GE(std::abs(ss.revolutions[ss.after_revolutions - 1].omega_mean - final_mean),
            ss.relative_tolerance * final_mean);
  for (int k = ss.after_revolutions; k < ss.revolutions_counted; ++k)
    EXPECT_LT(std::abs(ss.revolutions[k].omega_mean - final_mean), ss.relative_tolerance * final_mean);
  // Window: the last 5 whole revolutions, ending at the last crossing.
  EXPECT_EQ(ss.window_revolutions, 5);
  EXPECT_NEAR(ss.t_end - ss.t_begin, 5 * T, 1e-3);
  EXPECT_LE(ss.t_end, 40.0);
  EXPECT_GT(ss.t_end, 40.0 - T);
  EXPECT_NEAR(final_mean, s.ws, 1e-4 * s.ws);
  // Row range covers exactly the rows inside [t_begin, t_end].
  const auto t = s.table(40.0).column("t");
  ASSERT_LT(ss.row_begin, ss.row_end);
  EXPECT_GE(t[ss.row_begin], ss.t_begin);
  EXPECT_LT(t[ss.row_begin - 1], ss.t_begin);
  EXPECT_LE(t[ss.row_end - 1], ss.t_end);
  if (ss.row_end < t.size()) {
    EXPECT_GT(t[ss.row_end], ss.t_end);
  }
}

TEST(SteadyState, NotReachedWhenRunEndsDuringStartUp) {
  // Same start-up cut at 10 s (< t* = 13.8 s): the last 5 revolutions still drift.
  const SteadyState ss = detectSteadyState(StartUp{}.table(10.0), 5);
  EXPECT_FALSE(ss.reached);
  EXPECT_GT(ss.after_revolutions, ss.revolutions_counted - 5);
  EXPECT_EQ(ss.window_revolutions, 5);  // metrics are still taken over the last 5 revolutions
}

TEST(SteadyState, LooserToleranceSettlesEarlier) {
  const StartUp s;
  const SteadyState tight = detectSteadyState(s.table(40.0), 5, 1e-3);
  const SteadyState loose = detectSteadyState(s.table(40.0), 5, 1e-2);
  EXPECT_LT(loose.after_revolutions, tight.after_revolutions);
  EXPECT_NEAR(loose.t_settled, s.tau * std::log(100.0), 2 * kPi / s.ws);
}

TEST(SteadyState, RampNeverSettles) {
  // ω = 5 + 0.5·t: each revolution about 10 % faster than the previous one.
  const SteadyState ss = detectSteadyState(
      motion([](double t) { return 5 * t + 0.25 * t * t; }, [](double t) { return 5 + 0.5 * t; },
             20.0, 1e-3),
      3);
  EXPECT_FALSE(ss.reached);
  EXPECT_GT(ss.revolutions_counted, 10);
  EXPECT_EQ(ss.after_revolutions, ss.revolutions_counted - 1);  // only the final one agrees with itself
  EXPECT_EQ(ss.window_revolutions, 3);
}

TEST(SteadyState, SlowRampWithinEachRevolutionButDriftingOverWindowIsNotSteady) {
  // Per-revolution change ≈ 4e-4 (below 1e-3) but ≈ 2e-3 over 5 revolutions: comparing with the
  // final revolution, not the neighbour, catches it.
  const double w0 = 10, alpha = 0.0064;  // Δω/ω per revolution = α·T/ω ≈ 4e-4
  const SteadyState ss = detectSteadyState(
      motion([&](double t) { return w0 * t + 0.5 * alpha * t * t; },
             [&](double t) { return w0 + alpha * t; }, 8.0, 1e-3),
      5);
  ASSERT_GE(ss.revolutions_counted, 6);
  EXPECT_FALSE(ss.reached);
}

TEST(SteadyState, StalledCrankFallsBackToLastFifthOfRun) {
  // Crank creeps 3 rad in 10 s: not one whole revolution.
  const SteadyState ss = detectSteadyState(
      motion([](double t) { return 0.3 * t; }, [](double) { return 0.3; }, 10.0, 0.01), 3);
  EXPECT_FALSE(ss.reached);
  EXPECT_EQ(ss.revolutions_counted, 0);
  EXPECT_EQ(ss.window_revolutions, 0);
  EXPECT_EQ(ss.after_revolutions, -1);
  EXPECT_NEAR(ss.t_begin, 8.0, 1e-12);
  EXPECT_NEAR(ss.t_end, 10.0, 1e-12);
  EXPECT_EQ(ss.row_end, 1001u);
  EXPECT_NEAR(ss.row_end - ss.row_begin, 201u, 1);
  EXPECT_FALSE(ss.note.empty());
}

TEST(SteadyState, FewerRevolutionsThanWindowIsNotReached) {
  // Constant speed, 3 whole revolutions, window of 5 asked for.
  const double w = 2 * kPi;  // one revolution per second
  const SteadyState ss = detectSteadyState(
      motion([&](double t) { return w * t; }, [&](double) { return w; }, 3.5, 1e-3), 5);
  EXPECT_EQ(ss.revolutions_counted, 3);
  EXPECT_FALSE(ss.reached);
  EXPECT_EQ(ss.window_revolutions, 3);
  EXPECT_EQ(ss.after_revolutions, 0);
  EXPECT_NEAR(ss.t_begin, 0.0, 1e-9);
  EXPECT_NEAR(ss.t_end, 3.0, 1e-9);
  // With a window of 3 the same run is steady.
  EXPECT_TRUE(detectSteadyState(
                  motion([&](double t) { return w * t; }, [&](double) { return w; }, 3.5, 1e-3), 3)
                  .reached);
}

TEST(SteadyState, BackwardRotationCountsRevolutions) {
  const double w = -2 * kPi;
  const SteadyState ss = detectSteadyState(
      motion([&](double t) { return 1.0 + w * t; }, [&](double) { return w; }, 6.2, 1e-3), 3);
  EXPECT_EQ(ss.revolutions_counted, 6);
  EXPECT_TRUE(ss.reached);
  EXPECT_NEAR(ss.revolutions.back().omega_mean, w, 1e-9);
}

TEST(SteadyState, BlownUpRunUsesFinitePrefix) {
  const double w = 2 * kPi;
  Table ts = motion([&](double t) { return w * t; }, [&](double) { return w; }, 6.5, 1e-3);
  for (std::size_t i = 5000; i < ts.rows.size(); ++i) ts.rows[i][2] = NAN;  // from t = 5 s
  const SteadyState ss = detectSteadyState(ts, 3);
  EXPECT_EQ(ss.finite_rows, 5000u);
  EXPECT_EQ(ss.revolutions_counted, 4);  // crossings at 1..4 s; t = 5 s is not a finite row
  EXPECT_LE(ss.row_end, 5000u);
  EXPECT_NE(ss.note.find("non-finite"), std::string::npos);
}

TEST(SteadyState, MissingColumnsOrEmptyTableDoNotThrow) {
  Table empty;
  empty.columns = {"t", "phi_crank", "omega_crank"};
  SteadyState ss;
  EXPECT_NO_THROW(ss = detectSteadyState(empty, 3));
  EXPECT_FALSE(ss.reached);
  EXPECT_EQ(ss.row_begin, ss.row_end);
  Table no_phi;
  no_phi.columns = {"t"};
  no_phi.rows = {{0.0}, {1.0}};
  EXPECT_NO_THROW(ss = detectSteadyState(no_phi, 3));
  EXPECT_FALSE(ss.note.empty());
}

namespace {

// A motion whose every revolution has the same mean speed while its waveform still settles:
// ω = ω_s + A(t)·sin(2θ) with the ripple A(t) = a·(1 + e^{-t/τ}) decaying slowly; φ taken as
// ω_s·t (the ripple's mean over a revolution is 0 to first order, so the per-revolution means
// agree to ~a/ω_s·(T/τ)·e^{-t/τ}, far inside 1e-3).
Table settlingRipple(double t_end, double ws, double a, double tau) {
  return motion([=](double t) { return ws * t; },
                [=](double t) { return ws + a * (1 + std::exp(-t / tau)) * std::sin(2 * ws * t); }, t_end, 1e-3);
}

}  // namespace

TEST(SteadyState, TheRevolutionsExtremesMustRepeatAsWellAsTheirMeans) {
  // ω_s = 10 rad/s, a = 0.5 rad/s, τ = 3 s: at t = 8 s the ripple's amplitude still falls by
  // a·e^{-t/τ}·T/τ ≈ 0.5·0.07·0.21 = 7e-3 rad/s per revolution, 7e-4 of ω_s but 3.5e-3 over the
  // five revolutions of the window: not steady by the extremes (the means agree throughout).
  const SteadyState early = detectSteadyState(settlingRipple(8.0, 10.0, 0.5, 3.0), 5);
  ASSERT_GE(early.revolutions_counted, 10);
  for (const CrankRevolution& r : early.revolutions) EXPECT_NEAR(r.omega_mean, 10.0, 1e-2);
  EXPECT_FALSE(early.reached);
  // By t = 40 s the ripple's decay is e^{-40/3} ≈ 2e-6 of a: the extremes repeat.
  EXPECT_TRUE(detectSteadyState(settlingRipple(40.0, 10.0, 0.5, 3.0), 5).reached);
}

TEST(SteadyState, ExtremaLocatedBetweenTheRowsSettleWhatTheRowsCannot) {
  // A sharp dip once per revolution: ω = 10 − 3·exp(−(s/w)²), s the time from the revolution's
  // middle, width w = 2 ms, against rows 5 ms apart whose phase slides every revolution: the rows
  // see the dip's bottom at 7 … 10 rad/s, one revolution to the next.
  const double ws = 10.0, T = 2 * kPi / ws, w = 2e-3;
  const auto omega = [&](double t) {
    const double s = std::fmod(t, T) - 0.5 * T;
    return ws - 3.0 * std::exp(-(s / w) * (s / w));
  };
  // φ: ω's integral, the dip's area subtracted per revolution (√π·w·3 each).
  const double dip_area = std::sqrt(kPi) * w * 3.0;
  const auto phi = [&](double t) {
    const double k = std::floor(t / T), s = std::fmod(t, T) - 0.5 * T;
    return ws * t - k * dip_area - 0.5 * dip_area * (1 + std::erf(s / w));
  };
  const Table ts = motion(phi, omega, 20.0, 5e-3);
  EXPECT_FALSE(detectSteadyState(ts, 5).reached);  // the rows' minima do not repeat
  std::vector<CrankSpeedExtremum> extrema;
  for (double tm = 0.5 * T; tm < 20.0; tm += T) extrema.push_back({tm, 7.0});
  const SteadyState ss = detectSteadyState(ts, 5, kSteadyStateRelativeTolerance, extrema);
  EXPECT_TRUE(ss.reached);
  EXPECT_DOUBLE_EQ(ss.revolutions.back().omega_min, 7.0);
}
