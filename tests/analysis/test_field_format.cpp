// io/FieldFormat.h: numbers and text as CSV fields and JSON values. Expected strings written out by
// hand from the rules in the header (12 significant digits, RFC 4180 quoting, null for non-finite).
#include <gtest/gtest.h>

#include <cmath>

#include "io/FieldFormat.h"

namespace rollerdyn {
namespace {

TEST(FieldFormat, CsvNumberTwelveDigitsAndNanForNonFinite) {
  EXPECT_EQ(csvNumber(0.1), "0.1");
  EXPECT_EQ(csvNumber(1.0 / 3.0), "0.333333333333");
  EXPECT_EQ(csvNumber(-2e5), "-200000");
  EXPECT_EQ(csvNumber(1234567890123.0), "1.23456789012e+12");
  EXPECT_EQ(csvNumber(3.25e-7), "3.25e-07");
  EXPECT_EQ(csvNumber(NAN), "nan");
  EXPECT_EQ(csvNumber(INFINITY), "nan");
  EXPECT_EQ(csvNumber(-INFINITY), "nan");
}

TEST(FieldFormat, CsvTextQuotedOnlyWhenNeeded) {
  EXPECT_EQ(csvText("crank.offset_deg"), "crank.offset_deg");
  EXPECT_EQ(csvText(""), "");
  EXPECT_EQ(csvText("delta<=0.05,H>1"), "\"delta<=0.05,H>1\"");
  EXPECT_EQ(csvText("say \"stalled\""), "\"say \"\"stalled\"\"\"");
  EXPECT_EQ(csvText("line one\nline two\r"), "\"line one line two \"");
}

TEST(FieldFormat, JsonNumberNullForNonFinite) {
  EXPECT_EQ(jsonNumber(2.5).dump(), "2.5");
  EXPECT_TRUE(jsonNumber(NAN).is_null());
  EXPECT_TRUE(jsonNumber(INFINITY).is_null());
  EXPECT_TRUE(jsonNumber(-INFINITY).is_null());
}

}  // namespace
}  // namespace rollerdyn
