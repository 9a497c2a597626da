// The report page in a real browser: headless Chromium (Debian's chromium, installed by
// scripts/setup.sh) loads a page written by `rollerdyn report` from a file:// URL and runs its
// scripts under a virtual time budget; --dump-dom then shows the attributes the page's scripts
// set. Checked: the animation plays (frame, time and a checksum of the mechanism canvas's pixels
// move on from the first frame drawn, in each of two page loads), the interactive charts were made and painted, every
// embedded figure decoded, and no script error was raised. Without Chart.js on the page (the
// fallback), the animation still plays and no script fails. Skipped, with the reason, when
// chromium is not installed.
#include <gtest/gtest.h>

#include <cstdlib>
#include <map>
#include <sstream>
#include <regex>
#include <string>

#include "cli/CliTestSupport.h"
#include "report/HtmlReport.h"
#include "report/OutputFolder.h"
#include "scene/SceneParser.h"

namespace rollerdyn {
namespace {

namespace fs = std::filesystem;
using test::model;
using test::runRollerdyn;
using test::slurp;
using test::TempDir;

std::string findChromium() {
  const char* path = std::getenv("PATH");
  std::string dirs = path ? path : "/usr/bin:/bin";
  for (size_t start = 0; start <= dirs.size();) {
    const size_t colon = dirs.find(':', start);
    const std::string dir = dirs.substr(start, colon == std::string::npos ? std::string::npos : colon - start);
    for (const char* name : {"chromium", "chromium-browser"}) {
      const fs::path p = fs::path(dir) / name;
      if (!dir.empty() && ::access(p.c_str(), X_OK) == 0) return p.string();
    }
    if (colon == std::string::npos) break;
    start = colon + 1;
  }
  return "";
}

// The DOM after `budget_ms` of virtual time, page opened with #selftest (the animation then also
// records a checksum of its canvas). Empty if chromium failed.
std::string dumpDom(const std::string& chromium, const fs::path& page, int budget_ms, const TempDir& work) {
  const fs::path dom = work.path() / ("dom-" + std::to_string(budget_ms) + ".html");
  const std::string cmd = "timeout 60 '" + chromium +
                          "' --headless --no-sandbox --disable-gpu --no-first-run --disable-background-networking "
                          "--disable-component-update --disable-sync --user-data-dir='" +
                          (work.path() / "profile").string() + "' --virtual-time-budget=" + std::to_string(budget_ms) +
                          " --window-size=1200,1600 --dump-dom 'file://" + page.string() + "#selftest' > '" +
                          dom.string() + "' 2>/dev/null";
  if (std::system(cmd.c_str()) != 0) return "";
  return slurp(dom);
}

// Attributes of the first tag that contains `marker`, e.g. marker "id=\"mechanism\"".
std::map<std::string, std::string> attributesOf(const std::string& dom, const std::string& marker) {
  std::map<std::string, std::string> out;
  const size_t at = dom.find(marker);
  if (at == std::string::npos) return out;
  const size_t open = dom.rfind('<', at), close = dom.find('>', at);
  const std::string tag = dom.substr(open, close - open);
  static const std::regex attr("([a-z-]+)=\"([^\"]*)\"");
  for (auto it = std::sregex_iterator(tag.begin(), tag.end(), attr); it != std::sregex_iterator(); ++it)
    out[(*it)[1]] = (*it)[2];
  return out;
}

std::string htmlTag(const std::string& dom) { return dom.substr(0, dom.find('>', dom.find("<html")) + 1); }

class ReportInBrowser : public ::testing::Test {
 protected:
  void SetUp() override {
    chromium_ = findChromium();
    if (chromium_.empty()) GTEST_SKIP() << "chromium not installed (Debian package chromium; scripts/setup.sh installs it)";
  }
  std::string chromium_;
};

TEST_F(ReportInBrowser, AnimationPlaysAndFiguresRender) {
  TempDir out("browser");
  const auto r = runRollerdyn({"report", model("balanced-4cart.yaml"), "--set", "simulation.t_end=3", "--out", out.str()}, 300);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  const fs::path page = out.path() / "report.html";
  const std::string early = dumpDom(chromium_, page, 600, out), late = dumpDom(chromium_, page, 1800, out);
  ASSERT_FALSE(early.empty()) << "chromium produced no DOM";
  ASSERT_FALSE(late.empty()) << "chromium produced no DOM";

  EXPECT_EQ(htmlTag(early).find("data-script-errors"), std::string::npos) << htmlTag(early);
  EXPECT_EQ(htmlTag(late).find("data-script-errors"), std::string::npos) << htmlTag(late);

  // Chromium paces requestAnimationFrame by the wall clock, not the virtual one (measured: t =
  // 0.23 ... 0.29 s at budgets of 0.6 and 1.8 s, and on a loaded machine a load could end on its
  // first frame). Under #selftest the page therefore schedules its frames by timers on a
  // synthetic 40 ms clock, which follow the virtual time, so each load shows a fixed number of
  // frames; the page records the first frame it drew beside the current one.
  for (const std::string* dom : {&early, &late}) {
    const auto m = attributesOf(*dom, "id=\"mechanism\"");
    ASSERT_TRUE(m.count("data-t") && m.count("data-t-first") && m.count("data-pixels") && m.count("data-pixels-first"));
    EXPECT_GT(std::stod(m.at("data-t")), std::stod(m.at("data-t-first"))) << "the animation did not advance";
    EXPECT_NE(m.at("data-frame"), m.at("data-frame-first"));
    EXPECT_NE(m.at("data-pixels"), m.at("data-pixels-first")) << "the mechanism canvas did not change";
  }

  const auto plots = attributesOf(late, "id=\"time-plots\"");
  EXPECT_EQ(plots.count("data-charts") ? plots.at("data-charts") : "", "4");
  EXPECT_EQ(plots.count("data-painted") ? plots.at("data-painted") : "", "4") << "charts made but not drawn";
  const auto body = attributesOf(late, "<body");
  ASSERT_TRUE(body.count("data-figures")) << "figure counter did not run";
  const std::string figs = body.at("data-figures");
  const std::string loaded = figs.substr(0, figs.find('/')), total = figs.substr(figs.find('/') + 1);
  EXPECT_EQ(loaded, total) << "figures decoded / embedded: " << figs;
  EXPECT_GE(std::stoi(total), 10);
}

// Every verdict cell shows its verdict's colour in every row, as the browser paints it: green pass,
// red FAIL, grey not applicable (a striped-row rule `tr:nth-child(even) td` once outranked the
// verdict classes, so a FAIL in an even row was not red). A coupling rated far below its load
// fails, the other checks pass or do not apply, so the table has more than one colour to show.
TEST_F(ReportInBrowser, EveryVerdictCellShowsItsVerdictsColour) {
  TempDir out("browser-verdicts");
  const auto r = runRollerdyn({"report", model("balanced-4cart.yaml"), "--set", "sizing.coupling_rated_torque=10",
                               "--out", out.str()}, 300);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  const std::string dom = dumpDom(chromium_, out.path() / "report.html", 1000, out);
  ASSERT_FALSE(dom.empty()) << "chromium produced no DOM";
  const auto body = attributesOf(dom, "<body");
  ASSERT_TRUE(body.count("data-verdict-cells")) << "verdict colour recorder did not run";
  // The colours of the stylesheet's .ok, .bad and .na (#e3f4e3, #fde2e2, #ececec).
  const std::map<std::string, std::string> colour = {
      {"ok", "rgb(227, 244, 227)"}, {"bad", "rgb(253, 226, 226)"}, {"na", "rgb(236, 236, 236)"}};
  std::map<std::string, int> seen;
  std::stringstream cells(body.at("data-verdict-cells"));
  for (std::string cell; std::getline(cells, cell, ';');) {
    const std::string cls = cell.substr(0, cell.find(' '));
    const size_t open = cell.find("rgb"), close = cell.find(')', open);
    ASSERT_NE(open, std::string::npos) << cell;
    const std::string painted = cell.substr(open, close - open + 1), text = cell.substr(close + 2);
    if (colour.count(cls)) {
      EXPECT_EQ(painted, colour.at(cls)) << cell;
      ++seen[cls];
    }
    if (text == "FAIL") {
      EXPECT_EQ(cls, "bad") << cell;
    }
    if (text == "pass") {
      EXPECT_EQ(cls, "ok") << cell;
    }
  }
  EXPECT_GE(seen["bad"], 1) << body.at("data-verdict-cells");
  EXPECT_GE(seen["ok"], 1) << body.at("data-verdict-cells");
}

// The page written without Chart.js: the note instead of the charts, the animation unaffected.
TEST_F(ReportInBrowser, WithoutChartJsNoScriptFails) {
  TempDir out("browser-nochart");
  const auto r = runRollerdyn({"simulate", model("recuperative-2cart.yaml"), "--set", "simulation.t_end=2", "--out",
                               out.str()}, 300);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const OutputFolder folder = readOutputFolder(out.str());
  const Scene scene = parseSceneFile(model("recuperative-2cart.yaml"));
  ReportContent c;
  c.scene_name = scene.name;
  c.summary = folder.summary;
  c.animation = mechanismFrames(scene, folder.timeseries, folder.reactions);
  c.time_plots = mainTimePlots(folder.timeseries, folder.reactions);
  c.chartjs_path = (out.path() / "no-such-chart.js").string();
  const fs::path page = out.path() / "report.html";
  { std::ofstream(page) << renderReportHtml(c); }
  const std::string early = dumpDom(chromium_, page, 500, out), late = dumpDom(chromium_, page, 1500, out);
  ASSERT_FALSE(late.empty());
  EXPECT_EQ(htmlTag(late).find("data-script-errors"), std::string::npos) << htmlTag(late);
  EXPECT_NE(late.find("Interactive time plots left out"), std::string::npos);
  for (const std::string* dom : {&early, &late}) {  // moved within each load (see above)
    const auto m = attributesOf(*dom, "id=\"mechanism\"");
    ASSERT_TRUE(m.count("data-pixels") && m.count("data-pixels-first"));
    EXPECT_NE(m.at("data-pixels"), m.at("data-pixels-first"));
  }
}

}  // namespace
}  // namespace rollerdyn
