// Helpers of the sweep tests that run the `rollerdyn` binary: the rows of an output folder
// without the measured CPU time, for comparing two runs of the same sweep.
#pragma once

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "cli/CliTestSupport.h"

namespace rollerdyn::test {

// sweep.csv with the cpu_seconds column removed (the only column that is a measurement).
inline std::string csvWithoutCpu(const std::string& dir) {
  std::istringstream in(slurp(dir + "/sweep.csv"));
  std::string out, line;
  long cpu = -1;
  for (bool header = true; std::getline(in, line); header = false) {
    std::vector<std::string> f;
    std::stringstream ss(line);
    for (std::string x; std::getline(ss, x, ',');) f.push_back(x);
    if (header)
      for (std::size_t i = 0; i < f.size(); ++i)
        if (f[i].rfind("cpu_seconds", 0) == 0) cpu = long(i);  // "cpu_seconds[s]"
    for (std::size_t i = 0; i < f.size(); ++i)
      if (long(i) != cpu) out += f[i] + ",";
    out += "\n";
  }
  return out;
}

inline nlohmann::json sweepJson(const std::string& dir) { return nlohmann::json::parse(slurp(dir + "/sweep.json")); }

// sweep.json's optimum without the CPU time of the run at the parabola's vertex (a measurement).
inline nlohmann::json optimumWithoutCpu(nlohmann::json j) {
  nlohmann::json o = j["optimum"];
  if (o.is_object() && o.contains("parabola") && o["parabola"]["run"].is_object()) o["parabola"]["run"].erase("cpu_seconds");
  return o;
}

// Every point's values, metrics, status and steady flag equal (doubles compared exactly: the
// JSON holds them with all digits).
inline void expectSameRows(const nlohmann::json& a, const nlohmann::json& b) {
  ASSERT_EQ(a["points"].size(), b["points"].size());
  for (std::size_t i = 0; i < a["points"].size(); ++i) {
    const auto &p = a["points"][i], &q = b["points"][i];
    EXPECT_EQ(p["values"], q["values"]) << "point " << i;
    EXPECT_EQ(p["metrics"], q["metrics"]) << "point " << i;
    EXPECT_EQ(p["status"], q["status"]) << "point " << i;
    EXPECT_EQ(p["steady_state_reached"], q["steady_state_reached"]) << "point " << i;
    EXPECT_EQ(p["warnings"], q["warnings"]) << "point " << i;
  }
}

}  // namespace rollerdyn::test
