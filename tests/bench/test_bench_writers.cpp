// The bench studies' writers (writeIntegratorStudy, writeCartsStudy, writeEffectsStudy) on a small
// synthetic set of rows: the files they promise exist, the CSV has one line per row with the
// rows' own numbers, and the markdown names every row. The numbers are made up here, so what the
// files contain is checked against values written in this test, not computed by the code.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "bench/BenchStudies.h"
#include "io/ReadFile.h"
#include "support/Loveikin2018Scene.h"

namespace rollerdyn::bench {
namespace {

BenchRow row(const std::string& study, const std::string& variant, double x, const std::string& model,
             const std::string& integrator, double accuracy, double cpu, double err_w, double err_m, bool reference) {
  BenchRow r;
  r.study = study;
  r.variant = variant;
  r.x = x;
  r.carts = study == "carts" ? int(x) : 4;
  r.reference = reference;
  r.m.setting.model = model;
  r.m.setting.integrator = integrator;
  r.m.setting.accuracy = accuracy;
  r.m.outcome = Outcome::Ok;
  r.m.status = "completed";
  r.m.repeats = 1;
  r.m.cpu_seconds = r.m.cpu_min = r.m.cpu_max = cpu;
  r.m.steps = 1234;
  r.m.realizations = 5678;
  r.m.simulated_time = 2.0;
  r.m.real_time_factor = 2.0 / cpu;
  r.error_omega = err_w;
  r.error_coupling = err_m;
  return r;
}

std::string tempDir(const std::string& name) {
  const auto d = std::filesystem::temp_directory_path() / ("rollerdyn_bench_writers_" + name);
  std::filesystem::remove_all(d);
  return d.string();
}

int lines(const std::string& text) {
  int n = 0;
  for (char c : text) n += c == '\n';
  return n;
}

TEST(BenchWriters, IntegratorStudyWritesCsvAndReport) {
  const Scene scene = test_scenes::loveikin2018Scene();
  BenchOptions opt;
  opt.quick = true;
  const std::vector<BenchRow> rows = {
      row("integrators", "", 0, "multibody", "RungeKuttaMerson", 1e-10, 22.25, 0, 0, true),
      row("integrators", "", 0, "multibody", "RungeKuttaMerson", 1e-6, 2.75, 3.125e-8, 4.5e-7, false),
      row("integrators", "", 0, "reduced", "cvode", 1e-10, 0.5, 0, 0, true),
      row("integrators", "", 0, "reduced", "cvode", 1e-6, 0.0625, 2.5e-8, 3.75e-7, false)};
  const std::string dir = tempDir("integrators");
  const std::vector<std::string> written = writeIntegratorStudy(dir, scene, rows, opt);
  ASSERT_FALSE(written.empty());
  for (const auto& f : written) EXPECT_TRUE(std::filesystem::exists(f)) << f;
  const std::string csv = readFileContents(dir + "/bench.csv");
  EXPECT_EQ(lines(csv), 1 + int(rows.size()));  // header + one line per row
  EXPECT_NE(csv.find("3.125e-08"), std::string::npos) << csv;
  EXPECT_NE(csv.find("22.25"), std::string::npos) << csv;
  const std::string md = readFileContents(dir + "/bench.md");
  EXPECT_NE(md.find("RungeKuttaMerson"), std::string::npos);
  EXPECT_NE(md.find("cvode"), std::string::npos);
  std::filesystem::remove_all(dir);
}

TEST(BenchWriters, CartsAndEffectsStudiesWriteCsvAndReport) {
  const Scene scene = test_scenes::loveikin2018Scene();
  BenchOptions opt;
  opt.quick = true;
  const std::vector<BenchRow> carts = {row("carts", "n=4", 4, "multibody", "RungeKuttaMerson", 1e-6, 1.5, NAN, NAN, false),
                                       row("carts", "n=32", 32, "multibody", "RungeKuttaMerson", 1e-6, 24.5, NAN, NAN, false),
                                       row("carts", "n=4", 4, "reduced", "cvode", 1e-6, 0.125, NAN, NAN, false),
                                       row("carts", "n=32", 32, "reduced", "cvode", 1e-6, 0.75, NAN, NAN, false)};
  const std::string dc = tempDir("carts");
  for (const auto& f : writeCartsStudy(dc, scene, carts, opt)) EXPECT_TRUE(std::filesystem::exists(f)) << f;
  const std::string csv = readFileContents(dc + "/carts.csv");
  EXPECT_EQ(lines(csv), 1 + int(carts.size()));
  EXPECT_NE(csv.find("24.5"), std::string::npos) << csv;
  EXPECT_EQ(csv.find("nan"), std::string::npos) << csv;  // NaN errors are empty fields
  const std::string md = readFileContents(dc + "/carts.md");
  // The per-cart cost column of the n = 32 multibody row: 24.5 s / 32 carts = 0.765625 s.
  EXPECT_NE(md.find("0.766"), std::string::npos) << md;
  std::filesystem::remove_all(dc);

  const std::vector<BenchRow> effects = {
      row("effects", "coupling stiffness 1e+07 N·m/rad", 1e7, "multibody", "RungeKuttaMerson", 1e-6, 3.5, NAN, NAN, false),
      row("effects", "coupling stiffness 1e+07 N·m/rad", 1e7, "reduced", "cvode", 1e-6, 0.25, NAN, NAN, false)};
  const std::string de = tempDir("effects");
  for (const auto& f : writeEffectsStudy(de, scene, effects, opt)) EXPECT_TRUE(std::filesystem::exists(f)) << f;
  EXPECT_EQ(lines(readFileContents(de + "/effects.csv")), 1 + int(effects.size()));
  EXPECT_NE(readFileContents(de + "/effects.md").find("coupling stiffness 1e+07"), std::string::npos);
  std::filesystem::remove_all(de);
}

}  // namespace
}  // namespace rollerdyn::bench
