// Bad --set arguments end-to-end: exit code 2 and ONE line on stderr naming the argument, the
// key path, what was expected and what was found (README: "Exit codes"). One case per class of
// syntax error: missing '=', empty key, unknown key, key below a leaf, bad value, unclosed flow
// list, trailing comma after a flow list (found by fuzz/scene_fuzzer.cpp: it was silently dropped).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "cli/CliTestSupport.h"

namespace rollerdyn {
namespace {

using test::model;
using test::runRollerdyn;

struct SetCase {
  const char* arg;
  std::vector<std::string> fragments;
};

TEST(CliSetErrors, EachClassIsRejectedWithItsMessage) {
  const std::vector<SetCase> cases = {
      {"carts.count", {"--set #1 (carts.count): carts.count: expected KEY.PATH=VALUE", "got no '='"}},
      {"=4", {"--set #1 (=4)", "expected a key path of the scene schema", "one of the top-level keys"}},
      {"carts.cuont=4", {"--set #1 (carts.cuont=4): carts.cuont: expected a key path of the scene schema",
                         "did you mean 'count'?"}},
      {"crank.radius.x=1", {"--set #1 (crank.radius.x=1): crank.radius.x: expected no key below leaf key crank.radius"}},
      {"rods.length=abc", {"--set #1 (rods.length=abc): rods.length: expected a number > 0 [m], got abc"}},
      {"rods.length=0.1", {"--set #1 (rods.length=0.1): rods.length: expected l > r = 0.2 m"}},
      {"carts.sides=[same", {"--set #1 (carts.sides=[same): carts.sides: expected a YAML scalar or flow value"}},
      {"carts.sides=[same, same, same, same],",
       {"carts.sides: expected a YAML scalar or flow value", "a ',' outside a flow list or map"}},
      {"coupling.damping=", {"--set #1 (coupling.damping=): coupling.damping: expected a number"}},
  };
  for (const SetCase& c : cases) {
    SCOPED_TRACE(c.arg);
    const auto r = runRollerdyn({"check", model("balanced-4cart.yaml"), "--set", c.arg}, 60);
    EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
    EXPECT_EQ(r.err.rfind("rollerdyn: ", 0), 0u) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "expected one line:\n" << r.err;
    for (const std::string& f : c.fragments) EXPECT_NE(r.err.find(f), std::string::npos) << "lacks \"" << f << "\":\n" << r.err;
  }
}

TEST(CliSetErrors, SecondSetArgumentIsNamed) {
  const auto r = runRollerdyn(
      {"check", model("balanced-4cart.yaml"), "--set", "crank.offset_deg=60", "--set", "crank.offset_deg=400"}, 60);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--set #2 (crank.offset_deg=400): crank.offset_deg:"), std::string::npos) << r.err;
}

TEST(CliSetErrors, GoodOverrideStillPasses) {
  const auto r = runRollerdyn({"check", model("balanced-4cart.yaml"), "--set", "crank.offset_deg=60"}, 60);
  EXPECT_EQ(r.exit_code, 0) << r.err;
}

TEST(CliSetErrors, MissingSceneFileIsBadInput) {
  const auto r = runRollerdyn({"check", "/nonexistent/scene.yaml"}, 60);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("scene.yaml"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace rollerdyn
