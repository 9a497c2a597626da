// The resonance warnings of the modal analysis (what simulate's verdict rests on).
#include <gtest/gtest.h>

#include "modes/ModalAnalysis.h"
#include "scene/SceneParser.h"

using namespace rollerdyn;
using namespace rollerdyn::modes;

namespace {
ModesReport light(const std::vector<std::string>& overrides) {
  ModesOptions o;
  o.multibody = false;
  o.campbell = false;
  o.charts = false;
  o.angles = 36;
  return analyseModes(parseSceneFile(std::string(ROLLERDYN_SOURCE_DIR) + "/model/balanced-4cart.yaml", overrides), o);
}
bool mentions(const std::vector<std::string>& w, const std::string& text) {
  for (const std::string& s : w)
    if (s.find(text) != std::string::npos) return true;
  return false;
}
}  // namespace

// Undamped coupling of 73 kN·m/rad: the coupling mode sits at p ≈ 4ω, the four-cart layout's
// first exciting order (its load torque's largest harmonic).
TEST(ModalWarnings, ForcedResonanceAtTheLayoutsFirstOrder) {
  const ModesReport r = light({"coupling.stiffness=73000", "coupling.damping=0"});
  ASSERT_TRUE(r.steady.found) << r.steady.failure;
  EXPECT_TRUE(mentions(r.warnings, "within 5 % of order 4 of the crank speed")) << (r.warnings.empty() ? "" : r.warnings[0]);
}

// The papers' coupling: the mode lies between orders 4 and 8 and is stable: no warning. At p ≈ 3ω
// (41 kN·m/rad) the two-mass check would warn (3ω), but order 3 does not excite four equal carts.
TEST(ModalWarnings, NoneBetweenTheOrders) {
  EXPECT_TRUE(light({}).warnings.empty());
  EXPECT_TRUE(light({"coupling.stiffness=41000", "coupling.damping=0"}).warnings.empty());
}
