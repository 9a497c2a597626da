// crankshaft.throw_positions / bearing_positions / bending_stiffness (Scene::crankshaft): read as
// given, absent by default, and every bad input named by key with what was expected.
#include <gtest/gtest.h>

#include "scene/KeyEffects.h"
#include "scene/SceneTestSupport.h"

using namespace rollerdyn;
using namespace rollerdyn::test;

namespace {

std::string withShaft(const std::string& body) { return kMinimalScene + "crankshaft:\n" + body; }

}  // namespace

TEST(SceneCrankshaft, AbsentKeysLeaveTheLayoutEmpty) {
  const Scene s = parseSceneText(kMinimalScene, "test.yaml");
  EXPECT_FALSE(s.crankshaft.given());
  EXPECT_TRUE(s.crankshaft.throw_positions.empty());
}

TEST(SceneCrankshaft, PositionsAreReadPerCartAndPerBearing) {
  const Scene s = parseSceneText(withShaft("  throw_positions: [0.2, 0.8]\n  bearing_positions: [0, 0.5, 1.0]\n"),
                                 "test.yaml");
  ASSERT_TRUE(s.crankshaft.given());
  EXPECT_EQ(s.crankshaft.throw_positions, (std::vector<double>{0.2, 0.8}));
  EXPECT_EQ(s.crankshaft.bearing_positions, (std::vector<double>{0.0, 0.5, 1.0}));
}

TEST(SceneCrankshaft, OverhungThrowIsAccepted) {
  const Scene s = parseSceneText(withShaft("  throw_positions: [-0.3, 0.5]\n  bearing_positions: [0, 1]\n"), "test.yaml");
  EXPECT_EQ(s.crankshaft.throw_positions[0], -0.3);
}

TEST(SceneCrankshaft, ThrowCountMustEqualTheCarts) {
  expectSceneError(withShaft("  throw_positions: [0.2, 0.5, 0.8]\n  bearing_positions: [0, 1]\n"),
                   {"crankshaft.throw_positions", "a list of 2 numbers", "one per cart"});
}

TEST(SceneCrankshaft, OneThrowPositionForAllCartsIsRefused) {
  expectSceneError(withShaft("  throw_positions: 0.5\n  bearing_positions: [0, 1]\n"),
                   {"crankshaft.throw_positions", "a list of 2 numbers"});
}

TEST(SceneCrankshaft, BearingsMustAscend) {
  expectSceneError(withShaft("  throw_positions: [0.2, 0.8]\n  bearing_positions: [0, 1, 1]\n"),
                   {"crankshaft.bearing_positions[2]", "greater than crankshaft.bearing_positions[1]"});
}

TEST(SceneCrankshaft, OneBearingIsRefused) {
  expectSceneError(withShaft("  throw_positions: [0.2, 0.8]\n  bearing_positions: [0.5]\n"),
                   {"crankshaft.bearing_positions", "two or more"});
}

TEST(SceneCrankshaft, ThrowsWithoutBearingsNameTheMissingKey) {
  expectSceneError(withShaft("  throw_positions: [0.2, 0.8]\n"), {"crankshaft.bearing_positions"});
  expectSceneError(withShaft("  bearing_positions: [0, 1]\n"), {"crankshaft.throw_positions"});
}

TEST(SceneCrankshaft, BearingPositionsMustBeAList) {
  expectSceneError(withShaft("  throw_positions: [0.2, 0.8]\n  bearing_positions: 1\n"),
                   {"crankshaft.bearing_positions", "a list of numbers"});
}

TEST(SceneCrankshaft, BendingStiffnessIsReportedWithoutEffectOnTheReactions) {
  const Scene s = parseSceneText(
      withShaft("  throw_positions: [0.2, 0.8]\n  bearing_positions: [0, 0.5, 1]\n  bending_stiffness: 2.0e5\n"),
      "test.yaml");
  EXPECT_EQ(s.crankshaft.bending_stiffness, 2.0e5);
  bool named = false;
  for (const std::string& w : keysWithoutEffect(s, "multibody"))
    named = named || (w.find("crankshaft.bending_stiffness") != std::string::npos &&
                      w.find("do not depend on") != std::string::npos);
  EXPECT_TRUE(named);
}

namespace {
// kMinimalScene in the constrained formulation with a crank inertia: what a torsional chain needs.
std::string chainScene(const std::string& shaft) {
  std::string s = replaced("  t_end: 1.0", "  t_end: 1.0\n  formulation: constrained");
  s = replaced("  offset_deg: 90", "  offset_deg: 90\n  inertia_per_crank: 0.5", s);
  return s + "crankshaft:\n" + shaft;
}
}  // namespace

TEST(SceneCrankshaft, ATorsionalChainNeedsOnlyTheThrows) {
  const Scene s = parseSceneText(chainScene("  throw_positions: [0.8, 0.2]\n  torsional_stiffness: 1.0e6\n"), "test.yaml");
  EXPECT_TRUE(s.crankshaft.torsionalChain());
  EXPECT_FALSE(s.crankshaft.given());  // no bearings: the bearings' resultant only
  EXPECT_EQ(s.crankshaft.torsional_stiffness, 1.0e6);
  bool named = false;
  for (const std::string& w : keysWithoutEffect(s, "reduced"))
    named = named || (w.find("crankshaft.torsional_stiffness") != std::string::npos && w.find("rigid") != std::string::npos);
  EXPECT_TRUE(named);
  EXPECT_TRUE(keysWithoutEffect(s, "multibody").empty());
}

TEST(SceneCrankshaft, ATorsionalChainIsRefusedWhereItCannotBeBuilt) {
  // The minimal formulation (the scene files' default) turns one rigid crankshaft.
  expectSceneError(kMinimalScene + "crankshaft:\n  throw_positions: [0.2, 0.8]\n  torsional_stiffness: 1.0e6\n",
                   {"crankshaft.torsional_stiffness", "simulation.formulation: constrained"});
  expectSceneError(chainScene("  torsional_stiffness: 1.0e6\n"), {"crankshaft.throw_positions", "segment lengths"});
  expectSceneError(chainScene("  throw_positions: [0.5, 0.5]\n  torsional_stiffness: 1.0e6\n"),
                   {"crankshaft.throw_positions", "distinct positions"});
  // Massless rods and no crank inertia: a throw's inertia would vanish at its dead centres.
  expectSceneError(replaced("  model: distributed", "  model: massless",
                            replaced("  inertia_per_crank: 0.5", "  inertia_per_crank: 0",
                                     chainScene("  throw_positions: [0.2, 0.8]\n  torsional_stiffness: 1.0e6\n"))),
                   {"crank.inertia_per_crank", "each throw of the chain"});
  expectSceneError(chainScene("  throw_positions: [0.2, 0.8]\n  torsional_stiffness: -1\n"),
                   {"crankshaft.torsional_stiffness"});
}
