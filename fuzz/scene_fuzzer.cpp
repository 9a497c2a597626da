// libFuzzer target for everything a user types into rollerdyn before a simulation starts: the
// scene file (YAML) and the --set KEY.PATH=VALUE arguments (src/scene/SceneParser.h).
//
// Input layout: the bytes up to the first NUL are the scene text; each further NUL-separated
// chunk (at most 8) is one --set argument. A file without NUL is therefore a plain scene file,
// so the model files and the bad-scene corpus serve as seeds unchanged.
//
// Contract checked: parseSceneText() either returns a Scene or throws SceneError. Any other
// exception escapes and libFuzzer reports it as a crash; ASan/UBSan report memory errors and
// undefined behaviour; -timeout catches hangs. A returned Scene must satisfy the invariants the
// models rely on (checked below), and a SceneError must name where it came from. The parser never
// writes files, so it cannot write outside an output folder; the target itself writes nothing.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "scene/SceneError.h"
#include "scene/SceneParser.h"

namespace {

void require(bool ok) {
  if (!ok) std::abort();  // an invariant of a validated Scene does not hold: a parser bug
}

void checkScene(const rollerdyn::Scene& s) {
  require(std::isfinite(s.simulation.t_end) && s.simulation.t_end > 0);
  require(std::isfinite(s.simulation.output_step) && s.simulation.output_step > 0);
  require(std::isfinite(s.crank.radius) && s.crank.radius > 0);
  require(std::isfinite(s.rods.length) && s.rods.length > s.crank.radius);
  require(s.carts.count >= 1);
  require(static_cast<int>(s.carts.side.size()) == s.carts.count);
  for (int side : s.carts.side) require(side == 1 || side == -1);
  require(std::isfinite(s.carts.mass) && s.carts.mass > 0);
  require(s.reducer.ratio > 0 && s.reducer.efficiency > 0 && s.reducer.efficiency <= 1);
  if (s.motor.enabled) require(s.motor.omega_sync > 0 && s.motor.critical_slip > 0);
  (void)s.effects();
  (void)s.motorSideInertia();
  (void)s.crankSideInertia();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string input(reinterpret_cast<const char*>(data), size);
  std::vector<std::string> chunks;
  size_t start = 0;
  while (true) {
    const size_t nul = input.find('\0', start);
    chunks.push_back(input.substr(start, nul == std::string::npos ? std::string::npos : nul - start));
    if (nul == std::string::npos || chunks.size() > 8) break;
    start = nul + 1;
  }
  const std::string text = chunks.front();
  const std::vector<std::string> overrides(chunks.begin() + 1, chunks.end());
  try {
    const rollerdyn::Scene scene = rollerdyn::parseSceneText(text, "fuzz.yaml", overrides);
    checkScene(scene);
  } catch (const rollerdyn::SceneError& e) {
    require(!e.origin().empty());
    require(e.what() != nullptr && e.what()[0] != '\0');
  }
  return 0;
}
