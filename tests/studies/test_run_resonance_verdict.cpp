// The resonance and stability verdict of a run (studies/ResonanceCheck.h): one answer at one crank
// speed, the modal analysis deciding, every word of its reasons from the analysis' numbers, and no
// verdict for a drive that has no steady motion.
//
// Findings it rests on: six carts at 60°, k = 8000 N·m·s/rad: the verdict said the mode "lies
// between the excitation orders 6 and 8" (order 8 is not excited by this layout), "decays more than
// a million-fold" beside a largest multiplier of 3.71e-06; later trials saw the first estimate's
// warning "p0 = 70.62 rad/s is within 10 % of 8·ω = 71.14 rad/s" beside the modal verdict "p = 70.36
// ... 70.92 rad/s lies 17 % below order 8" (two different ω in one warning), and a green "the steady
// motion is stable" under a red "Run INCOMPLETE: motor stalled".
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <regex>

#include <gtest/gtest.h>

#include "modes/DriveOrbit.h"
#include "studies/ResonanceCheck.h"
#include "support/SixCartScene.h"
#include "reduced/ReducedModel.h"

using namespace rollerdyn;

namespace {

Scene sixCarts(const std::vector<std::string>& more = {}) { return test_scenes::sixCartsAt60(more); }

// The run's state of a drive that turns steadily at the speed where the motor carries the mean
// load (about 10.6 rad/s for six carts: p0 = 65.05 rad/s is 6.1·ω, within 10 % of order 6).
RunState turning(const Scene& s) {
  const modes::SteadyGuess g = modes::steadyGuess(ReducedModel(s));
  EXPECT_TRUE(g.ok) << g.failure;
  return RunState{"turning", true, g.omega};
}

struct Verdict {
  RunResonance v;
  nlohmann::json summary;
};

Verdict verdictOf(const Scene& scene, const RunState& state) {
  Verdict out;
  out.v = judgeRunResonance(scene, state, nullptr);
  out.summary["warnings"] = nlohmann::json::array();
  putRunResonance(out.v, out.summary);
  return out;
}

std::string fmt(const char* f, double x) {
  char b[64];
  std::snprintf(b, sizeof b, f, x);
  return b;
}

}  // namespace

// The first estimate hits order 6 and the modal analysis refutes it (ζ = 0.82): no warning, one
// line saying so, and every crank speed in it the same ω, the run's (the trial's warning carried two).
TEST(RunResonanceVerdict, TheFirstEstimateIsNoWarningWhereTheModalAnalysisRefutesItAndOneOmegaIsUsed) {
  const Scene s = sixCarts();
  const RunState st = turning(s);
  const Verdict r = verdictOf(s, st);
  ASSERT_EQ(r.v.first_estimate.hits.size(), 1u) << "the first estimate should hit order 6 here";
  EXPECT_EQ(r.v.first_estimate.hits[0].harmonic, 6);
  EXPECT_TRUE(r.v.warnings.empty()) << r.v.warnings[0];
  EXPECT_TRUE(r.summary["warnings"].empty()) << r.summary["warnings"].dump(1);
  EXPECT_EQ(r.v.verdict, "no resonance");
  EXPECT_EQ(r.summary["resonance_verdict"]["first_estimate"], "refuted by the modal analysis");
  const std::string& line = r.v.verdict_line;
  ASSERT_NE(line.find("resonance verdict: the modal analysis refutes the first estimate"), std::string::npos) << line;
  // One ω: each "omega = W" names the run's ω, and "6*omega = X" is 6 times it.
  const std::string w = fmt("%.4g", st.omega);
  int named = 0;
  const std::regex omega_is("(^|[^*])omega = ([0-9.]+) rad/s");  // not "k*omega = ...", the order's frequency
  for (std::sregex_iterator it(line.begin(), line.end(), omega_is), end; it != end; ++it, ++named)
    EXPECT_EQ((*it)[2].str(), w) << line;
  EXPECT_GT(named, 0) << line;
  EXPECT_NE(line.find("6*omega = " + fmt("%.4g", 6 * st.omega) + " rad/s"), std::string::npos) << line;
  EXPECT_DOUBLE_EQ(r.summary["resonance_verdict"]["omega"].get<double>(), st.omega);
  EXPECT_DOUBLE_EQ(r.summary["resonance"]["omega"].get<double>(), st.omega);
  EXPECT_DOUBLE_EQ(r.summary["resonance_modal"]["omega"].get<double>(), st.omega);
}

