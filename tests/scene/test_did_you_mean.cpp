// The one edit distance behind every "did you mean" hint (scene keys, --set, commands, options,
// sweep keys): Levenshtein distances by hand, and which near misses get a hint.
#include <gtest/gtest.h>

#include "scene/DidYouMean.h"

namespace rollerdyn {
namespace {

TEST(DidYouMean, EditDistanceKnownValues) {
  EXPECT_EQ(editDistance("", ""), 0u);
  EXPECT_EQ(editDistance("abc", ""), 3u);
  EXPECT_EQ(editDistance("", "abc"), 3u);
  EXPECT_EQ(editDistance("kitten", "sitting"), 3u);  // k->s, e->i, +g
  EXPECT_EQ(editDistance("cuont", "count"), 2u);     // two substitutions
  EXPECT_EQ(editDistance("simulat", "simulate"), 1u);
  EXPECT_EQ(editDistance("flaw", "lawn"), 2u);
}

TEST(DidYouMean, ClosestWithinTwoEditsAndLessThanHalfTheWord) {
  const std::vector<std::string> commands = {"check", "simulate", "plot", "report", "compare"};
  EXPECT_EQ(closestMatch("simulat", commands), "simulate");
  EXPECT_EQ(closestMatch("reprot", commands), "report");
  EXPECT_EQ(closestMatch("frobnicate", commands), "");
  EXPECT_EQ(closestMatch("-x", {"-h", "--out"}), "");  // one edit, but half the word
  EXPECT_EQ(closestMatch("--outt", {"--out", "--model"}), "--out");
  EXPECT_EQ(closestMatch("abcd", {"abxy", "abcx"}), "abcx");       // fewer edits wins
  EXPECT_EQ(closestMatch("abcd", {"abce", "abcf"}), "abce");       // ties: the first
  EXPECT_EQ(didYouMean("cuont", {"count", "sides"}), " (did you mean 'count'?)");
  EXPECT_EQ(didYouMean("zzzzz", {"count", "sides"}), "");
}

}  // namespace
}  // namespace rollerdyn
