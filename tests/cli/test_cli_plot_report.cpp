// End-to-end: simulate --plot, plot DIR, and report SCENE on short runs of the model scenes.
// Checks the files exist and look like what they claim (PNG signature, SVG root, self-contained
// HTML), that nothing is written outside the output folder, and the error paths of `plot`.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <set>
#include <string>

#include "cli/CliTestSupport.h"

namespace rollerdyn {
namespace {

namespace fs = std::filesystem;
using test::model;
using test::runRollerdyn;
using test::slurp;
using test::TempDir;

bool isPng(const fs::path& p) { return slurp(p).rfind("\x89PNG\r\n\x1a\n", 0) == 0; }
bool isSvg(const fs::path& p) { return slurp(p).find("<svg") != std::string::npos; }

std::set<std::string> stems(const fs::path& dir, const std::string& ext) {
  std::set<std::string> out;
  if (!fs::is_directory(dir)) return out;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ext) out.insert(e.path().stem().string());
  return out;
}

// Every file under `dir`, relative.
std::set<std::string> tree(const fs::path& dir) {
  std::set<std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(dir)) out.insert(fs::relative(e.path(), dir).string());
  return out;
}

const std::set<std::string> kElasticFigures = {
    "crank_speed_vs_angle", "crank_accel_vs_angle", "crank_speed_vs_time", "crank_accel_vs_time",
    "coupling_torque_vs_time", "motor_operating_point", "motor_operating_point_steady", "motor_torque_vs_time",
    "motor_torque_vs_angle", "motor_power_vs_time", "motor_power_vs_angle", "guide_reactions_vs_angle", "rod_forces_vs_angle",
    "twist_phase_rate", "twist_phase_rate_accel", "twist_phase_accel"};

TEST(CliPlot, SimulateWithPlotThenPlotAgain) {
  TempDir out("plot-out");
  const auto sim = runRollerdyn({"simulate", model("balanced-4cart.yaml"), "--set", "simulation.t_end=3", "--out",
                                 out.str(), "--plot"});
  ASSERT_EQ(sim.exit_code, 0) << sim.out << sim.err;
  const fs::path figs = out.path() / "figures";
  EXPECT_EQ(stems(figs, ".png"), kElasticFigures);
  EXPECT_EQ(stems(figs, ".svg"), kElasticFigures);
  for (const std::string& f : kElasticFigures) {
    EXPECT_TRUE(isPng(figs / (f + ".png"))) << f;
    EXPECT_TRUE(isSvg(figs / (f + ".svg"))) << f;
  }
  // summary.json names the scene, so `plot` finds the motor data by itself.
  const auto s = nlohmann::json::parse(slurp(out.path() / "summary.json"));
  EXPECT_EQ(s["scene_path"], model("balanced-4cart.yaml"));

  fs::remove_all(figs);
  const auto plot = runRollerdyn({"plot", out.str()});
  ASSERT_EQ(plot.exit_code, 0) << plot.out << plot.err;
  EXPECT_EQ(stems(figs, ".png"), kElasticFigures) << plot.out;
  EXPECT_EQ(plot.out.find("without its Kloss curve"), std::string::npos) << plot.out;
  // Only the four outputs and the figures: no temporary or stray files.
  for (const std::string& f : tree(out.path()))
    EXPECT_TRUE(f == "timeseries.csv" || f == "reactions.csv" || f == "crank_speed_extrema.csv" ||
                f == "summary.json" || f == "figures" || f.rfind("figures/", 0) == 0)
        << "unexpected " << f;
}

TEST(CliPlot, RigidCouplingHasNoTwistPortraitsAndSaysWhy) {
  TempDir out("plot-rigid");
  const auto sim = runRollerdyn({"simulate", model("recuperative-2cart.yaml"), "--set", "simulation.t_end=3",
                                 "--out", out.str(), "--model", "reduced"});
  ASSERT_EQ(sim.exit_code, 0) << sim.err;
  const auto plot = runRollerdyn({"plot", out.str()});
  ASSERT_EQ(plot.exit_code, 0) << plot.err;
  const auto png = stems(out.path() / "figures", ".png");
  EXPECT_TRUE(png.count("motor_operating_point"));
  EXPECT_TRUE(png.count("rod_forces_vs_angle"));
  EXPECT_FALSE(png.count("twist_phase_rate"));
  EXPECT_NE(plot.out.find("rigid coupling"), std::string::npos) << plot.out;
}

