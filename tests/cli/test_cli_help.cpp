// `rollerdyn --help` and every command's --help: listed, exit 0, with examples (CLI11 footers).
#include <gtest/gtest.h>

#include <sstream>

#include "cli/CliTestSupport.h"

namespace rollerdyn {
namespace {

using test::runRollerdyn;

TEST(CliHelp, TopLevelListsCommandsAndATypicalSession) {
  const auto r = runRollerdyn({"--help"}, 60);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* cmd : {"check", "simulate", "plot", "report"})
    EXPECT_NE(r.out.find(cmd), std::string::npos) << "--help does not list " << cmd << ":\n" << r.out;
  EXPECT_NE(r.out.find("A typical session"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("Exit codes"), std::string::npos) << r.out;
}

TEST(CliHelp, EachOfOurCommandsHasExamples) {
  for (const char* cmd : {"check", "simulate", "plot", "report"}) {
    SCOPED_TRACE(cmd);
    const auto r = runRollerdyn({cmd, "--help"}, 60);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("Example"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find(std::string("rollerdyn ") + cmd), std::string::npos) << r.out;
  }
}

// Every subcommand --help lists (whoever added it) shows at least one example.
TEST(CliHelp, EverySubcommandHasAnExample) {
  const auto top = runRollerdyn({"--help"}, 60);
  const size_t at = top.out.find("Subcommands:");
  ASSERT_NE(at, std::string::npos) << top.out;
  std::istringstream in(top.out.substr(at));
  std::string line;
  std::getline(in, line);
  int commands = 0;
  while (std::getline(in, line) && line.rfind("  ", 0) == 0) {
    std::istringstream words(line);
    std::string cmd;
    words >> cmd;
    ++commands;
    SCOPED_TRACE(cmd);
    const auto r = runRollerdyn({cmd, "--help"}, 60);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("Example"), std::string::npos) << r.out;
  }
  EXPECT_GE(commands, 4);
}

TEST(CliHelp, SimulateOffersPlot) {
  const auto r = runRollerdyn({"simulate", "--help"}, 60);
  EXPECT_NE(r.out.find("--plot"), std::string::npos) << r.out;
}

TEST(CliHelp, NoCommandIsAnError) {
  const auto r = runRollerdyn({}, 60);
  EXPECT_NE(r.exit_code, 0);
}

}  // namespace
}  // namespace rollerdyn
