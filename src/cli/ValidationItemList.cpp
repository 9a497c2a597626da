#include "cli/ValidationItemList.h"

#include "io/AtomicFile.h"
#include "studies/IdentifyValidation.h"
#include "studies/StudyChecks.h"

namespace rollerdyn::cli {

validation::ValidationSection modesSection(const modes::ModesValidationResult& m, const std::string& page) {
  validation::ValidationSection s("modes", "Torsional modes and Floquet stability");
  s.text() << "The modal analysis and the Floquet stability verdicts (`rollerdyn modes`), each check against an "
              "independent reference: closed forms, the published expansions of the Mathieu equation's transition "
              "curves, a simulated run at a point the chart marks unstable. The page with every number: `"
           << page << "`.\n\n";
  for (const modes::ModesCheck& c : m.checks) {
    std::string text = c.line.substr(c.line.find(": ") + 2);  // without the "modes: " of the console
    for (const char* verdict : {": holds", ": FAILS"})         // the claim's verdict is printed after it
      if (text.size() > 7 && text.compare(text.size() - 7, 7, verdict) == 0) text.resize(text.size() - 7);
    if (c.is_claim)
      s.claim(c.pass, text);
    else
      s.text() << "- " << text << " (a measurement, no claim)\n";
  }
  return s;
}

void writeModesPage(const std::string& out_dir, const modes::ModesValidationResult& m) {
  writeFileAtomic(out_dir + "/modes/validation.json", m.json.dump(2) + "\n");
  writeFileAtomic(out_dir + "/modes/validation.md", modes::modesValidationMarkdown(m));
}

std::vector<validation::NamedItem> validationItems(const std::string& out_dir) {
  using namespace rollerdyn::validation;
  return {
      {"motor torque against Kloss's formula", &motorLawChecks},
      {"cart kinematics against the slider-crank closed form", &kinematicsChecks},
      {"energy balance of the shipped scenes", &energyBalanceChecks},
      {"drive sizing recomputed from the run's tables", &driveSizingChecks},
      {"sweep rows and optimization evaluations against separate runs", &sweepRowChecks},
      {"identification of known coupling values from noisy synthetic measurements", &identificationChecks},
      {"torsional modes and Floquet stability",
       [out_dir](const ItemContext& ctx) {
         const modes::ModesValidationResult m =
             modes::runModesValidation(ctx.model_dir, [&ctx](const std::string& line) { ctx.log(line); });
         writeModesPage(out_dir, m);
         return modesSection(m, "modes/validation.md");
       }},
  };
}

}  // namespace rollerdyn::cli
