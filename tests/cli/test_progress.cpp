// cli::Progress (src/cli/Progress.h): what it draws, how often, and that it is silent when
// disabled (stderr not a terminal). test_cli does not link the CLI's objects, so the one source
// file is compiled in here.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "cli/Progress.cpp"  // NOLINT: see above

namespace rollerdyn::cli {
namespace {

// Everything written to a temporary FILE*.
std::string contents(std::FILE* f) {
  std::fflush(f);
  std::rewind(f);
  std::string s;
  for (int c; (c = std::fgetc(f)) != EOF;) s += static_cast<char>(c);
  return s;
}

TEST(Progress, DisabledWritesNothing) {
  std::FILE* f = std::tmpfile();
  {
    Progress p(f, false, [] { return 0.0; });
    p(1.0, 10.0);
    p(10.0, 10.0);
    p.items(3, 3);
  }
  EXPECT_EQ(contents(f), "");
  std::fclose(f);
}

TEST(Progress, SimulatedTimeShowsShareSpeedAndTimeLeft) {
  std::FILE* f = std::tmpfile();
  double now = 0;
  {
    Progress p(f, true, [&now] { return now; });
    now = 2.0;  // 2 s of CPU for 5 s simulated: 2.5x real time, 5 s left to simulate = 2 s
    p(5.0, 10.0);
  }
  const std::string s = contents(f);
  EXPECT_NE(s.find("\r   50.0 %  t = 5.000 s  2.5x real time  2 s left"), std::string::npos) << s;
  EXPECT_EQ(s.back(), '\n') << "destructor ends the line";
  std::fclose(f);
}

TEST(Progress, RedrawsAtMostEveryFifthOfASecondButAlwaysAtTheEnd) {
  std::FILE* f = std::tmpfile();
  double now = 0;
  {
    Progress p(f, true, [&now] { return now; });
    now = 1.0;
    p(1.0, 4.0);   // drawn (first)
    now = 1.1;
    p(2.0, 4.0);   // too soon
    now = 1.25;
    p(3.0, 4.0);   // drawn
    now = 1.26;
    p(4.0, 4.0);   // finished: always drawn, line ended
  }
  const std::string s = contents(f);
  EXPECT_EQ(std::count(s.begin(), s.end(), '\r'), 3) << s;
  EXPECT_EQ(s.find("t = 2.000"), std::string::npos) << s;
  EXPECT_NE(s.find("100.0 %"), std::string::npos) << s;
  EXPECT_EQ(std::count(s.begin(), s.end(), '\n'), 1) << "one newline, not two:\n" << s;
  std::fclose(f);
}

TEST(Progress, ItemsForSweepsAndBenchmarks) {
  std::FILE* f = std::tmpfile();
  double now = 0;
  {
    Progress p(f, true, [&now] { return now; });
    p.setLabel("sweep dphi");
    now = 10.0;
    p.items(4, 10, "runs");
  }
  const std::string s = contents(f);
  EXPECT_NE(s.find("sweep dphi     40.0 %  4/10 runs  0.40 runs/s  15 s left"), std::string::npos) << s;
  std::fclose(f);
}

TEST(Progress, DefaultFollowsWhetherStderrIsATerminal) {
  Progress p;
  EXPECT_EQ(p.enabled(), ::isatty(STDERR_FILENO) == 1);
}

}  // namespace
}  // namespace rollerdyn::cli
