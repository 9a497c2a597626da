// runInChild (io/ChildProcess.h): the work's text comes back from the child; a child stopped
// by its CPU limit or by a crash is reported as such, with its CPU time, and never takes the
// parent with it.
#include <gtest/gtest.h>

#include <csignal>
#include <cstdlib>
#include <string>

#include "io/ChildProcess.h"

namespace rollerdyn {
namespace {

TEST(ChildProcess, ReturnsTheWorksTextInFull) {
  const std::string big(200000, 'x');  // more than one pipe buffer
  const auto child = runInChild(10, 11, [&] { return "row:" + big; });
  ASSERT_TRUE(child.has_value());
  EXPECT_TRUE(child->exitedCleanly());
  EXPECT_FALSE(child->stoppedByCpuLimit());
  EXPECT_EQ(child->text, "row:" + big);
  EXPECT_EQ(child->howItEnded(), "exit 0");
}

TEST(ChildProcess, CpuLimitStopsTheChildAndIsReported) {
  const auto child = runInChild(1, 2, [] {
    volatile double x = 0;
    for (;;) x = x + 1.0;  // spins until SIGXCPU after 1 s of CPU
    return std::string("never");
  });
  ASSERT_TRUE(child.has_value());
  EXPECT_FALSE(child->exitedCleanly());
  EXPECT_TRUE(child->stoppedByCpuLimit()) << child->howItEnded();
  EXPECT_TRUE(child->text.empty());
  EXPECT_GE(child->cpu_seconds, 0.9);  // the limit is whole seconds of CPU, accounted in ticks
}

TEST(ChildProcess, ACrashIsReportedWithItsSignal) {
  const auto child = runInChild(10, 11, []() -> std::string { std::abort(); });
  ASSERT_TRUE(child.has_value());
  EXPECT_FALSE(child->exitedCleanly());
  EXPECT_FALSE(child->stoppedByCpuLimit());
  EXPECT_TRUE(child->endedBySignal());
  EXPECT_TRUE(child->killedBy(SIGABRT));
  EXPECT_EQ(child->howItEnded(), "signal " + std::to_string(SIGABRT));
}

}  // namespace
}  // namespace rollerdyn
