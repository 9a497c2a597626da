// Designs of a sweep (src/studies/SweepDesigns.h): grid order, values files, Latin hypercube.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>

#include "cli/CliTestSupport.h"
#include "studies/SweepDesigns.h"

namespace rollerdyn {
namespace {

TEST(SweepDesigns, GridHasTheLastParameterFastest) {
  SweepOptions o;
  o.params = {parseSweepValues("a", "1,2"), parseSweepValues("b", "10,20,30")};
  const SweepDesigns d = sweepDesigns(o);
  ASSERT_EQ(d.texts.size(), 6u);
  EXPECT_EQ(d.texts[0], (std::vector<std::string>{"1", "10"}));
  EXPECT_EQ(d.texts[2], (std::vector<std::string>{"1", "30"}));
  EXPECT_EQ(d.texts[3], (std::vector<std::string>{"2", "10"}));
  EXPECT_EQ(d.values[5], (std::vector<double>{2, 30}));
  // Explicit designs are taken as they are, words (coupling.type=rigid) as NaN numbers.
  o.designs = {{"5", "rigid"}};
  const SweepDesigns e = sweepDesigns(o);
  ASSERT_EQ(e.values.size(), 1u);
  EXPECT_EQ(e.values[0][0], 5.0);
  EXPECT_TRUE(std::isnan(e.values[0][1]));
}

TEST(SweepDesigns, ValuesFileWithHeaderCommentsAndErrors) {
  test::TempDir dir("designs");
  const std::string path = dir.str() + "/designs.txt";
  std::ofstream(path) << "# two parameters\n"
                         "crank.offset_deg, coupling.damping\n"
                         "60, 2000\n"
                         "\n"
                         "90 8000   # blanks work too\n";
  const auto d = readValuesFile(path, {"crank.offset_deg", "coupling.damping"});
  ASSERT_EQ(d.size(), 2u);
  EXPECT_EQ(d[0], (std::vector<std::string>{"60", "2000"}));
  EXPECT_EQ(d[1], (std::vector<std::string>{"90", "8000"}));
  // A short line: the message names the file and line, and what was expected.
  std::ofstream(path) << "60,2000\n90\n";
  try {
    readValuesFile(path, {"crank.offset_deg", "coupling.damping"});
    FAIL() << "a line with one value was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(path + ":2:"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("expected 2 value(s)"), std::string::npos) << e.what();
  }
  std::ofstream(path) << "# nothing\n";
  EXPECT_THROW(readValuesFile(path, {"a"}), std::invalid_argument);
  EXPECT_THROW(readValuesFile(dir.str() + "/missing.txt", {"a"}), std::invalid_argument);
}

TEST(SweepDesigns, RangesAreChecked) {
  const SampleRange r = parseSampleRange("flywheel.inertia", "0:400");
  EXPECT_EQ(r.lower, 0.0);
  EXPECT_EQ(r.upper, 400.0);
  for (const char* bad : {"", "5", "400:0", "1:1", "a:b", "0:1:2"})
    EXPECT_THROW(parseSampleRange("k", bad), std::invalid_argument) << bad;
}

TEST(SweepDesigns, LatinHypercubeHasOneValueInEveryStratumAndIsReproducible) {
  const std::vector<SampleRange> ranges = {{"a", 0.0, 10.0}, {"b", -1.0, 1.0}};
  const std::size_t n = 50;
  const auto d = latinHypercube(ranges, n, 7);
  ASSERT_EQ(d.size(), n);
  // The defining property (McKay, Beckman and Conover (1979)): in every dimension the n values
  // fall one in each of the n equal strata of the range.
  for (std::size_t k = 0; k < ranges.size(); ++k) {
    std::set<long> strata;
    for (const auto& design : d) {
      const double v = std::stod(design[k]);
      ASSERT_GE(v, ranges[k].lower);
      ASSERT_LE(v, ranges[k].upper);
      strata.insert(std::min<long>(long(n) - 1, long((v - ranges[k].lower) / (ranges[k].upper - ranges[k].lower) * n)));
    }
    EXPECT_EQ(strata.size(), n) << "dimension " << k;
  }
  EXPECT_EQ(latinHypercube(ranges, n, 7), d);  // same seed, same designs
  EXPECT_NE(latinHypercube(ranges, n, 8), d);
  // The two columns are not paired stratum by stratum (that would be a diagonal, no sample).
  std::size_t same = 0;
  for (const auto& design : d)
    same += long(std::stod(design[0]) / 10.0 * n) == long((std::stod(design[1]) + 1.0) / 2.0 * n);
  EXPECT_LT(same, n / 2);
  EXPECT_THROW(latinHypercube(ranges, 0, 1), std::invalid_argument);
}

TEST(SweepDesigns, DesignParametersCarryTheColumns) {
  const auto p = designParameters({"a", "b"}, {{"1", "x"}, {"2", "y"}});
  ASSERT_EQ(p.size(), 2u);
  EXPECT_EQ(p[0].values, (std::vector<double>{1, 2}));
  EXPECT_TRUE(p[0].numeric());
  EXPECT_FALSE(p[1].numeric());
}

}  // namespace
}  // namespace rollerdyn
