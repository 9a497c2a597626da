// The Loveikin, Pochka, Romasevych (2018) scene of the reduced-model tests: the shared test scene (tests/support/
// Loveikin2018Scene.h) with the choices these tests were written for. Declared in each test file as
// `rollerdyn::test::loveikin2018LikeScene()`.
#include <cmath>

#include "support/Loveikin2018Scene.h"

namespace rollerdyn {
namespace test {

Scene loveikin2018LikeScene() {
  Scene s = test_scenes::loveikin2018Scene();
  s.name = "loveikin2018-like";
  s.source = "Loveikin, Pochka, Romasevych (2018) (four carts, elastic drive), parameters after eq. (39)";
  s.simulation.output_step = 1e-3;
  s.crank.inertia_per_crank = 0.0;              // J'_K is not given by the paper
  s.rods.model = RodModel::Split;               // the paper's lumping, Loveikin, Pochka, Romasevych (2018) eq. (2)-(3)
  s.carts.geometry.com_height = 0.3;            // non-zero, so inertia moments are exercised
  s.motor.critical_slip = 0.1145;               // as printed (the formula gives 0.1146)
  s.reduced.baranov_step = 0.5 * M_PI / 180.0;
  return s;
}

}  // namespace test
}  // namespace rollerdyn
