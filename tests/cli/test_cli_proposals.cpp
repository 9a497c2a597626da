// Every optimum or estimate the studies print is a run's value, or is labelled an estimate with
// the run that checks it beside it: the sweep's parabola, optimize's optimum, simulate's flywheel.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <regex>
#include <string>

#include <nlohmann/json.hpp>

#include "cli/CliTestSupport.h"

namespace rollerdyn {
namespace {

using test::model;
using test::runRollerdyn;
using test::slurp;
using test::TempDir;

constexpr auto npos = std::string::npos;
constexpr double kAccuracy = 1e-6;  // simulation.accuracy of the scenes (the schema's default)

// δ of `simulate SCENE --model reduced --set ...` (summary.json).
double simulatedDelta(const std::string& scene, const std::vector<std::string>& sets, const std::string& tag) {
  TempDir out(tag);
  std::vector<std::string> args = {"simulate", scene, "--model", "reduced", "--out", out.str()};
  for (const std::string& s : sets) args.insert(args.end(), {"--set", s});
  const auto r = runRollerdyn(args, 120);
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  const auto j = nlohmann::json::parse(slurp(out.path() / "summary.json"));
  return j["delta"].is_number() ? j["delta"].get<double>() : NAN;
}

// The trial's finding on a shipped scene: four carts with the circuit motor law have a kinked δ
// minimum at 90° (the evenly spread layout). The parabola through 75°, 90°, 105° puts the minimum
// at 89.57° with δ = 0.00876, below the grid's 0.00890; a run there gives 0.0133. The sweep must
// run the vertex and print the run's value, never the parabola's as a minimum.
TEST(CliProposals, SweepPrintsTheVertexRunNotTheParabolasEstimate) {
  TempDir out("vertex");
  const std::string scene = model("balanced-4cart.yaml");
  const auto r = runRollerdyn({"sweep", scene, "--param", "crank.offset_deg", "--values", "60:120:15", "--model",
                               "reduced", "--set", "motor.model=circuit", "--minimize", "delta", "--out", out.str()},
                              300);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  const auto j = nlohmann::json::parse(slurp(out.path() / "sweep.json"));
  // The parabola's vertex from the grid's three points, by hand (equal spacing h):
  // x = x1 + h(y0 − y2)/(2(y0 − 2y1 + y2)), predicted y1 − (y0 − y2)²/(8(y0 − 2y1 + y2)).
  const auto& pts = j["points"];
  ASSERT_EQ(pts.size(), 5u);
  const double y0 = pts[1]["metrics"]["delta"], y1 = pts[2]["metrics"]["delta"], y2 = pts[3]["metrics"]["delta"];
  ASSERT_LT(y1, y0);
  ASSERT_LT(y1, y2);
  const double c = y0 - 2 * y1 + y2, x = 90 + 15 * (y0 - y2) / (2 * c), predicted = y1 - (y0 - y2) * (y0 - y2) / (8 * c);
  const double at = j["optimum"]["parabola"]["parameter"];
  EXPECT_NEAR(at, x, 1e-9 * x);
  EXPECT_NEAR(j["optimum"]["parabola"]["predicted"].get<double>(), predicted, 1e-9);
  // A run at the vertex, made here with simulate, against the sweep's vertex run.
  char text[64];
  std::snprintf(text, sizeof text, "%.12g", at);
  const double run = simulatedDelta(scene, {"motor.model=circuit", std::string("crank.offset_deg=") + text}, "vertex-sim");
  EXPECT_NEAR(j["optimum"]["parabola"]["run"]["value"].get<double>(), run, kAccuracy * run);
  ASSERT_GT(run, predicted + kAccuracy * y0) << "the kink: the parabola's estimate does not hold";
  EXPECT_EQ(j["optimum"]["parabola"]["holds"], false);
  // The optimum is the better run: the grid's 90° (y1 < run).
  EXPECT_EQ(j["optimum"]["source"], "grid point");
  EXPECT_EQ(j["optimum"]["value"].get<double>(), y1);
  EXPECT_NE(r.out.find("[vertex of the parabola] crank.offset_deg=" + std::string(text)), npos) << r.out;
  // The console prints the grid point's run (6 significant digits) and the vertex run's (4).
  char best[64], vertex[64], estimate[64];
  std::snprintf(best, sizeof best, "%.6g", y1);
  std::snprintf(vertex, sizeof vertex, "%.4g", run);
  std::snprintf(estimate, sizeof estimate, "%.6g", predicted);
  EXPECT_NE(r.out.find(std::string("minimum of delta = ") + best + " at crank.offset_deg=90 (steady state reached)\n"), npos)
      << r.out;
  EXPECT_NE(r.out.find(std::string("does not hold: a run there gives ") + vertex), npos) << r.out;
  EXPECT_NE(r.out.find("refine the grid near 90 (--values 75:105:1.5)"), npos) << r.out;
  EXPECT_EQ(r.out.find(std::string("delta = ") + estimate + "\n"), npos) << r.out;  // the estimate is never a result
}

// optimize prints its optimum as the run at exactly the printed values: `simulate --set KEY=VALUE`
// with them gives the printed metric within the integration tolerance, and a minimised parameter
// is printed as it was applied (it printed "flywheel.inertia = 248.637" for a run at 248.636572173).
TEST(CliProposals, OptimizeOptimumReproducesWhenRunAtThePrintedValues) {
  const std::regex line("optimum: (\\S+) = (\\S+) at (\\S+)=(\\S+)");
  std::smatch m;
  {
    TempDir out("opt-delta");
    const std::string scene = model("recuperative-2cart.yaml");
    const auto r = runRollerdyn({"optimize", scene, "--param", "crank.offset_deg", "--range", "60:120", "--minimize",
                                 "delta", "--model", "reduced", "--method", "bobyqa", "--max-evals", "8", "--out",
                                 out.str()},
                                300);
    ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
    ASSERT_TRUE(std::regex_search(r.out, m, line)) << r.out;
    ASSERT_EQ(m[3], "crank.offset_deg");
    const double printed = std::stod(m[2]);
    const double run = simulatedDelta(scene, {"crank.offset_deg=" + m[4].str()}, "opt-delta-sim");
    EXPECT_NEAR(printed, run, kAccuracy * run) << m[0];
  }
  TempDir out("opt-flywheel");
  const std::string scene = model("energy-balanced-3cart.yaml");
  const auto r = runRollerdyn({"optimize", scene, "--param", "flywheel.inertia", "--range", "0:400", "--minimize",
                               "flywheel.inertia", "--constraint", "delta<=0.05", "--model", "reduced", "--method",
                               "cobyla", "--max-evals", "12", "--out", out.str()},
                              300);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  ASSERT_TRUE(std::regex_search(r.out, m, line)) << r.out;
  EXPECT_EQ(m[2].str(), m[4].str()) << m[0];  // the minimised inertia is the one the run used
  const double run = simulatedDelta(scene, {"flywheel.inertia=" + m[2].str()}, "opt-flywheel-sim");
  const auto j = nlohmann::json::parse(slurp(out.path() / "optimize.json"));
  EXPECT_NEAR(j["optimum"]["metrics"]["delta"].get<double>(), run, kAccuracy * run);
  EXPECT_LE(run, 0.05 * (1 + kAccuracy));
}

// simulate's flywheel for δ* is an estimate (excess work, or the run's δ·J extrapolated), never
// run by simulate: the console, summary.json and the report all say so, with its basis, and give a
// run that checks it; that run, as printed, runs the printed flywheel.
TEST(CliProposals, FlywheelProposalIsLabelledAnEstimateEverywhereWithARunThatChecksIt) {
  const std::string scene = model("recuperative-2cart.yaml");
  const std::vector<std::string> sets = {"--set", "sizing.target_delta=0.04", "--set", "simulation.t_end=8", "--set",
                                         "simulation.reactions=false"};
  TempDir out("flywheel"), rep("flywheel-report");
  std::vector<std::string> args = {"simulate", scene, "--out", out.str()};
  args.insert(args.end(), sets.begin(), sets.end());
  const auto r = runRollerdyn(args, 120);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  args = {"report", scene, "--out", rep.str()};
  args.insert(args.end(), sets.begin(), sets.end());
  const auto rr = runRollerdyn(args, 300);
  ASSERT_EQ(rr.exit_code, 0) << rr.out << rr.err;
  const auto f = nlohmann::json::parse(slurp(out.path() / "summary.json"))["sizing"]["flywheel"];
  // JSON: the proposal is an estimate, with its basis and the runs that check it.
  ASSERT_EQ(f["estimate"], true) << f.dump(2);
  EXPECT_EQ(f["basis"].get<std::string>().rfind("an estimate, not run: ", 0), 0u) << f["basis"];
  const auto& check = f["check_by_runs"];
  ASSERT_TRUE(check["run_at_proposal"].is_string()) << f.dump(2);
  char proposal[32];
  std::snprintf(proposal, sizeof proposal, "%.4g", f["flywheel_crankshaft"].get<double>());  // the crankshaft's
  EXPECT_EQ(check["flywheel_inertia"].get<double>(), std::stod(proposal));
  // Console: the same number, labelled, with the basis and the check run.
  EXPECT_NE(r.out.find(std::string("for δ* = 0.04, by estimate: a flywheel of ") + proposal + " kg·m² in all on the crankshaft"),
            npos) << r.out;
  EXPECT_NE(r.out.find(f["basis"].get<std::string>()), npos) << r.out;
  const std::string cmd = check["run_at_proposal"];
  EXPECT_NE(r.out.find("      " + cmd + "\n"), npos) << r.out;
  // Report: the same number, labelled, with the basis and the check run.
  const std::string html = slurp(rep.path() / "report.html");
  EXPECT_NE(html.find(std::string("flywheel on the crankshaft reaching δ* (ESTIMATE, not run)</td><td class=\"n\">") + proposal),
            npos);
  std::string basis_html;  // as the page escapes it
  for (char c : f["basis"].get<std::string>()) basis_html += c == '\'' ? std::string("&#39;") : std::string(1, c);
  EXPECT_NE(html.find(basis_html), npos) << basis_html;
  EXPECT_NE(html.find("<code>" + cmd + "</code>"), npos);
  // The check run, as printed, runs the printed flywheel.
  ASSERT_EQ(cmd.rfind("rollerdyn simulate ", 0), 0u) << cmd;
  EXPECT_NE(cmd.find(std::string(" --set flywheel.inertia=") + proposal), npos) << cmd;
  TempDir run("flywheel-check");
  const std::string line = std::string(ROLLERDYN_BINARY) + cmd.substr(std::string("rollerdyn").size()) + " --out " +
                           run.str() + " > /dev/null 2>&1";
  ASSERT_EQ(WEXITSTATUS(std::system(line.c_str())), 0) << line;
  const auto checked = nlohmann::json::parse(slurp(run.path() / "summary.json"));
  EXPECT_EQ(checked["overrides"].back(), std::string("flywheel.inertia=") + proposal);
  EXPECT_TRUE(checked["delta"].is_number());
}

}  // namespace
}  // namespace rollerdyn
