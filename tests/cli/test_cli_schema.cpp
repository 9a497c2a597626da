// `rollerdyn schema`: the scene keys from the schema itself. --markdown prints exactly the
// committed scene file reference (docs/scene-reference.md), so the page cannot drift from what the
// parser accepts; --columns prints the output columns' tables the outputs page holds; KEY shows
// one key or section; a misspelt KEY is a usage error with a hint.
#include <gtest/gtest.h>

#include <string>

#include "cli/CliTestSupport.h"

namespace rollerdyn {
namespace {

using test::runRollerdyn;

TEST(CliSchema, MarkdownIsTheCommittedReference) {
  const auto r = runRollerdyn({"schema", "--markdown"}, 60);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string committed = test::slurp(std::string(ROLLERDYN_SOURCE_DIR) + "/docs/scene-reference.md");
  EXPECT_TRUE(r.out == committed)
      << "docs/scene-reference.md differs from `rollerdyn schema --markdown`; regenerate it:\n"
         "  ./build/rollerdyn schema --markdown > docs/scene-reference.md";
}

TEST(CliSchema, ColumnsAreTheTablesOfTheOutputsPage) {
  const auto r = runRollerdyn({"schema", "--columns"}, 60);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("| `omega_crank` | rad/s |"), std::string::npos) << r.out;
  const std::string page = test::slurp(std::string(ROLLERDYN_SOURCE_DIR) + "/docs/outputs.md");
  EXPECT_NE(page.find(r.out), std::string::npos)
      << "docs/outputs.md's column tables differ from `rollerdyn schema --columns`: replace them by its output";
}

TEST(CliSchema, OneSectionWithUnitsDefaultsAndSources) {
  const auto r = runRollerdyn({"schema", "coupling"}, 60);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("coupling.damping [N·m·s/rad]  default 0"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("coupling.stiffness [N·m/rad]  conditional: required when coupling.type is elastic"),
            std::string::npos) << r.out;
  EXPECT_NE(r.out.find("source: Loveikin, Pochka, Romasevych (2018) eq. (58)"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("motor."), std::string::npos) << "only the section asked for:\n" << r.out;
}

TEST(CliSchema, MisspeltKeyIsAUsageErrorWithAHint) {
  const auto r = runRollerdyn({"schema", "couplng.damping"}, 60);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("did you mean 'coupling.damping'?"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace rollerdyn
