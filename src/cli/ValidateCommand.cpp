// `rollerdyn validate [--quick] [--out DIR]`: the validation suite (src/compare/ValidationSuite.h).
// `rollerdyn validate --studies DIR`: only the markdown pages of the studies folder, from the
// tables validation/studies/run.sh wrote there (src/compare/StudiesReport.h).
// Exit status 0 when every claim holds or is an explained gap and every equivalence case passes,
// 1 otherwise, 3 when interrupted. Writes DIR/report.md, DIR/results.json, DIR/results/*.csv and DIR/figures/*.png (gnuplot,
// src/report/Gnuplot.h). Reads the shipped scenes from model/ and the published tables from
// validation/published/, so it runs from the repository root.
#include <unistd.h>

#include <ctime>
#include <iostream>

#include "cli/Commands.h"
#include "cli/ValidationItemList.h"
#include "compare/StudiesReport.h"
#include "compare/ValidationSuite.h"
#include "io/AtomicFile.h"
#include "report/Gnuplot.h"
#include "report/OutputDir.h"

namespace rollerdyn::cli {

int runValidate(bool quick, const std::string& out_dir) {
  using namespace rollerdyn::validation;
  prepareOutputDir(out_dir);  // before the suite: a bad --out fails now
  ValidationOptions o;
  o.quick = quick;
  o.items = validationItems();
  o.interrupt = &g_interrupted;
  const std::clock_t c0 = std::clock();
  o.log = [c0](const std::string& line) {
    std::cerr << "[" << int(double(std::clock() - c0) / CLOCKS_PER_SEC) << " s cpu] " << line << '\n';
  };
  const ValidationResults results = runValidation(o);
  const ValidationReport report = buildValidationReport(results, "figures");

  int figures = 0;
  if (gnuplotAvailable()) {
    for (const ReportFigure& f : report.figures) {
      renderPlot(f.spec, out_dir + "/figures/" + f.name, /*png=*/true, /*svg=*/false);
      ++figures;
    }
  } else {
    std::cerr << "rollerdyn: gnuplot not found (Debian package gnuplot-nox): report written without figures\n";
  }
  for (const auto& [name, table] : report.tables) writeCsvAtomic(out_dir + "/results/" + name, table);
  writeFileAtomic(out_dir + "/results.json", report.results.dump(2) + "\n");
  writeFileAtomic(out_dir + "/report.md", report.markdown);

  std::cout << "validation report: " << out_dir << "/report.md (" << figures << " figures; CPU " << results.cpu_seconds
            << " s)\n"
            << validationSummary(results, report);
  if (g_interrupted) {
    std::cerr << "rollerdyn: interrupted; the report holds what was computed\n";
    return 3;
  }
  // 1 when any claim is FAILED or any equivalence case fails: a check that cannot fail the run
  // is not a check (CI runs `validate` as a test).
  return validationExitStatus(results, report);
}

int runValidateStudies(const std::string& dir) {
  const std::vector<validation::StudiesPage> pages = validation::buildStudiesPages(dir);
  for (const auto& p : pages) writeFileAtomic(dir + "/" + p.file, p.markdown);
  std::cout << "studies pages: " << pages.size() << " written to " << dir << "/\n";
  return 0;
}

}  // namespace rollerdyn::cli
