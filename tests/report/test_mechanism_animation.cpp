// The mechanism animation's frame data against the run's own time series: the frames embedded
// in a report page written by `rollerdyn report` are read back from the page and compared, row
// by row, with timeseries.csv and reactions.csv of the same folder and with the slider-crank
// closed form computed here from the scene's r, l and Δφ:
//   θ_j = φ_2 + (j-1)·Δφ,  A_j = r·(cos θ_j, sin θ_j),  x_B = r·cos θ_j + σ_j·sqrt(l² - r²·sin² θ_j)
// (Loveikin, Pochka, Romasevych (2018) eq. (31), (40)). Scenes with all carts on one side and
// with carts on opposite sides, so each cart is checked to be on its own side.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <functional>
#include <string>

#include "cli/CliTestSupport.h"
#include "report/MechanismAnimation.h"
#include "report/OutputFolder.h"
#include "scene/SceneParser.h"

namespace rollerdyn {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test::model;
using test::runRollerdyn;
using test::slurp;
using test::TempDir;

// The JSON of <script type="application/json" id="ID"> in `html` ("<\/" read back as "</").
json embeddedJson(const std::string& html, const std::string& id) {
  const std::string open = "<script type=\"application/json\" id=\"" + id + "\">";
  const size_t a = html.find(open);
  if (a == std::string::npos) return nullptr;
  const size_t b = html.find("</script>", a);
  std::string text = html.substr(a + open.size(), b - a - open.size());
  for (size_t at = 0; (at = text.find("<\\/", at)) != std::string::npos;) text.replace(at, 3, "</");
  return json::parse(text);
}

struct PageCase {
  const char* scene;
  std::vector<int> sides;  // σ_j as the scene file states them (carts.sides)
};

void PrintTo(const PageCase& c, std::ostream* os) { *os << c.scene; }

class MechanismFramesOfAReport : public ::testing::TestWithParam<PageCase> {};

TEST_P(MechanismFramesOfAReport, MatchTimeSeriesAndClosedForm) {
  const PageCase& pc = GetParam();
  TempDir out("mech");
  const auto r = runRollerdyn({"report", model(pc.scene), "--set", "simulation.t_end=1.5", "--out", out.str()}, 300);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  const json page = embeddedJson(slurp(out.path() / "report.html"), "mech-data");
  ASSERT_TRUE(page.is_object()) << "no frame data in the page";
  const OutputFolder folder = readOutputFolder(out.str());
  const Scene scene = parseSceneFile(model(pc.scene));
  const double rr = scene.crank.radius, l = scene.rods.length, dphi = scene.crank.offset;

  const json& g = page["geometry"];
  EXPECT_DOUBLE_EQ(g["r"].get<double>(), rr);
  EXPECT_DOUBLE_EQ(g["l"].get<double>(), l);
  EXPECT_DOUBLE_EQ(g["offset"].get<double>(), dphi);
  EXPECT_EQ(g["sides"].get<std::vector<int>>(), pc.sides);
  ASSERT_EQ(page["carts"].size(), pc.sides.size());

  const Table& ts = folder.timeseries;
  const Table& rx = folder.reactions;
  const int it = ts.index("t"), ip = ts.index("phi_crank");
  const auto frame_t = page["t"].get<std::vector<double>>();
  ASSERT_GE(frame_t.size(), 100u);
  EXPECT_EQ(frame_t.size(), ts.rows.size()) << "short run: every row is a frame";
  ASSERT_TRUE(page["has_forces"].get<bool>());
  double worst_hinge = 0, worst_rod = 0;
  for (size_t k = 0; k < frame_t.size(); ++k) {
    const auto& row = ts.rows[k];
    ASSERT_NEAR(frame_t[k], row[it], 1e-6 * std::max(1.0, row[it])) << "frame " << k;
    const double phi = page["phi"][k].get<double>();
    ASSERT_NEAR(phi, row[ip], 1e-5 * std::max(1.0, std::abs(row[ip])));
    for (size_t j = 0; j < pc.sides.size(); ++j) {
      const json& c = page["carts"][j];
      const double theta = row[ip] + double(j) * dphi;
      const double pin_x = c["pin_x"][k].get<double>(), pin_y = c["pin_y"][k].get<double>();
      const double hinge = c["hinge_x"][k].get<double>();
      EXPECT_NEAR(pin_x, rr * std::cos(theta), 1e-5);
      EXPECT_NEAR(pin_y, rr * std::sin(theta), 1e-5);
      const double s = std::sin(theta);
      const double x_B = rr * std::cos(theta) + pc.sides[j] * std::sqrt(l * l - rr * rr * s * s);
      worst_hinge = std::max(worst_hinge, std::abs(hinge - x_B));
      worst_rod = std::max(worst_rod, std::abs(std::hypot(pin_x - hinge, pin_y) - l));
      EXPECT_GT(hinge * pc.sides[j], 0.0) << "cart " << j + 1 << " on the wrong side at frame " << k;
      EXPECT_NEAR(hinge, row[ts.index("x_cart_" + std::to_string(j + 1))], 1e-5);
      const std::string n = std::to_string(j + 1);
      for (const char* q : {"N_front_", "N_rear_", "F_rod_"}) {
        const double want = rx.rows[k][rx.index(q + n)];
        EXPECT_NEAR(c[std::string(q).substr(0, std::string(q).size() - 1)][k].get<double>(), want,
                    1e-4 * std::max(1.0, std::abs(want)))
            << q << n << " frame " << k;
      }
    }
  }
  // Hinges on the closed form and rods of length l, to the multibody model's constraint accuracy.
  EXPECT_LT(worst_hinge, 1e-4) << "largest |x_B - closed form| [m]";
  EXPECT_LT(worst_rod, 1e-4) << "largest | |AB| - l | [m]";
  std::cout << pc.scene << ": largest |x_B - closed form| = " << worst_hinge << " m, largest rod length error = "
            << worst_rod << " m\n";
}

INSTANTIATE_TEST_SUITE_P(Scenes, MechanismFramesOfAReport,
                         ::testing::Values(PageCase{"balanced-4cart.yaml", {1, 1, 1, 1}},
                                           PageCase{"recuperative-2cart.yaml", {1, -1}}),
                         [](const ::testing::TestParamInfo<PageCase>& info) {
                           return info.index == 0 ? std::string("AllOnOneSide") : std::string("OppositeSides");
                         });

Table table(std::vector<std::string> columns, size_t rows, const std::function<double(size_t, size_t)>& value) {
  Table t;
  t.columns = std::move(columns);
  for (size_t i = 0; i < rows; ++i) {
    std::vector<double> row;
    for (size_t c = 0; c < t.columns.size(); ++c) row.push_back(value(i, c));
    t.rows.push_back(row);
  }
  return t;
}

TEST(MechanismFrames, StrideKeepsAtMostMaxFramesEvenlySpaced) {
  const Scene scene = parseSceneFile(model("recuperative-2cart.yaml"));
  const Table ts = table({"t", "phi_crank", "x_cart_1", "x_cart_2"}, 10, [](size_t i, size_t c) { return i + 0.1 * c; });
  const MechanismFrames f = mechanismFrames(scene, ts, Table{}, 4);
  EXPECT_EQ(f.rows, (std::vector<size_t>{0, 3, 6, 9}));
  EXPECT_EQ(f.t, (std::vector<double>{0, 3, 6, 9}));
  EXPECT_FALSE(f.has_forces) << "no reactions: no arrows";
  ASSERT_EQ(f.carts.size(), 2u);
  EXPECT_DOUBLE_EQ(f.carts[1].hinge_x[2], 6.3);
  EXPECT_TRUE(f.carts[0].N_front.empty());
}

TEST(MechanismFrames, ReactionsOnOtherRowsAreNotShown) {
  const Scene scene = parseSceneFile(model("recuperative-2cart.yaml"));
  const Table ts = table({"t", "phi_crank", "x_cart_1", "x_cart_2"}, 5, [](size_t i, size_t) { return double(i); });
  const std::vector<std::string> rc = {"t", "N_front_1", "N_rear_1", "F_rod_1", "N_front_2", "N_rear_2", "F_rod_2"};
  const Table same = table(rc, 5, [](size_t i, size_t c) { return c == 0 ? double(i) : -100.0 * c; });
  const MechanismFrames f = mechanismFrames(scene, ts, same);
  EXPECT_TRUE(f.has_forces);
  EXPECT_DOUBLE_EQ(f.N_abs_max, 500.0);     // |N_rear_2| = 100·5
  EXPECT_DOUBLE_EQ(f.F_rod_abs_max, 600.0);  // |F_rod_2| = 100·6
  EXPECT_FALSE(mechanismFrames(scene, ts, table(rc, 4, [](size_t i, size_t) { return double(i); })).has_forces);
  EXPECT_FALSE(mechanismFrames(scene, ts, table(rc, 5, [](size_t i, size_t) { return i + 0.5; })).has_forces)
      << "rows at other times";
}

TEST(MechanismFrames, MissingColumnsOrCartsAreErrors) {
  const Scene scene = parseSceneFile(model("recuperative-2cart.yaml"));
  EXPECT_THROW(mechanismFrames(scene, table({"t", "x_cart_1", "x_cart_2"}, 3, [](size_t, size_t) { return 0.0; }), Table{}),
               std::invalid_argument);
  EXPECT_THROW(mechanismFrames(scene, table({"t", "phi_crank", "x_cart_1"}, 3, [](size_t, size_t) { return 0.0; }), Table{}),
               std::invalid_argument);
}

TEST(MechanismFrames, SectionHasControlsDataAndScript) {
  const Scene scene = parseSceneFile(model("recuperative-2cart.yaml"));
  const Table ts = table({"t", "phi_crank", "x_cart_1", "x_cart_2"}, 3, [](size_t i, size_t) { return double(i); });
  const std::string h = mechanismAnimationHtml(mechanismFrames(scene, ts, Table{}));
  for (const char* part : {"id=\"mechanism\"", "id=\"mech-play\"", "id=\"mech-slider\"", "max=\"2\"", "id=\"mech-canvas\"",
                           "id=\"mech-data\"", "rollerdyn-time", "rollerdyn-seek", "requestAnimationFrame"})
    EXPECT_NE(h.find(part), std::string::npos) << part;
  EXPECT_EQ(mechanismAnimationHtml(MechanismFrames{}), "");
}

}  // namespace
}  // namespace rollerdyn
