// `mpirun -n 3 --oversubscribe rollerdyn sweep ...` (src/studies/SweepMpi.h) writes the rows of
// the threaded sweep: same points, same numbers, same order; sweep.json says how it ran.
//
// Open MPI refuses to start as root unless told (CI and this machine run as root), and in a
// container its shared-memory transport may lack the kernel's cross-memory attach: the test
// therefore sets OMPI_ALLOW_RUN_AS_ROOT(_CONFIRM)=1 and OMPI_MCA_btl_vader_single_copy_mechanism=none
// (README, studies section). Skipped, with the reason, when mpirun is missing or rollerdyn was
// built without MPI.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "studies/SweepCliSupport.h"
#include "studies/SweepMpi.h"

namespace rollerdyn {
namespace {

using test::model;

std::vector<std::string> sweepArgs(const std::string& out) {
  return {"sweep", model("recuperative-2cart.yaml"), "--param", "crank.offset_deg", "--values", "0:180:15",
          "--set", "simulation.t_end=4", "--set", "simulation.steady_window_revolutions=2", "--model",
          "reduced", "--minimize", "delta", "--out", out};
}

// Runs `mpirun -n ranks ... rollerdyn args` to the end; stdout and stderr into dir/mpirun.log.
int runUnderMpirun(int ranks, const std::vector<std::string>& args, const std::string& dir) {
  ::setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
  ::setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
  ::setenv("OMPI_MCA_btl_vader_single_copy_mechanism", "none", 1);
  std::string cmd = "cd '" + std::string(ROLLERDYN_SOURCE_DIR) + "' && mpirun --oversubscribe -n " +
                    std::to_string(ranks) + " '" + std::string(ROLLERDYN_BINARY) + "'";
  for (const std::string& a : args) cmd += " '" + a + "'";
  cmd += " > '" + dir + "/mpirun.log' 2>&1";
  const int status = std::system(cmd.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

void skipWithoutMpi() {
  if (!mpiBuilt()) GTEST_SKIP() << "rollerdyn was built without MPI (CMake did not find libopenmpi-dev)";
  if (std::system("command -v mpirun > /dev/null 2>&1") != 0)
    GTEST_SKIP() << "mpirun not on PATH (Debian openmpi-bin; scripts/setup.sh installs it)";
}

TEST(SweepMpi, ThreeRanksGiveTheRowsOfTheThreadedSweep) {
  skipWithoutMpi();
  if (::testing::Test::IsSkipped()) return;
  test::TempDir dir("sweep-mpi");
  const std::string threaded = dir.str() + "/threads", mpi = dir.str() + "/mpi";
  const test::CliResult t = test::runRollerdyn(sweepArgs(threaded), 300);
  ASSERT_EQ(t.exit_code, 0) << t.err;
  ASSERT_EQ(runUnderMpirun(3, sweepArgs(mpi), dir.str()), 0) << test::slurp(dir.str() + "/mpirun.log");

  // Identical rows in grid order, the CPU-time column aside; and all digits in sweep.json.
  EXPECT_EQ(test::csvWithoutCpu(mpi), test::csvWithoutCpu(threaded));
  const auto jt = test::sweepJson(threaded), jm = test::sweepJson(mpi);
  test::expectSameRows(jt, jm);
  EXPECT_EQ(test::optimumWithoutCpu(jm), test::optimumWithoutCpu(jt));
  EXPECT_TRUE(jm["optimum"]["parabola"]["run"].is_object());  // rank 0 ran the vertex

  // How each ran: the threaded sweep on one rank; the MPI sweep on three, every point computed
  // once, by more than one rank (the work was shared, not done by rank 0 alone).
  EXPECT_EQ(jt["ranks"], 1);
  EXPECT_EQ(jm["ranks"], 3);
  const auto per_rank = jm["points_per_rank"].get<std::vector<int>>();
  ASSERT_EQ(per_rank.size(), 3u);
  EXPECT_EQ(per_rank[0] + per_rank[1] + per_rank[2], 13);
  EXPECT_GT(per_rank[1] + per_rank[2], 0);
  // Workers print nothing: one header line and 13 point lines from rank 0 only.
  const std::string log = test::slurp(dir.str() + "/mpirun.log");
  std::size_t headers = 0;
  for (std::size_t at = 0; (at = log.find("sweep of ", at)) != std::string::npos; ++at) ++headers;
  EXPECT_EQ(headers, 1u) << log;
}

TEST(SweepMpi, DispatcherOnlyLeavesTheWorkToTheWorkers) {
  skipWithoutMpi();
  if (::testing::Test::IsSkipped()) return;
  test::TempDir dir("sweep-mpi-dispatch");
  auto args = sweepArgs(dir.str() + "/out");
  args.push_back("--dispatcher-only");
  ASSERT_EQ(runUnderMpirun(3, args, dir.str()), 0) << test::slurp(dir.str() + "/mpirun.log");
  const auto per_rank = test::sweepJson(dir.str() + "/out")["points_per_rank"].get<std::vector<int>>();
  ASSERT_EQ(per_rank.size(), 3u);
  EXPECT_EQ(per_rank[0], 0);
  EXPECT_EQ(per_rank[1] + per_rank[2], 13);
}

// The MPI library is loaded from a plug-in beside the program, only under a launcher: a program
// without its plug-in (copied alone to another folder) refuses the sweep before any point, with
// an error that names the plug-in's path and the loader's reason, and prints no sweep header.
// No mpirun is needed: the launcher's variable alone sends the sweep to MPI.
TEST(SweepMpi, AMissingPlugInIsAClearError) {
  if (!mpiBuilt()) GTEST_SKIP() << "rollerdyn was built without MPI (CMake did not find libopenmpi-dev)";
  test::TempDir dir("sweep-mpi-no-plugin");
  const std::string program = dir.str() + "/rollerdyn";
  std::filesystem::copy_file(ROLLERDYN_BINARY, program);
  std::string cmd = "cd '" + std::string(ROLLERDYN_SOURCE_DIR) + "' && OMPI_COMM_WORLD_SIZE=2 '" + program + "'";
  for (const std::string& a : sweepArgs(dir.str() + "/out")) cmd += " '" + a + "'";
  cmd += " > '" + dir.str() + "/log' 2>&1";
  const int status = std::system(cmd.c_str());
  const std::string log = test::slurp(dir.str() + "/log");
  ASSERT_TRUE(WIFEXITED(status)) << log;
  EXPECT_NE(WEXITSTATUS(status), 0) << log;
  EXPECT_NE(log.find("MPI plug-in " + dir.str() + "/librollerdyn_mpi.so could not be loaded"), std::string::npos)
      << log;
  EXPECT_EQ(log.find("sweep of "), std::string::npos) << log;
}

}  // namespace
}  // namespace rollerdyn

namespace rollerdyn {
namespace {

// The launcher is recognised from its environment; a plain run sees none of these variables.
TEST(SweepMpiLaunch, RecognisesTheLaunchersFromTheirEnvironment) {
  const char* names[] = {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK", "SLURM_PROCID", "SLURM_STEP_NUM_TASKS"};
  std::vector<std::pair<std::string, std::string>> saved;
  for (const char* n : names)
    if (const char* v = std::getenv(n)) saved.emplace_back(n, v);
  for (const char* n : names) ::unsetenv(n);
  EXPECT_FALSE(detectMpiLaunch().launched);
  ::setenv("OMPI_COMM_WORLD_SIZE", "3", 1);
  MpiLaunch l = detectMpiLaunch();
  EXPECT_TRUE(l.launched);
  EXPECT_EQ(l.world_size, 3);
  EXPECT_EQ(l.variable, "OMPI_COMM_WORLD_SIZE");
  ::unsetenv("OMPI_COMM_WORLD_SIZE");
  // Inside an srun step the step's task count is the size; a batch script's shell has no step.
  ::setenv("SLURM_PROCID", "0", 1);
  EXPECT_EQ(detectMpiLaunch().world_size, 0);
  ::setenv("SLURM_STEP_NUM_TASKS", "64", 1);
  EXPECT_EQ(detectMpiLaunch().world_size, 64);
  for (const char* n : names) ::unsetenv(n);
  for (const auto& [n, v] : saved) ::setenv(n.c_str(), v.c_str(), 1);
}

}  // namespace
}  // namespace rollerdyn
