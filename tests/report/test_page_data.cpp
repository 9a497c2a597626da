// Data and scripts embedded in the report page: rounding to significant digits, and escaping so
// that nothing inside a block can end it early.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "report/PageData.h"

namespace rollerdyn {
namespace {

TEST(PageData, RoundsToSignificantDigits) {
  EXPECT_DOUBLE_EQ(roundSignificant(0.123456789, 6), 0.123457);
  EXPECT_DOUBLE_EQ(roundSignificant(-98765.4321, 3), -98800.0);
  EXPECT_DOUBLE_EQ(roundSignificant(1.6e-9, 1), 2e-9);
  EXPECT_EQ(roundSignificant(0.0, 6), 0.0);
  EXPECT_TRUE(std::isnan(roundSignificant(std::numeric_limits<double>::quiet_NaN(), 6)));
  EXPECT_EQ(roundedArray({0.123456789, 2.0}, 6).dump(), "[0.123457,2.0]");
  EXPECT_EQ(roundedArray({std::numeric_limits<double>::quiet_NaN()}, 6).dump(), "[null]");
}

TEST(PageData, JsonBlockCannotBeClosedByItsContent) {
  const nlohmann::json j = {{"label", "</script><b>"}};
  const std::string block = jsonScriptBlock("d", j);
  EXPECT_EQ(block, "<script type=\"application/json\" id=\"d\">{\"label\":\"<\\/script><b>\"}</script>\n");
  // "<\/" is the same JSON string.
  const std::string body = block.substr(block.find('>') + 1, block.rfind("</script>") - block.find('>') - 1);
  EXPECT_EQ(nlohmann::json::parse(body)["label"], "</script><b>");
}

TEST(PageData, ScriptBlockEscapesClosingTagsInAnyCase) {
  EXPECT_EQ(inlineScriptBlock("var a = '</script>'; var b = '</SCRIPT >'; var c = '</scr'; x < /y/;"),
            "<script>\nvar a = '<\\/script>'; var b = '<\\/SCRIPT >'; var c = '</scr'; x < /y/;\n</script>\n");
}

}  // namespace
}  // namespace rollerdyn
