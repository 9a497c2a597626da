// The report's joint table renders summary.json's joint lives: its header's unit and its cells
// agree with the JSON (the trial read "n/a" under a header promising "h, or rev" while the JSON had
// the rod end's L10 in revolutions), n/a comes with the JSON's reason, and the main bearings carry
// the JSON's label. The JSON here is written by hand.
#include <gtest/gtest.h>

#include <string>

#include "report/SizingSection.h"

using namespace rollerdyn;
using nlohmann::json;

namespace {

json jointRow(int cart, const json& hours, const std::string& basis, const json& reason) {
  return {{"cart", cart > 0 ? json(cart) : json(nullptr)}, {"mean", 1000.0}, {"amplitude", 500.0}, {"peak", 1500.0},
          {"equivalent_load", 1200.0}, {"rating", 60000.0}, {"speed_basis", "w"}, {"L10_revolutions", 1.25e11},
          {"L10_hours", hours}, {"life_basis", basis}, {"life_reason", reason}};
}

json summary(const json& rod_hours, const json& rod_reason) {
  const json rod = jointRow(2, rod_hours, "oscillates through 2γ = 28.96°", rod_reason);
  const json main = jointRow(0, 3.5e5, "one bearing carrying the whole resultant", nullptr);
  return {{"motion", "turning"},
          {"sizing",
           {{"window", {{"t_begin", 8.0}, {"t_end", 10.0}, {"revolutions", 3.0}}},
            {"joints",
             {{"rod_end", {{"what", "rod end (the rod's small end on the cart's pin B)"}, {"worst", rod}, {"per_cart", {rod}}}},
              {"main_bearing",
               {{"what", "main bearings, resultant on the crankshaft (all bearings together; per-bearing loads need "
                         "the bearing positions)"},
                {"worst", main},
                {"per_cart", {main}}}}}}}}};
}

std::string rowOf(const std::string& html, const std::string& start) {
  const std::size_t tr = html.find("<tr><td>" + start);
  if (tr == std::string::npos) return "";
  return html.substr(tr, html.find("</tr>", tr) - tr);
}

}  // namespace

TEST(SizingSectionJoints, LifeColumnInHoursShowsTheJsonHours) {
  const std::string html = sizingSectionHtml(summary(24213.0, nullptr));
  EXPECT_NE(html.find("<th>L10 [h]</th>"), std::string::npos) << html;
  const std::string rod = rowOf(html, "rod end");
  ASSERT_FALSE(rod.empty()) << html;
  EXPECT_NE(rod.find("<td class=\"n\">2.42e+04</td>"), std::string::npos) << rod;
  EXPECT_NE(html.find("oscillates through 2γ = 28.96°"), std::string::npos) << html;
}

TEST(SizingSectionJoints, NotApplicableLifeShowsTheJsonReason) {
  const std::string html =
      sizingSectionHtml(summary(nullptr, "the drive does not turn (motion: stalled): no running to wear the bearing"));
  const std::string rod = rowOf(html, "rod end");
  ASSERT_FALSE(rod.empty()) << html;
  EXPECT_NE(rod.find("<td class=\"n\">n/a</td>"), std::string::npos) << rod;
  EXPECT_NE(html.find("L10 n/a: the drive does not turn (motion: stalled): no running to wear the bearing"),
            std::string::npos)
      << html;
}

TEST(SizingSectionJoints, MainBearingsLabelledAsTheResultant) {
  const std::string html = sizingSectionHtml(summary(24213.0, nullptr));
  EXPECT_FALSE(rowOf(html, "main bearings, resultant on the crankshaft (all bearings together; per-bearing loads need "
                           "the bearing positions)")
                   .empty())
      << html;
}
