#include "studies/StartLoad.h"

#include <cmath>
#include <limits>

#include "reduced/ReducedModel.h"

namespace rollerdyn {

StartLoad startLoadOf(const Scene& scene) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  StartLoad l{kNaN, kNaN};
  try {
    const ReducedModel model(scene);
    const double r = scene.hasCamDrive() ? 0.5 * scene.cam.stroke : scene.crank.radius;
    const double omega_probe = 50.0 * scene.loads.velocity_smoothing / r;
    l.at_start_angle = model.loadTorque(scene.initial.crank_angle, omega_probe);
    constexpr int kSamples = 360;
    double sum = 0;
    for (int i = 0; i < kSamples; ++i)
      sum += model.loadTorque(scene.initial.crank_angle + 2.0 * M_PI * i / kSamples, omega_probe);
    l.revolution_mean = sum / kSamples;
  } catch (const std::exception&) {
    // a scene the reduced model rejects: the explanation then says the loads are not known
  }
  return l;
}

}  // namespace rollerdyn
