// Ctrl-C on a running `rollerdyn simulate`: the SIGINT handler sets the interrupt flag, the
// multibody run checks it after each output row's progress callback, stops, and the command
// still writes complete files with the rows it has; summary.json says complete = false and
// status "interrupted at t = ..."; the exit code is 3 (README: "Exit codes").
//
// The test sends a real SIGINT to the real binary (test_cli does not link the multibody model,
// so the flag cannot be set from inside a progress callback here). It waits until the process
// has installed its handler (SigCgt in /proc/PID/status) and has used 0.5 s of CPU (utime +
// stime in /proc/PID/stat): the whole default 10 s run costs about 0.3 s, so by then it has
// integrated many rows however loaded the machine is (a wall-clock wait would not say that).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <thread>

#include <unistd.h>

#include "cli/CliTestSupport.h"

namespace rollerdyn {
namespace {

namespace fs = std::filesystem;
using test::model;
using test::slurp;
using test::TempDir;

// Whether process `pid` has a handler for SIGINT (bit 1 of the SigCgt mask).
bool catchesSigint(pid_t pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/status");
  for (std::string line; std::getline(in, line);)
    if (line.rfind("SigCgt:", 0) == 0) return (std::stoull(line.substr(7), nullptr, 16) & 0x2ull) != 0;
  return false;
}

// CPU seconds process `pid` has used (fields 14 and 15 of /proc/PID/stat, in clock ticks); -1
// when it cannot be read or the process has ended (state Z).
double cpuSecondsOf(pid_t pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
  std::string text;
  std::getline(in, text);
  const std::size_t close = text.rfind(')');  // the command name may hold spaces
  if (close == std::string::npos) return -1;
  std::istringstream fields(text.substr(close + 2));
  std::string f;
  unsigned long long utime = 0, stime = 0;
  for (int i = 3; i <= 15 && fields >> f; ++i) {
    if (i == 3 && f == "Z") return -1;
    if (i == 14) utime = std::stoull(f);
    if (i == 15) stime = std::stoull(f);
  }
  return double(utime + stime) / double(::sysconf(_SC_CLK_TCK));
}

// A CSV is complete when it ends with a newline and every row has as many numeric fields as the
// header has names. Returns the number of data rows, -1 if incomplete.
long completeCsvRows(const fs::path& p, std::string* why) {
  const std::string text = slurp(p);
  if (text.empty() || text.back() != '\n') {
    *why = p.string() + ": empty or not ending with a newline";
    return -1;
  }
  std::istringstream in(text);
  std::string line;
  std::getline(in, line);
  const long fields = std::count(line.begin(), line.end(), ',') + 1;
  long rows = 0;
  while (std::getline(in, line)) {
    ++rows;
    if (std::count(line.begin(), line.end(), ',') + 1 != fields) {
      *why = p.string() + ": row " + std::to_string(rows) + " has the wrong number of fields";
      return -1;
    }
    std::istringstream fs_in(line);
    for (std::string f; std::getline(fs_in, f, ',');) {
      char* end = nullptr;
      std::strtod(f.c_str(), &end);
      if (f.empty() || *end != '\0') {
        *why = p.string() + ": row " + std::to_string(rows) + ": '" + f + "' is not a number";
        return -1;
      }
    }
  }
  return rows;
}

TEST(CliInterrupt, SigintStopsTheRunAndKeepsCompleteOutputs) {
  TempDir io("interrupt-io"), out("interrupt-out");
  // t_end far beyond what can finish before the signal, so the run is surely interrupted.
  const pid_t pid = test::startRollerdyn(
      {"simulate", model("balanced-4cart.yaml"), "--set", "simulation.t_end=10000", "--out", out.str()}, io.path());
  ASSERT_GT(pid, 0);
  const auto t0 = std::chrono::steady_clock::now();
  while (!catchesSigint(pid)) {
    ASSERT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 60)
        << "rollerdyn never installed its SIGINT handler";
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  for (double cpu; (cpu = cpuSecondsOf(pid)) < 0.5;) {  // let it integrate some rows (file comment)
    ASSERT_GE(cpu, 0.0) << "rollerdyn ended before the signal";
    ASSERT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 300)
        << "rollerdyn did not get 0.5 s of CPU in 300 s";
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  ASSERT_EQ(::kill(pid, SIGINT), 0);
  const test::CliResult r = test::waitRollerdyn(pid, io.path(), 120);
  ASSERT_EQ(r.signal, 0) << "rollerdyn died of signal " << r.signal << "\n" << r.err;
  EXPECT_EQ(r.exit_code, 3) << r.out << r.err;
  EXPECT_NE(r.err.find("interrupted at t = "), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\r'), std::string::npos) << "progress drawn although stderr is a file";

  std::string why;
  const long ts_rows = completeCsvRows(out.path() / "timeseries.csv", &why);
  EXPECT_GT(ts_rows, 1) << why;
  const long rx_rows = completeCsvRows(out.path() / "reactions.csv", &why);
  EXPECT_EQ(rx_rows, ts_rows) << why;

  nlohmann::json s;
  ASSERT_NO_THROW(s = nlohmann::json::parse(slurp(out.path() / "summary.json")));
  EXPECT_EQ(s["complete"], false);
  const std::string status = s["status"].get<std::string>();
  EXPECT_EQ(status.rfind("interrupted at t = ", 0), 0u) << status;
  ASSERT_TRUE(s["simulated_time"].is_number());
  EXPECT_GT(s["simulated_time"].get<double>(), 0.0);
  EXPECT_LT(s["simulated_time"].get<double>(), 10000.0);

  // Nothing but the four outputs: no temporary file left behind, nothing else written.
  for (const auto& e : fs::directory_iterator(out.path())) {
    const std::string n = e.path().filename().string();
    EXPECT_TRUE(n == "timeseries.csv" || n == "reactions.csv" || n == "crank_speed_extrema.csv" || n == "summary.json")
        << "unexpected file " << n;
  }
}

}  // namespace
}  // namespace rollerdyn
