// The HTML page: self-contained (figures embedded, scripts inline, nothing fetched), everything
// from the scene or the run escaped, the incomplete-run banner, the tables it promises, and the
// mechanism section with the interactive plots or, without Chart.js, a note.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "report/HtmlReport.h"
#include "scene/SceneParser.h"

namespace rollerdyn {
namespace {

namespace fs = std::filesystem;

TEST(HtmlReport, Base64KnownVectors) {  // RFC 4648, section 10
  EXPECT_EQ(base64Encode(""), "");
  EXPECT_EQ(base64Encode("f"), "Zg==");
  EXPECT_EQ(base64Encode("fo"), "Zm8=");
  EXPECT_EQ(base64Encode("foo"), "Zm9v");
  EXPECT_EQ(base64Encode("foob"), "Zm9vYg==");
  EXPECT_EQ(base64Encode("fooba"), "Zm9vYmE=");
  EXPECT_EQ(base64Encode("foobar"), "Zm9vYmFy");
  EXPECT_EQ(base64Encode(std::string("\xff\x00\x80", 3)), "/wCA");
}

TEST(HtmlReport, Escapes) { EXPECT_EQ(htmlEscape("<a href=\"x\">&'"), "&lt;a href=&quot;x&quot;&gt;&amp;&#39;"); }

// Nothing loaded from elsewhere: no src/href to anything, no style import, every script inline.
void expectSelfContained(const std::string& html) {
  for (const char* remote : {"src=\"http", "href=", "<link", "@import", "url(", "<script src", "<iframe"})
    EXPECT_EQ(html.find(remote), std::string::npos) << remote;
  const std::string plain = "<script>", data = "<script type=\"application/json\" ";
  for (size_t at = 0; (at = html.find("<script", at)) != std::string::npos; ++at)
    EXPECT_TRUE(html.compare(at, plain.size(), plain) == 0 || html.compare(at, data.size(), data) == 0)
        << html.substr(at, 60);
}

ReportContent content(const fs::path& png) {
  ReportContent c;
  c.scene_name = "balanced-4cart";
  c.scene_source = "Loveikin, Pochka, Romasevych (2018) <script>alert(1)</script>";
  c.scene_path = "model/balanced-4cart.yaml";
  c.overrides = {"crank.offset_deg=60"};
  c.effects = {"kloss_motor", "elastic_coupling"};
  c.parameters = {{"crank.offset_deg", "60", "deg", "angle between consecutive cranks", "--set #1"}};
  c.derived = {{"motor-side inertia J_n1", "73.6", "kg·m²", "reduced", "derived"}};
  c.summary = {{"model", "multibody"},
               {"integrator", "RungeKuttaMerson"},
               {"status", "interrupted at t = 1.5 s"},
               {"complete", false},
               {"omega_crank", {{"mean", 10.5}, {"min", 10.1}, {"max", 10.9}}},
               {"delta", 0.0762},
               {"reactions", {{"N_front_1", {{"min", -1200.5}, {"max", 3400.25}, {"mean", 1.0}, {"abs_max", 3400.25}}},
                              {"bearing_x", {{"min", -1.0}, {"max", 1.0}, {"mean", 0.0}, {"abs_max", 1.0}}}}}};
  c.reaction_columns = {"t", "N_front_1", "bearing_x"};
  c.figures = {{"crank_speed_vs_angle", "Crank speed.", png.string(), ""}};
  c.notes = {"twist phase portraits left out: the coupling does not twist (rigid coupling)"};
  c.command = "rollerdyn report model/balanced-4cart.yaml --set crank.offset_deg=60";
  return c;
}

TEST(HtmlReport, PageIsSelfContainedAndComplete) {
  const fs::path png = fs::temp_directory_path() / ("rollerdyn-fig-" + std::to_string(::getpid()) + ".png");
  { std::ofstream(png, std::ios::binary) << "\x89PNG\r\n\x1a\nfake"; }
  const std::string html = renderReportHtml(content(png));
  fs::remove(png);

  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(html.find("<meta charset=\"utf-8\">"), std::string::npos);
  EXPECT_NE(html.find("src=\"data:image/png;base64," + base64Encode("\x89PNG\r\n\x1a\nfake") + "\""), std::string::npos);
  expectSelfContained(html);
  EXPECT_NE(html.find("Loveikin, Pochka, Romasevych (2018) &lt;script&gt;alert(1)&lt;/script&gt;"), std::string::npos);
  // Incomplete run: a red banner with the status.
  EXPECT_NE(html.find("class=\"status bad\">Run INCOMPLETE: interrupted at t = 1.5 s"), std::string::npos);
  // Reactions: in reactions.csv order, min and max shown.
  const size_t n = html.find("<code>N_front_1</code>"), b = html.find("<code>bearing_x</code>");
  ASSERT_NE(n, std::string::npos);
  ASSERT_NE(b, std::string::npos);
  EXPECT_LT(n, b);
  EXPECT_NE(html.find("-1200.5"), std::string::npos);
  EXPECT_NE(html.find("3400.25"), std::string::npos);
  EXPECT_NE(html.find("guide reaction, front guide roller, cart 1"), std::string::npos);
  // Effects in words with the key that sets them, not the identifiers of summary.json.
  EXPECT_NE(html.find("<span class=\"chip\">torsional spring of the coupling (coupling.stiffness)</span>"), std::string::npos);
  EXPECT_EQ(html.find(">elastic_coupling<"), std::string::npos);
  EXPECT_NE(html.find("<code>crank.offset_deg</code>"), std::string::npos);
  EXPECT_NE(html.find("--set #1"), std::string::npos);
  EXPECT_NE(html.find("rigid coupling"), std::string::npos);
  EXPECT_NE(html.find("0.0762"), std::string::npos);
}

TEST(HtmlReport, CompleteRunHasAGreenBanner) {
  ReportContent c = content("");
  c.figures.clear();
  c.summary["complete"] = true;
  c.summary["status"] = "completed";
  const std::string html = renderReportHtml(c);
  EXPECT_NE(html.find("class=\"status ok\">Run complete: completed"), std::string::npos);
}

TEST(HtmlReport, WarningsOfTheSummaryAreShown) {
  ReportContent c = content("");
  c.figures.clear();
  c.summary["warnings"] = {"crank speed near resonance <p0>"};
  const std::string html = renderReportHtml(c);
  EXPECT_NE(html.find("<li>crank speed near resonance &lt;p0&gt;</li>"), std::string::npos);
}

// A run of two rows and two carts, enough for the mechanism section and the time plots.
void addMotion(ReportContent& c) {
  Table ts, rx;
  ts.columns = {"t", "phi_crank", "omega_crank", "coupling_torque", "x_cart_1", "x_cart_2"};
  ts.rows = {{0.0, 0.0, 10.0, 5.0, 1.0, -0.6}, {0.1, 1.0, 10.5, 6.0, 0.9, -0.7}};
  const Scene scene = parseSceneFile(std::string(ROLLERDYN_SOURCE_DIR) + "/model/recuperative-2cart.yaml");
  c.animation = mechanismFrames(scene, ts, rx);
  c.time_plots = mainTimePlots(ts, rx);
}

TEST(HtmlReport, MechanismSectionWithInteractivePlots) {
  ReportContent c = content("");
  c.figures.clear();
  addMotion(c);
  const fs::path lib = fs::temp_directory_path() / ("rollerdyn-chart-" + std::to_string(::getpid()) + ".js");
  { std::ofstream(lib) << "window.Chart = function () {};"; }
  c.chartjs_path = lib.string();
  const std::string html = renderReportHtml(c);
  fs::remove(lib);
  expectSelfContained(html);
  const size_t motion = html.find("<h2>Mechanism in motion</h2>"), scene = html.find("<h2>Scene</h2>");
  ASSERT_NE(motion, std::string::npos);
  EXPECT_LT(motion, scene) << "the animation comes first";
  for (const char* part : {"id=\"mech-canvas\"", "id=\"mech-data\"", "window.Chart = function () {};",
                           "id=\"plot-speed\"", "id=\"plot-torque\"", "data-script-errors", "data-figures"})
    EXPECT_NE(html.find(part), std::string::npos) << part;
}

TEST(HtmlReport, WithoutChartJsTheAnimationStaysAndANoteExplains) {
  ReportContent c = content("");
  c.figures.clear();
  addMotion(c);
  c.chartjs_path = "/nonexistent/chart.min.js";
  const std::string html = renderReportHtml(c);
  EXPECT_NE(html.find("id=\"mech-canvas\""), std::string::npos);
  EXPECT_NE(html.find("Interactive time plots left out: Chart.js (Debian package libjs-chart.js"), std::string::npos);
  EXPECT_EQ(html.find("id=\"plot-speed\""), std::string::npos);
}

TEST(HtmlReport, NoRunDataNoMechanismSection) {
  ReportContent c = content("");
  c.figures.clear();
  EXPECT_EQ(renderReportHtml(c).find("Mechanism in motion"), std::string::npos);
}

TEST(HtmlReport, MissingFigureFileIsAnError) {
  EXPECT_THROW(renderReportHtml(content("/nonexistent/figure.png")), std::runtime_error);
}

}  // namespace
}  // namespace rollerdyn
