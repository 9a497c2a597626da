// `rollerdyn identify`: its exit codes and files. A measurement made here by `simulate` (reduced
// model, 2 s, a softer coupling than the scene's; noise free, so the fit's own quality is the
// library tests' business, tests/studies/test_identify.cpp). Its only "noise" is simulate's own
// integration error (accuracy 1e-6, ~1e-7 of the speeds), so identify runs at --accuracy 1e-10:
// at its default 1e-8 the cost would be flat within its own integration noise near the optimum
// (docs/identify.md, "Stop"). The fit converges (exit 0) and writes
// identify.json with both keys, their std and the correlation matrix; one iteration from the
// scene's values cannot settle (exit 4, the reason in the JSON and on the console); a header in
// another unit is bad input (exit 2, one line naming file, line and column).
#include <gtest/gtest.h>

#include <fstream>

#include <nlohmann/json.hpp>

#include "cli/CliTestSupport.h"

namespace rollerdyn {
namespace {

using nlohmann::json;
using test::model;
using test::runRollerdyn;
using test::slurp;
using test::TempDir;

TEST(IdentifyCli, ExitCodesAndFiles) {
  TempDir dir("identify");
  const std::string measured = (dir.path() / "measured").string();
  ASSERT_EQ(runRollerdyn({"simulate", model("balanced-4cart.yaml"), "--model", "reduced", "--out", measured, "--set",
                          "simulation.t_end=2", "--set", "coupling.stiffness=120000"})
                .exit_code,
            0);
  const std::vector<std::string> common = {"identify", model("balanced-4cart.yaml"), "--model", "reduced", "--data",
                                           measured + "/timeseries.csv", "--signals", "omega_crank,omega_motor",
                                           "--free", "coupling.stiffness,coupling.damping", "--bounds",
                                           "coupling.stiffness=2e4:2e6", "--bounds", "coupling.damping=500:50000",
                                           "--accuracy", "1e-10"};
  std::vector<std::string> ok = common;
  ok.insert(ok.end(), {"--out", (dir.path() / "ok").string()});
  const test::CliResult r = runRollerdyn(ok);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  const json j = json::parse(slurp(dir.path() / "ok" / "identify.json"));
  EXPECT_TRUE(j["convergence"]["converged"].get<bool>());
  ASSERT_EQ(j["keys"].size(), 2u);
  EXPECT_EQ(j["keys"][0]["key"], "coupling.stiffness");
  EXPECT_NEAR(j["keys"][0]["value"].get<double>(), 120000, 0.01 * 120000);  // noise free: the truth to far better
  EXPECT_EQ(j["correlation"]["matrix"].size(), 2u);
  EXPECT_NE(r.out.find("coupling.stiffness"), std::string::npos);

  std::vector<std::string> short_fit = common;
  short_fit.insert(short_fit.end(), {"--max-iterations", "1", "--out", (dir.path() / "short").string()});
  const test::CliResult s = runRollerdyn(short_fit);
  EXPECT_EQ(s.exit_code, 4) << s.out << s.err;
  EXPECT_NE(s.out.find("NOT CONVERGED: the iteration limit (1)"), std::string::npos) << s.out;
  EXPECT_FALSE(json::parse(slurp(dir.path() / "short" / "identify.json"))["convergence"]["converged"].get<bool>());

  const std::string bad = (dir.path() / "bad.csv").string();
  std::ofstream(bad) << "t[s],omega_crank[rpm]\n0,1\n0.1,2\n0.2,3\n";
  const test::CliResult b = runRollerdyn({"identify", model("balanced-4cart.yaml"), "--data", bad, "--free",
                                          "coupling.stiffness", "--bounds", "coupling.stiffness=2e4:2e6"});
  EXPECT_EQ(b.exit_code, 2);
  EXPECT_NE(b.err.find(bad + ":1: column 'omega_crank' (column 2): expected the header omega_crank[rad/s]"),
            std::string::npos)
      << b.err;
}

}  // namespace
}  // namespace rollerdyn
