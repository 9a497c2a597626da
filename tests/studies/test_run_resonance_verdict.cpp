// The resonance verdict simulate prints when the first estimate warns and the modal analysis does
// not: every word of it must follow from the analysis' numbers. Finding of the six-cart trial
// (six carts at 60°, k = 8000 N·m·s/rad): the verdict said the mode "lies between the excitation
// orders 6 and 8" (order 8 is not excited by this layout; p/ω = 6.09 is 1.5 % above order 6), "it
// decays more than a million-fold per revolution" beside a largest multiplier of 3.71e-06 (a
// 270,000-fold decay), and never said why the first estimate's warning does not apply: the mode's
// heavy damping.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <regex>

#include <gtest/gtest.h>

#include "modes/RunModes.h"
#include "scene/SceneParser.h"
#include "support/SixCartScene.h"

using namespace rollerdyn;
using namespace rollerdyn::modes;

namespace {

Scene sixCarts(const std::vector<std::string>& more = {}) { return test_scenes::sixCartsAt60(more); }

struct Verdict {
  std::string line;  // "resonance verdict: ..."
  nlohmann::json summary;
};

// The verdict as simulate makes it, with a first-estimate warning standing (the verdict is only
// printed beside one).
Verdict verdictOf(const Scene& scene) {
  Verdict v;
  v.summary["warnings"] = nlohmann::json::array();
  const std::vector<std::string> lines =
      writeResonanceVerdict(scene, v.summary, {"torsional resonance: p0 near 6*omega (test stand-in)"});
  for (const std::string& l : lines)
    if (l.rfind("resonance verdict:", 0) == 0) v.line = l;
  return v;
}

std::string fmt(const char* f, double x) {
  char b[64];
  std::snprintf(b, sizeof b, f, x);
  return b;
}

}  // namespace

// The decay per revolution is printed as the number 1/|μ| of the largest multiplier (three
// significant digits), not as a phrase that a multiplier of 3.7e-6 contradicts; "more than a
// million-fold" only for a multiplier that is below 1e-6.
TEST(ResonanceVerdict, TheDecayPerRevolutionIsTheLargestMultipliersInverse) {
  const Verdict v = verdictOf(sixCarts());
  ASSERT_FALSE(v.line.empty()) << v.summary.dump(2);
  const double mu = v.summary["resonance_modal"]["max_multiplier_modulus"].get<double>();
  ASSERT_GT(mu, 1e-6);  // the trial's case: 3.71e-6
  std::smatch m;
  ASSERT_TRUE(std::regex_search(v.line, m, std::regex("decays at least ([0-9,.e+]+)-fold per revolution"))) << v.line;
  std::string digits = m[1].str();
  digits.erase(std::remove(digits.begin(), digits.end(), ','), digits.end());
  EXPECT_NEAR(std::stod(digits), 1 / mu, 0.005 / mu) << v.line;  // three significant digits
  EXPECT_EQ(v.line.find("more than a million-fold"), std::string::npos) << v.line;  // every |μ| here is > 1e-6
  // The two frequencies from the multipliers named for what they are: the third trial read the
  // undamped one (25.9 rad/s) labelled "with its damping" beside `modes`' damped 14.85 rad/s.
  std::smatch f;
  ASSERT_TRUE(std::regex_search(v.line, f, std::regex("oscillates at ([0-9.]+) rad/s \\(damped\\) about an undamped "
                                                      "natural frequency of ([0-9.]+) rad/s")))
      << v.line;
  EXPECT_LT(std::stod(f[1].str()), std::stod(f[2].str())) << v.line;  // damped below undamped
}

// The orders named are the layout's (the list `modes` prints: 6, 12, 18, 24 for six carts at 60°),
// the nearest one with the distance of p from it in per cent.
TEST(ResonanceVerdict, TheNearestOrdersAreTheLayoutsOwn) {
  const Verdict v = verdictOf(sixCarts());
  ASSERT_FALSE(v.line.empty()) << v.summary.dump(2);
  const std::vector<int> layout = v.summary["resonance_modal"]["excitation_orders"].get<std::vector<int>>();
  ASSERT_FALSE(layout.empty());
  EXPECT_EQ(layout.front(), 6);
  for (int k : layout) EXPECT_EQ(k % 6, 0) << "order " << k << " is not excited by six equal carts at 60 deg";
  // Every order the verdict names is one of them.
  const std::regex order_word("\\border ([0-9]+)|\\borders ([0-9]+) and ([0-9]+)");
  int named = 0;
  for (std::sregex_iterator it(v.line.begin(), v.line.end(), order_word), end; it != end; ++it)
    for (int g = 1; g <= 3; ++g)
      if ((*it)[g].matched) {
        ++named;
        const int k = std::stoi((*it)[g].str());
        EXPECT_NE(std::find(layout.begin(), layout.end(), k), layout.end()) << "order " << k << " in: " << v.line;
      }
  EXPECT_GT(named, 0) << v.line;
  // p/ω = 6.09: 1.5 % above order 6 (the mean frozen-angle frequency against 6ω).
  const double w = v.summary["resonance_modal"]["omega"].get<double>();
  const double p = v.summary["resonance_modal"]["p_band"]["mean"].get<double>();
  EXPECT_NE(v.line.find(fmt("%.2g %% above order 6", 100 * (p / (6 * w) - 1))), std::string::npos) << v.line;
}

// Why the first estimate's warning does not apply: the mode's damping ratio is stated, as a number.
TEST(ResonanceVerdict, TheDampingRatioThatKeepsTheModeFromResonatingIsStated) {
  const Verdict v = verdictOf(sixCarts());
  ASSERT_FALSE(v.line.empty()) << v.summary.dump(2);
  ASSERT_TRUE(v.summary["resonance_modal"].contains("damping_ratio")) << v.summary["resonance_modal"].dump(2);
  const double zeta = v.summary["resonance_modal"]["damping_ratio"].get<double>();
  EXPECT_NEAR(zeta, 0.82, 0.01);  // k = 8000 N·m·s/rad: ζ = 0.8195 (two-mass check)
  EXPECT_NE(v.line.find(fmt("damping ratio %.2g", zeta)), std::string::npos) << v.line;
  EXPECT_NE(v.line.find("no resonance peak"), std::string::npos) << v.line;  // ζ > 1/√2
}
