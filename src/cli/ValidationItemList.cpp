#include "cli/ValidationItemList.h"

#include "studies/StudyChecks.h"

namespace rollerdyn::cli {

std::vector<validation::NamedItem> validationItems() {
  using namespace rollerdyn::validation;
  return {
      {"motor torque against Kloss's formula", &motorLawChecks},
      {"cart kinematics against the slider-crank closed form", &kinematicsChecks},
      {"energy balance of the shipped scenes", &energyBalanceChecks},
      {"drive sizing recomputed from the run's tables", &driveSizingChecks},
      {"sweep rows and optimization evaluations against separate runs", &sweepRowChecks},
  };
}

}  // namespace rollerdyn::cli