TEST(CliPlot, WarnsWhenTheSceneDoesNotMatchTheRunsMotor) {
  TempDir out("plot-motor");
  const auto sim = runRollerdyn({"simulate", model("recuperative-2cart.yaml"), "--set", "simulation.t_end=2",
                                 "--set", "motor.breakdown_torque=300", "--out", out.str(), "--model", "reduced"});
  ASSERT_EQ(sim.exit_code, 0) << sim.err;
  // The run's own --set (recorded in summary.json) apply: the trial's `plot` of a run made with
  // another motor law, or with the motor off, warned "was the run made with other motor data?".
  const auto plain = runRollerdyn({"plot", out.str()});
  EXPECT_EQ(plain.exit_code, 0) << plain.err;
  EXPECT_EQ(plain.out.find("differs from the Kloss curve"), std::string::npos) << plain.out;
  // Other motor data than the run's still warn.
  const auto other = runRollerdyn({"plot", out.str(), "--set", "motor.breakdown_torque=500"});
  EXPECT_EQ(other.exit_code, 0) << other.err;
  EXPECT_NE(other.out.find("differs from the Kloss curve"), std::string::npos) << other.out;
  // A run with the motor off draws no motor figures, and says why.
  TempDir off("plot-motor-off");
  ASSERT_EQ(runRollerdyn({"simulate", model("recuperative-2cart.yaml"), "--set", "simulation.t_end=2", "--set",
                          "motor.enabled=false", "--out", off.str(), "--model", "reduced"})
                .exit_code,
            0);
  const auto coast = runRollerdyn({"plot", off.str()});
  EXPECT_EQ(coast.exit_code, 0) << coast.err;
  EXPECT_NE(coast.out.find("motor figures left out: the scene's motor is disabled"), std::string::npos) << coast.out;
}

// A catalogue law's run is drawn on its own steady curve, titled so: the second trial's Park run
// read "motor operating points on its Kloss curve" with the breakdown mark at Kloss's slip.
TEST(CliPlot, ACatalogueLawsOperatingPointsAreOnItsOwnCurve) {
  TempDir out("plot-park");
  const auto sim = runRollerdyn({"simulate", model("balanced-4cart.yaml"), "--model", "reduced", "--set",
                                 "motor.model=circuit", "--set", "simulation.t_end=2", "--out", out.str(), "--plot"});
  ASSERT_EQ(sim.exit_code, 0) << sim.err;
  const std::string svg = slurp(out.path() / "figures" / "motor_operating_point.svg");
  EXPECT_NE(svg.find("operating points on its steady torque-speed curve"), std::string::npos);
  EXPECT_EQ(svg.find("Kloss curve"), std::string::npos);
  EXPECT_EQ(sim.out.find("differs from the"), std::string::npos) << sim.out;  // the run is on its own curve
}