// The decay per revolution is printed as the number 1/|μ| of the largest multiplier (three
// significant digits), not as a phrase that a multiplier of 3.7e-6 contradicts; the two
// frequencies from the multipliers named for what they are.
TEST(RunResonanceVerdict, TheDecayPerRevolutionIsTheLargestMultipliersInverse) {
  const Scene s = sixCarts();
  const Verdict r = verdictOf(s, turning(s));
  const std::string& c = r.v.conclusion;
  ASSERT_FALSE(c.empty()) << r.summary.dump(2);
  const double mu = r.summary["resonance_modal"]["max_multiplier_modulus"].get<double>();
  ASSERT_GT(mu, 1e-6);  // the trial's case: 3.71e-6
  std::smatch m;
  ASSERT_TRUE(std::regex_search(c, m, std::regex("decays at least ([0-9,.e+]+)-fold per revolution"))) << c;
  std::string digits = m[1].str();
  digits.erase(std::remove(digits.begin(), digits.end(), ','), digits.end());
  EXPECT_NEAR(std::stod(digits), 1 / mu, 0.005 / mu) << c;
  EXPECT_EQ(c.find("more than a million-fold"), std::string::npos) << c;
  std::smatch f;
  ASSERT_TRUE(std::regex_search(c, f, std::regex("oscillates at ([0-9.]+) rad/s \\(damped\\) about an undamped "
                                                 "natural frequency of ([0-9.]+) rad/s")))
      << c;
  EXPECT_LT(std::stod(f[1].str()), std::stod(f[2].str())) << c;
}

// The orders named are those that drive the coupling (multiples of 6 for six equal carts at 60°),
// the nearest one with the distance of p from it in per cent at the run's ω.
TEST(RunResonanceVerdict, TheNearestOrdersAreThoseThatDriveTheCoupling) {
  const Scene s = sixCarts();
  const RunState st = turning(s);
  const Verdict r = verdictOf(s, st);
  const std::string& c = r.v.conclusion;
  ASSERT_FALSE(c.empty());
  const std::vector<int> orders = r.summary["resonance_modal"]["excitation_orders"].get<std::vector<int>>();
  ASSERT_FALSE(orders.empty());
  EXPECT_EQ(orders.front(), 6);
  for (int k : orders) EXPECT_EQ(k % 6, 0) << "order " << k << " is not excited by six equal carts at 60 deg";
  const std::regex order_word("\\border ([0-9]+)");
  int named = 0;
  for (std::sregex_iterator it(c.begin(), c.end(), order_word), end; it != end; ++it, ++named)
    EXPECT_NE(std::find(orders.begin(), orders.end(), std::stoi((*it)[1].str())), orders.end()) << c;
  EXPECT_GT(named, 0) << c;
  const double p = r.summary["resonance_modal"]["p_band"]["mean"].get<double>();
  EXPECT_NE(c.find(fmt("%.2g %% above order 6", 100 * (p / (6 * st.omega) - 1))), std::string::npos) << c;
}

