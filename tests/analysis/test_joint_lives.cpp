// Joint lives (JointSizing.h) on a synthetic crank-slider run whose every figure is written down
// by hand: one cart on a centred crank-slider (r, l) turning at constant Ω, the rod swinging through
// ±γ about the cart's pin with γ = asin(r/l) computed here, forces chosen so that the equivalent
// loads have closed forms. The run is built from the slider-crank geometry in this file, not from
// the code under test.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <utility>
#include <string>

#include "analysis/DriveSizing.h"
#include "analysis/SizingSummary.h"
#include "analysis/SteadyState.h"

using namespace rollerdyn;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double Om = 10.5;               // crank speed Ω [rad/s]: f = Ω/2π = 1.67 swings per second
constexpr double r = 0.2, l = 0.8;        // crank radius, rod length [m]
constexpr double d = 0.046;               // guide-roller diameter [m]
constexpr double G0 = 5000;               // guide force, constant [N]
constexpr double R0 = 20000, R1 = 8000;   // rod force R0 + R1·β/γ [N]
constexpr double A0 = 30000, A1 = 10000;  // crank-pin force A0 + A1·cos θ [N]
constexpr double B0 = 4000;               // main-bearing resultant, constant [N]
constexpr double C_roller = 40000, C_rod = 60000, C_pin = 150000, C_main = 50000;  // ratings [N]

// The rod angle of a centred crank-slider: the cart's pin B on the line through the shaft axis,
// sin β = (r/l)·sin θ, so |β| ≤ asin(r/l).
double beta(double th) { return std::asin(r / l * std::sin(th)); }
double gammaSwing() { return std::asin(r / l); }

Scene scene() {
  Scene s{};
  s.name = "synthetic crank-slider";
  s.simulation.steady_window_revolutions = 4;
  s.crank.radius = r;
  s.crank.offset = 0;
  s.rods.length = l;
  s.rods.model = RodModel::Massless;
  s.carts.count = 1;
  s.carts.side = {1};
  s.carts.mass = 1000;
  s.carts.geometry.d = d;
  s.sizing.rating_guide_roller = C_roller;
  s.sizing.rating_rod_end = C_rod;
  s.sizing.rating_crank_pin = C_pin;
  s.sizing.rating_main_bearing = C_main;
  return s;
}

// 6 revolutions at constant Ω, K rows per revolution.
RunResult run(long K = 20000) {
  RunResult rr;
  rr.model = "multibody";
  rr.timeseries.columns = {"t", "phi_crank", "omega_crank", "v_cart_1"};
  rr.reactions.columns = {"t", "N_front_1", "F_rod_1", "crankpin_x_1", "crankpin_y_1", "bearing_x", "bearing_y"};
  const double T = 6 * 2 * kPi / Om;
  const long N = 6 * K;
  for (long i = 0; i <= N; ++i) {
    const double t = T * i / N, th = Om * t;
    // x_B = r·cos θ + l·cos β, v = dx_B/dt.
    const double v = Om * (-r * std::sin(th) - r * r / l * std::sin(th) * std::cos(th) / std::cos(beta(th)));
    rr.timeseries.rows.push_back({t, th, Om, v});
    const double F_pin = A0 + A1 * std::cos(th);
    rr.reactions.rows.push_back({t, G0, R0 + R1 * beta(th) / gammaSwing(), F_pin * std::cos(th),
                                 F_pin * std::sin(th), B0, 0.0});
  }
  return rr;
}

DriveSizing sized(const RunResult& rr, bool turning = true, const std::string& motion = "turning") {
  const Scene sc = scene();
  const SteadyState w = detectSteadyState(rr.timeseries, sc.simulation.steady_window_revolutions);
  return computeDriveSizing(sc, rr, w, turning, turning ? 0.0 : NAN, motion);
}

const nlohmann::json& row(const nlohmann::json& sizing, const char* kind) {
  return sizing.at("joints").at(kind).at("worst");
}

}  // namespace

#define EXPECT_REL(x, y, rel) EXPECT_NEAR((x), (y), (rel) * std::abs(y))

