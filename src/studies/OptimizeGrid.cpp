#include "studies/OptimizeGrid.h"

#include <exception>
#include <utility>

#include "scene/SceneParser.h"

namespace rollerdyn {

namespace {

// The global stage's values of parameter k in the unit box: `per` evenly spaced, plus, for the
// crank offset, the evenly spread layouts Δφ = k·360°/n of the scene's n carts.
std::vector<double> gridValues(const OptimizeOptions& o, std::size_t k, int per) {
  std::vector<double> values;
  for (int i = 0; i < per; ++i) values.push_back(double(i) / (per - 1));
  if (o.params[k].key != "crank.offset_deg") return values;
  int carts = 0;
  try {
    carts = (o.scene_input ? parseSceneInput(*o.scene_input, o.base_overrides)
                           : parseSceneFile(o.scene_path, o.base_overrides))
                .carts.count;
  } catch (const std::exception&) {
  }
  for (int m = 1; m < carts; ++m)
    for (int turn = 0; turn < 2; ++turn) {  // within 0..720°
      const double deg = 360.0 * m / carts + 360.0 * turn;
      const double u = (deg - o.params[k].lower) / (o.params[k].upper - o.params[k].lower);
      if (u > 0 && u < 1) values.push_back(u);
    }
  return values;
}

}  // namespace

std::vector<std::vector<double>> globalGrid(const OptimizeOptions& o) {
  const int n = int(o.params.size());
  const int per = n == 1 ? 19 : n == 2 ? 7 : 5;
  std::vector<std::vector<double>> grid(1, std::vector<double>());
  for (int k = 0; k < n; ++k) {
    const std::vector<double> values = gridValues(o, std::size_t(k), per);
    std::vector<std::vector<double>> next;
    for (const auto& g : grid)
      for (double v : values) {
        next.push_back(g);
        next.back().push_back(v);
      }
    grid = std::move(next);
  }
  return grid;
}

}  // namespace rollerdyn