TEST(CliPlot, ErrorsAreBadInput) {
  TempDir empty("plot-empty");
  const auto r = runRollerdyn({"plot", empty.str()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("holds none of timeseries.csv"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::is_empty(empty.path())) << "plot wrote into a folder it could not use";
  EXPECT_NE(runRollerdyn({"plot", "/nonexistent-folder"}).exit_code, 0);

  TempDir bad("plot-bad");
  { std::ofstream(bad.path() / "timeseries.csv") << "t,omega_crank\n0,1\n0.1\n"; }
  const auto b = runRollerdyn({"plot", bad.str()});
  EXPECT_EQ(b.exit_code, 2);
  EXPECT_NE(b.err.find("timeseries.csv:3: expected 2 fields, got 1"), std::string::npos) << b.err;
}

TEST(CliReport, WritesOneSelfContainedPage) {
  TempDir out("report");
  const auto r = runRollerdyn({"report", model("balanced-4cart.yaml"), "--set", "simulation.t_end=3", "--set",
                               "crank.offset_deg=60", "--out", out.str()});
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  const std::string html = slurp(out.path() / "report.html");
  ASSERT_FALSE(html.empty());
  EXPECT_NE(html.find("<title>rollerdyn report: balanced-4cart</title>"), std::string::npos);
  for (const char* section : {"Scene", "Summary metrics", "Motion and drive sizing", "Motor", "Joints and bearings",
                              "Joint reactions over the steady window", "Figures",
                              "Scene parameters", "Derived quantities"})
    EXPECT_TRUE(html.find(std::string("<h2>") + section) != std::string::npos ||
                html.find(std::string("<h3>") + section) != std::string::npos)
        << "missing section " << section;
  // The run's resonance verdict is on the page as summary.json has it (the fourth trial's page showed
  // the first estimate's alarm only): a 3 s run of this drive has not settled, so the verdict and the
  // stability are n/a, with the reason, never a green "stable".
  const auto summary = nlohmann::json::parse(slurp(out.path() / "summary.json"));
  ASSERT_EQ(summary["resonance_verdict"]["verdict"], "not applicable") << summary["resonance_verdict"].dump();
  EXPECT_NE(html.find("Resonance verdict: n/a (" + summary["resonance_verdict"]["reason"].get<std::string>()),
            std::string::npos);
  EXPECT_NE(html.find("Stability of the steady motion (Floquet): n/a"), std::string::npos);
  EXPECT_EQ(html.find("steady motion is stable"), std::string::npos);
  // The count printed is the folder's: the trial read "16 figures" beside 23 (the modes' left out).
  std::size_t pngs = 0;
  for (const auto& f : fs::directory_iterator(out.path() / "figures")) pngs += f.path().extension() == ".png";
  EXPECT_NE(r.out.find(std::to_string(pngs) + " figures in "), std::string::npos) << pngs << "\n" << r.out;
  // Every figure embedded, none linked: the run's and those of the torsional-modes section.
  size_t embedded = 0, modes_figures = 0;
  for (size_t at = 0; (at = html.find("src=\"data:image/png;base64,", at)) != std::string::npos; ++at) ++embedded;
  for (const auto& f : fs::directory_iterator(out.path() / "figures")) {
    const std::string n = f.path().filename().string();
    if (f.path().extension() == ".png" && (n.rfind("frozen_", 0) == 0 || n.rfind("campbell", 0) == 0 ||
                                           n.rfind("stability_", 0) == 0 || n.rfind("spectrum_", 0) == 0))
      ++modes_figures;
  }
  EXPECT_GE(modes_figures, 3u);  // frozen-angle frequencies, Campbell diagram, stability charts
  EXPECT_EQ(embedded, kElasticFigures.size() + modes_figures);
  EXPECT_NE(html.find("<h2 id=\"modes\">Torsional modes and stability</h2>"), std::string::npos);
  for (const char* remote : {"src=\"http", "href=", "src=\"figures/", "<script src", "<link", "@import"})
    EXPECT_EQ(html.find(remote), std::string::npos) << "page refers to " << remote;
  // The mechanism in motion and, with Debian's Chart.js installed, the interactive plots.
  EXPECT_NE(html.find("id=\"mech-data\""), std::string::npos);
  if (fs::exists("/usr/share/javascript/chart.js/chart.min.js"))
    EXPECT_NE(html.find("id=\"plot-rod_forces\""), std::string::npos);
  // The override is shown where it came from, with the value used.
  EXPECT_NE(html.find("crank.offset_deg=60"), std::string::npos);
  EXPECT_NE(html.find("--set #2"), std::string::npos);
  EXPECT_NE(html.find("N_front_1"), std::string::npos);
  EXPECT_TRUE(fs::exists(out.path() / "summary.json"));
  EXPECT_NE(r.out.find("report.html"), std::string::npos);
}

}  // namespace
}  // namespace rollerdyn
