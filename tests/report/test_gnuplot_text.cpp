// escapeUnderscores (report/Gnuplot.h): "_" would start a subscript in gnuplot's enhanced text.
#include <gtest/gtest.h>

#include "report/Gnuplot.h"

namespace rollerdyn {
namespace {

TEST(GnuplotText, EscapesEveryUnderscoreAndNothingElse) {
  EXPECT_EQ(escapeUnderscores("crank.offset_deg [deg]"), "crank.offset\\_deg [deg]");
  EXPECT_EQ(escapeUnderscores("__a_"), "\\_\\_a\\_");
  EXPECT_EQ(escapeUnderscores("eps [rad/s^2] {x} @ & ~"), "eps [rad/s^2] {x} @ & ~");
  EXPECT_EQ(escapeUnderscores(""), "");
}

}  // namespace
}  // namespace rollerdyn