// The rod end oscillates through 2γ once per crank revolution: ISO 281's L10 in revolutions,
// converted for oscillation, L10_osc = L10·180°/(2γ), in hours at f = Ω/2π oscillations a second.
TEST(JointLives, RodEndGetsTheOscillatingBearingLifeInHours) {
  const DriveSizing s = sized(run());
  const nlohmann::json z = sizingJson(s);
  const nlohmann::json& rod = row(z, "rod_end");
  const double gamma_deg = gammaSwing() * 180 / kPi;  // 14.48° for r/l = 0.25
  // P weighted by the swing speed |β̇|: β runs over [-γ, γ] twice a revolution, uniformly in the
  // weight, so P³ = mean over x ∈ [-1, 1] of (R0 + R1·x)³ = R0³ + R0·R1².
  const double P = std::cbrt(R0 * R0 * R0 + R0 * R1 * R1);
  EXPECT_REL(rod.at("equivalent_load").get<double>(), P, 1e-4);
  const double L10 = std::pow(C_rod / P, 3) * 1e6;
  const double L10_osc = L10 * 180 / (2 * gamma_deg);
  const double f = Om / (2 * kPi);
  ASSERT_TRUE(rod.at("L10_hours").is_number()) << rod.dump(1);
  EXPECT_REL(rod.at("L10_hours").get<double>(), L10_osc / (3600 * f), 3e-4);
  EXPECT_REL(rod.at("L10_oscillations").get<double>(), L10_osc, 3e-4);
  EXPECT_NEAR(rod.at("oscillation_angle_deg").get<double>(), 2 * gamma_deg, 1e-9);
  EXPECT_EQ(rod.at("motion"), "oscillating");
  // The conversion holds while 2γ ≥ 720°/Z: Z ≥ 720°/28.96° = 24.9, at least 25 rolling elements.
  EXPECT_EQ(rod.at("rolling_elements_min").get<double>(), std::ceil(720 / (2 * gamma_deg)));
  EXPECT_NE(rod.at("life_basis").get<std::string>().find("at least Z = 25 rolling elements"), std::string::npos);
}

// Guide rollers: the life in roller revolutions from the rolled distance. A centred crank-slider
// moves the cart 2r each way, 4r per crank revolution, so the roller turns 4r/(π·d) times per
// crank revolution whatever the speed profile.
TEST(JointLives, GuideRollerLifeFromTheRolledDistance) {
  const DriveSizing s = sized(run());
  const JointSizing* g = s.worst("guide_roller_front");
  ASSERT_NE(g, nullptr);
  EXPECT_REL(g->load.equivalent, G0, 1e-9);
  const double roller_rev_per_s = 4 * r / (kPi * d) * Om / (2 * kPi);
  EXPECT_REL(g->life_hours, std::pow(C_roller / G0, 3) * 1e6 / (3600 * roller_rev_per_s), 1e-4);
}

// The crank pin turns relative to the rod's big end at ω·(1 + dβ/dθ) (σ = +1): one relative
// revolution per crank revolution, with P weighted by that relative speed, here by quadrature of
// the closed form dβ/dθ = λ·cos θ/√(1 - λ²·sin² θ).
TEST(JointLives, CrankPinWeightedByItsRotationRelativeToTheRod) {
  const DriveSizing s = sized(run());
  const JointSizing* pin = s.worst("crank_pin");
  ASSERT_NE(pin, nullptr);
  const double lam = r / l;
  const int M = 200000;
  double num = 0, den = 0;
  for (int i = 0; i < M; ++i) {
    const double th = 2 * kPi * (i + 0.5) / M, c = std::cos(th), sn = std::sin(th);
    const double n = 1 + lam * c / std::sqrt(1 - lam * lam * sn * sn);
    num += std::pow(A0 + A1 * c, 3) * n;
    den += n;
  }
  const double P = std::cbrt(num / den);
  EXPECT_REL(pin->load.equivalent, P, 1e-5);
  EXPECT_REL(pin->load.mean_speed, Om, 1e-5);  // one relative revolution per crank revolution
  EXPECT_REL(pin->life_hours, std::pow(C_pin / P, 3) * 1e6 / (Om / (2 * kPi) * 3600), 1e-4);
}

