// prepareOutputDir: creates the folder, rejects one that cannot be created or is a file (with the
// option and the reason), and removes exactly the stale files of each kind, never a user's file.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "report/OutputDir.h"
#include "support/FreshTempDir.h"
#include "support/ThrownMessage.h"

namespace rollerdyn {
namespace {

namespace fs = std::filesystem;

using test::messageOf;

fs::path freshDir(const std::string& tag) { return test::freshTempDir("outdir-" + tag); }

void touch(const fs::path& p) { std::ofstream(p) << "x"; }

TEST(OutputDir, CreatesNestedFoldersAndLeavesNoProbe) {
  const fs::path d = freshDir("create");
  const fs::path nested = d / "a" / "b" / "c";
  EXPECT_TRUE(prepareOutputDir(nested.string()).empty());
  EXPECT_TRUE(fs::is_directory(nested));
  EXPECT_TRUE(fs::is_empty(nested)) << "the write probe must be removed";
  fs::remove_all(d);
}

TEST(OutputDir, UnusableFolderNamesOptionFolderAndReason) {
  const fs::path d = freshDir("bad");
  touch(d / "file");
  EXPECT_EQ(messageOf([&] { prepareOutputDir((d / "file").string()); }),
            "--out '" + (d / "file").string() + "': expected a folder, got an existing file");
  EXPECT_EQ(messageOf([&] { prepareOutputDir((d / "file" / "sub").string(), StaleOutputs::Keep, "figures folder"); }),
            "figures folder '" + (d / "file" / "sub").string() + "': cannot create the folder (Not a directory)");
  // A folder without write permission (only testable when not running as root).
  if (::geteuid() != 0) {
    fs::create_directories(d / "ro");
    fs::permissions(d / "ro", fs::perms::owner_read | fs::perms::owner_exec);
    EXPECT_NE(messageOf([&] { prepareOutputDir((d / "ro").string()); }).find("the folder is not writable"),
              std::string::npos);
    fs::permissions(d / "ro", fs::perms::owner_all);
  }
  fs::remove_all(d);
}

TEST(OutputDir, RemovesOnlyStaleFilesOfOurs) {
  const fs::path d = freshDir("stale");
  const auto populate = [&d] {
    fs::create_directories(d / "figures");
    for (const char* f : {"crank_speed_vs_angle.png", "crank_speed_vs_angle.svg", "twist_phase_rate.png",
                          "comparison_omega_crank.svg", "my_plot.png", "crank_speed_vs_angle.pdf"})
      touch(d / "figures" / f);
    for (const char* f : {"report.html", "report.png", "timeseries.csv", "notes.txt"}) touch(d / f);
  };
  populate();
  EXPECT_TRUE(prepareOutputDir(d.string(), StaleOutputs::Keep).empty());
  EXPECT_TRUE(fs::exists(d / "figures" / "crank_speed_vs_angle.png"));
  EXPECT_TRUE(fs::exists(d / "report.html"));

  EXPECT_EQ(prepareOutputDir(d.string(), StaleOutputs::RunFigures).size(), 4u);
  for (const char* kept : {"figures/my_plot.png", "figures/crank_speed_vs_angle.pdf", "report.html", "report.png",
                           "timeseries.csv", "notes.txt"})
    EXPECT_TRUE(fs::exists(d / kept)) << kept;
  EXPECT_FALSE(fs::exists(d / "figures" / "twist_phase_rate.png"));
  EXPECT_FALSE(fs::exists(d / "figures" / "comparison_omega_crank.svg"));

  populate();
  EXPECT_EQ(prepareOutputDir(d.string(), StaleOutputs::RunFiguresAndReport).size(), 6u);
  EXPECT_FALSE(fs::exists(d / "report.html"));
  EXPECT_FALSE(fs::exists(d / "report.png"));
  EXPECT_TRUE(fs::exists(d / "figures" / "my_plot.png"));  // the user's: kept, and so is figures/
  EXPECT_TRUE(fs::exists(d / "timeseries.csv"));           // overwritten by the run, not removed
  EXPECT_TRUE(fs::exists(d / "notes.txt"));

  fs::remove(d / "figures" / "my_plot.png");
  fs::remove(d / "figures" / "crank_speed_vs_angle.pdf");
  touch(d / "figures" / "rod_forces_vs_angle.png");
  prepareOutputDir(d.string(), StaleOutputs::RunFigures);
  EXPECT_FALSE(fs::exists(d / "figures")) << "figures/ held only our files: removed when emptied";
  fs::remove_all(d);
}

}  // namespace
}  // namespace rollerdyn
