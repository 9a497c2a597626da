// The report's checks table renders each check of summary.json's sizing.checks with the limit it
// is held against (with the sense of the comparison) and its method; a check written without them
// (older summaries) shows empty cells, not "n/a". The JSON here is written by hand.
#include <gtest/gtest.h>

#include <string>

#include "report/SizingSection.h"

using namespace rollerdyn;
using nlohmann::json;

namespace {

std::string rowOf(const std::string& html, const std::string& start) {
  const std::size_t tr = html.find("<tr><td>" + start);
  if (tr == std::string::npos) return "";
  return html.substr(tr, html.find("</tr>", tr) - tr);
}

json summaryWith(const json& checks) {
  return {{"motion", "turning"},
          {"sizing", {{"window", {{"t_begin", 8.0}, {"t_end", 10.0}, {"revolutions", 3.0}}}, {"checks", checks}}}};
}

}  // namespace

TEST(SizingSectionChecks, EachCheckShowsItsLimitAndMethod) {
  const json checks = json::array(
      {{{"check", "motor_breakdown"}, {"what", "peak over breakdown"}, {"value", 0.5}, {"verdict", "pass"},
        {"window", "steady window"}, {"reason", "r"}, {"limit", 0.9025}, {"passes_when", "<"},
        {"method", "IEC 60034-1 zone A"}},
       {{"check", "old"}, {"what", "a check without limit"}, {"value", 0.5}, {"verdict", "pass"},
        {"window", "steady window"}, {"reason", "r"}}});
  const std::string html = sizingSectionHtml(summaryWith(checks));
  const std::string row = rowOf(html, "peak over breakdown");
  ASSERT_FALSE(row.empty()) << html;
  EXPECT_NE(row.find("&lt; 0.9025"), std::string::npos) << row;
  EXPECT_NE(row.find("IEC 60034-1 zone A"), std::string::npos) << row;
  const std::string old = rowOf(html, "a check without limit");
  ASSERT_FALSE(old.empty());
  EXPECT_EQ(old.find("n/a"), std::string::npos) << old;
}