// A drive that does not turn wears no bearing: every life n/a with the reason, in every output.
TEST(JointLives, StalledDriveHasNoLivesAndSaysWhy) {
  for (const char* motion : {"stalled", "rocking", "at_rest"}) {
    const DriveSizing s = sized(run(2000), false, motion);
    ASSERT_FALSE(s.joints.empty());
    for (const JointSizing& j : s.joints) {
      EXPECT_TRUE(std::isnan(j.life_hours)) << motion << " " << j.joint;
      EXPECT_TRUE(std::isnan(j.life_revolutions)) << motion << " " << j.joint;
    }
    const nlohmann::json summary = {{"sizing", sizingJson(s)}, {"motion", motion}};
    for (const char* kind : {"guide_roller_front", "rod_end", "crank_pin", "main_bearing"}) {
      const nlohmann::json& x = row(summary.at("sizing"), kind);
      EXPECT_TRUE(x.at("L10_hours").is_null()) << kind;
      EXPECT_NE(x.value("life_reason", nlohmann::json()).dump().find("the drive does not turn"), std::string::npos)
          << kind << ": " << x.dump(1);
    }
    const std::string text = sizingText(summary);
    EXPECT_NE(text.find("L10 n/a: the drive does not turn (motion: " + std::string(motion) +
                        "): no running to wear the bearing"),
              std::string::npos)
        << text;
  }
}

// A drive still starting has no steady running yet: n/a, run longer.
TEST(JointLives, StartingDriveHasNoLivesUntilItRunsSteadily) {
  const DriveSizing s = sized(run(2000), false, "starting");
  for (const JointSizing& j : s.joints) EXPECT_TRUE(std::isnan(j.life_hours)) << j.joint;
  const nlohmann::json z = sizingJson(s);
  const nlohmann::json& rod = row(z, "rod_end");
  EXPECT_NE(rod.value("life_reason", nlohmann::json()).dump().find("run longer"), std::string::npos) << rod.dump(1);
}

// The console row of each joint shows the JSON's L10_hours under a header in hours (the trial:
// the console "2.34e+07 rev" beside the JSON's L10_revolutions 2.34e7 for the rod end).
TEST(JointLives, ConsoleShowsTheJsonLifeInHours) {
  const DriveSizing s = sized(run(4000));
  const nlohmann::json summary = {{"sizing", sizingJson(s)}, {"motion", "turning"}};
  const std::string text = sizingText(summary);
  EXPECT_NE(text.find("L10 [h]\n"), std::string::npos) << text;
  for (const auto& [kind, name] : {std::pair{"rod_end", "  rod end"}, std::pair{"guide_roller_front", "  guide roller, front"},
                                   std::pair{"crank_pin", "  crank pin"}}) {
    const nlohmann::json& x = row(summary.at("sizing"), kind);
    ASSERT_TRUE(x.at("L10_hours").is_number()) << kind;
    char hours[32];
    std::snprintf(hours, sizeof hours, " %.3g", x.at("L10_hours").get<double>());
    const std::size_t line = text.find(name);
    ASSERT_NE(line, std::string::npos) << text;
    const std::string console_row = text.substr(line, text.find('\n', line) - line);
    ASSERT_GE(console_row.size(), std::strlen(hours));
    EXPECT_EQ(console_row.substr(console_row.size() - std::strlen(hours)), hours) << console_row;
  }
}

// The main-bearing figure is the resultant of all main bearings on the crankshaft, and says so in
// the JSON and the console (the report renders the JSON's label: tests/report).
TEST(JointLives, MainBearingLabelledAsTheResultantOfAllBearings) {
  const DriveSizing s = sized(run(2000));
  const nlohmann::json summary = {{"sizing", sizingJson(s)}, {"motion", "turning"}};
  const std::string label =
      "main bearings, resultant on the crankshaft (all bearings together; per-bearing loads need the bearing "
      "positions)";
  EXPECT_EQ(summary.at("sizing").at("joints").at("main_bearing").value("what", ""), label);
  EXPECT_NE(sizingText(summary).find(label), std::string::npos);
}
