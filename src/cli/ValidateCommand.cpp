// `rollerdyn validate [--quick] [--out DIR]`: the validation suite (src/compare/ValidationSuite.h).
// `rollerdyn validate --studies DIR`: only the markdown pages of the studies folder, from the
// tables validation/studies/run.sh wrote there (src/compare/StudiesReport.h).
// Exit status 0 when every claim holds or is an explained gap and every equivalence case passes,
// 1 otherwise, 3 when interrupted. Writes DIR/report.md, DIR/results.json, DIR/results/*.csv and DIR/figures/*.png (gnuplot,
// src/report/Gnuplot.h). Reads the shipped scenes from model/ and the published tables from
// validation/published/, so it runs from the repository root.
#include <unistd.h>

#include <ctime>
#include <filesystem>
#include <iostream>
#include <stdexcept>

#include "cli/Commands.h"
#include "cli/ValidationItemList.h"
#include "compare/StudiesReport.h"
#include "compare/ValidationSuite.h"
#include "io/AtomicFile.h"
#include "modes/ModesValidation.h"
#include "report/Gnuplot.h"
#include "report/OutputDir.h"

namespace rollerdyn::cli {

// The repository's top folder holding the shipped scene files and published tables: the working
// directory when it holds them (a checkout), else the source tree this binary was built from, so
// `validate` runs from any working directory.
std::string repositoryDir() {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::exists("model/balanced-4cart.yaml", ec) && fs::exists("validation/published", ec)) return ".";
#ifdef ROLLERDYN_MODEL_DIR
  const fs::path top = fs::path(ROLLERDYN_MODEL_DIR).parent_path();
  if (fs::exists(top / "model/balanced-4cart.yaml", ec) && fs::exists(top / "validation/published", ec))
    return top.string();
#endif
  throw std::runtime_error(
      "validate: the shipped scene files and published tables (model/, validation/published/) are neither in "
      "the working folder nor in the source tree this binary was built from; run it from the repository's top "
      "folder");
}


// `validate --modes-only`: the torsional-modes checks alone (src/modes/ModesValidation.h), their
// lines on stdout, their page and numbers under DIR/modes/. Returns the number of failed claims.
// (A full `validate` runs them as its last validation item, ValidationItemList.cpp, so their claims
// are counted with every other claim.)
int runModesChecks(const std::string& out_dir, const std::string& model_dir) {
  std::cout << "torsional modes and Floquet stability:\n";
  const modes::ModesValidationResult m =
      modes::runModesValidation(model_dir, [](const std::string& line) { std::cout << "  " << line << '\n' << std::flush; });
  writeModesPage(out_dir, m);
  std::cout << "torsional modes: " << m.checks.size() << " checks, " << m.failed() << " failed (CPU " << m.cpu_seconds
            << " s); " << out_dir << "/modes/validation.md\n";
  return m.failed();
}

// The report's figures (PNG) when gnuplot is there; how many were drawn.
int drawValidationFigures(const validation::ValidationReport& report, const std::string& out_dir) {
  if (!gnuplotAvailable()) {
    std::cerr << "rollerdyn: gnuplot not found (Debian package gnuplot-nox): report written without figures\n";
    return 0;
  }
  int figures = 0;
  for (const validation::ReportFigure& f : report.figures) {
    renderPlot(f.spec, out_dir + "/figures/" + f.name, /*png=*/true, /*svg=*/false);
    ++figures;
  }
  return figures;
}

// The console's lines of the cases of carts of their own and of the induction-motor claims.
void printCartAndMotorClaims(const validation::ValidationResults& results) {
  using validation::Finding;
  for (const auto& c : results.per_cart) {
    const bool fails = c.verdict != Finding::Verdict::Holds;
    std::cout << "carts of their own " << c.label << (fails ? " FAILS: " : " holds: ") << c.description << '\n'
              << "    " << (c.explanation.empty() ? "(no result)" : c.explanation) << '\n';
  }
  for (const auto& c : results.motor) {
    const bool fails = c.verdict == Finding::Verdict::Fails;
    std::cout << "induction motor " << c.id << (fails ? " FAILS: " : c.verdict == Finding::Verdict::Holds ? " holds: " : ": ")
              << c.title << '\n';
    for (const auto& l : c.lines) std::cout << "    " << l << '\n';
  }
}

validation::ValidationOptions validationOptions(bool quick, const std::string& out_dir, const std::string& prefix) {
  validation::ValidationOptions o;
  o.quick = quick;
  o.model_dir = prefix + "model";
  o.published_dir = prefix + "validation/published";
  o.items = validationItems(out_dir);
  o.interrupt = &g_interrupted;
  const std::clock_t c0 = std::clock();
  o.log = [c0](const std::string& line) {
    std::cerr << "[" << int(double(std::clock() - c0) / CLOCKS_PER_SEC) << " s cpu] " << line << '\n';
  };
  return o;
}

int runValidate(bool quick, const std::string& out_dir, bool modes_only) {
  using namespace rollerdyn::validation;
  prepareOutputDir(out_dir);  // before the suite: a bad --out fails now
  const std::string top = repositoryDir();
  const std::string prefix = top == "." ? "" : top + "/";  // as before from the top folder
  if (modes_only) return runModesChecks(out_dir, prefix + "model") == 0 ? 0 : 1;
  const ValidationResults results = runValidation(validationOptions(quick, out_dir, prefix));
  const ValidationReport report = buildValidationReport(results, "figures");
  const int figures = drawValidationFigures(report, out_dir);
  for (const auto& [name, table] : report.tables) writeCsvAtomic(out_dir + "/results/" + name, table);
  writeFileAtomic(out_dir + "/results.json", report.results.dump(2) + "\n");
  writeFileAtomic(out_dir + "/report.md", report.markdown);
  printCartAndMotorClaims(results);
  std::cout << "validation report: " << out_dir << "/report.md (" << figures << " figures; CPU " << results.cpu_seconds
            << " s)\n"
            << validationSummary(results, report);
  if (g_interrupted) {
    std::cerr << "rollerdyn: interrupted; the report holds what was computed\n";
    return 3;
  }
  // 1 when any claim is FAILED (the cases of carts of their own, the induction-motor claims and
  // the torsional-modes checks included) or any equivalence case fails: a check that cannot fail
  // the run is not a check (CI runs `validate` as a test).
  return validationExitStatus(results, report);
}

int runValidateStudies(const std::string& dir) {
  const std::vector<validation::StudiesPage> pages = validation::buildStudiesPages(dir);
  for (const auto& p : pages) writeFileAtomic(dir + "/" + p.file, p.markdown);
  std::cout << "studies pages: " << pages.size() << " written to " << dir << "/\n";
  return 0;
}

}  // namespace rollerdyn::cli
