// The HTML page: self-contained (figures embedded, nothing fetched), everything from the scene
// or the run escaped, the incomplete-run banner, and the tables it promises.
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
  for (const char* remote : {"http://", "https://", "<script", "<link", "@import", "url("})
    EXPECT_EQ(html.find(remote), std::string::npos) << remote;
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
  EXPECT_NE(html.find("<span class=\"chip\">elastic_coupling</span>"), std::string::npos);
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

TEST(HtmlReport, MissingFigureFileIsAnError) {
  EXPECT_THROW(renderReportHtml(content("/nonexistent/figure.png")), std::runtime_error);
}

}  // namespace
}  // namespace rollerdyn