// Why the first estimate does not apply: the mode's damping ratio is stated, as a number.
TEST(RunResonanceVerdict, TheDampingRatioThatKeepsTheModeFromResonatingIsStated) {
  const Scene s = sixCarts();
  const Verdict r = verdictOf(s, turning(s));
  const double zeta = r.summary["resonance_modal"]["damping_ratio"].get<double>();
  EXPECT_NEAR(zeta, 0.82, 0.01);  // k = 8000 N·m·s/rad: ζ = 0.8195 (Floquet)
  EXPECT_NE(r.v.conclusion.find(fmt("damping ratio %.2g", zeta)), std::string::npos) << r.v.conclusion;
  EXPECT_NE(r.v.conclusion.find("no resonance peak"), std::string::npos) << r.v.conclusion;
}

// A drive that does not turn has no steady motion: neither a resonance nor a stability verdict
// (the report showed "the steady motion is stable" under "motor stalled"), and no first-estimate
// hit, whatever the mean speed of the window.
TEST(RunResonanceVerdict, ADriveWithoutASteadyMotionHasNoStabilityVerdict) {
  const Scene s = sixCarts();
  const double p0 = checkResonance(s, 10.0).p0;
  for (const RunState& st : {RunState{"stalled", false, p0 / 6}, RunState{"rocking", false, p0 / 6},
                             RunState{"starting", false, p0 / 6}, RunState{"at_rest", false, 0.0},
                             RunState{"turning", false, p0 / 6}}) {
    const Verdict r = verdictOf(s, st);
    EXPECT_EQ(r.v.stability, "not applicable") << st.motion;
    EXPECT_EQ(r.summary["stability"]["verdict"], "not applicable") << st.motion;
    EXPECT_FALSE(r.summary["stability"]["reason"].get<std::string>().empty()) << st.motion;
    EXPECT_EQ(r.summary["resonance_verdict"]["verdict"], "not applicable") << st.motion;
    EXPECT_FALSE(r.summary["resonance_modal"].contains("conclusion")) << st.motion;
    EXPECT_TRUE(r.summary["warnings"].empty()) << st.motion << ": " << r.summary["warnings"].dump();
    EXPECT_TRUE(r.v.first_estimate.hits.empty()) << st.motion;
    EXPECT_EQ(r.v.modal, nullptr) << st.motion << ": no analysis is made for it";
  }
  // What to do is said: a drive that did not start is made to start, a short run is run longer.
  EXPECT_NE(verdictOf(s, {"stalled", false, 0.0}).v.reason.find("does not turn"), std::string::npos);
  EXPECT_NE(verdictOf(s, {"turning", false, 10.0}).v.reason.find("run longer"), std::string::npos);
}

// A machine whose mean load exceeds the motor's breakdown torque has no steady motion of the
// linearized drive: the analysis says it is not applicable, a first-estimate hit stands as a
// warning labelled unchecked, and the verdict line says so (never silence).
TEST(RunResonanceVerdict, WithoutAModalAnalysisTheFirstEstimateStandsUnchecked) {
  const Scene s = sixCarts({"loads.roller_force_direction=opposes_velocity"});
  ASSERT_FALSE(modes::steadyGuess(ReducedModel(s)).ok);
  const double p0 = checkResonance(s, 10.0).p0;
  const Verdict r = verdictOf(s, RunState{"turning", true, p0 / 6.05});
  EXPECT_FALSE(r.v.modal_made);
  EXPECT_EQ(r.v.verdict, "unchecked first estimate");
  EXPECT_NE(r.v.verdict_line.find("resonance verdict: the modal analysis could not be made"), std::string::npos)
      << r.v.verdict_line;
  bool unchecked = false, not_applicable = false;
  for (const std::string& w : r.v.warnings) {
    unchecked = unchecked || (w.rfind("first estimate", 0) == 0 && w.find("unchecked") != std::string::npos);
    not_applicable = not_applicable || w.find("modal analysis not applicable") != std::string::npos;
  }
  EXPECT_TRUE(unchecked && not_applicable) << r.summary["warnings"].dump(1);
  EXPECT_FALSE(r.summary["resonance_modal"]["applicable"].get<bool>());
  EXPECT_EQ(r.summary["stability"]["verdict"], "not applicable");
}
