// crankshaft.*: where the throws and the main bearings sit along the shaft (Scene.h,
// CrankshaftLayout; analysis/CrankshaftBearings.h uses them).
#include "scene/SceneReader.h"

namespace rollerdyn::scene_detail {

CrankshaftLayout readCrankshaft(const Reader& in, int cart_count) {
  const SceneDocument& doc = in.doc();
  CrankshaftLayout c;
  c.bending_stiffness = in.number("crankshaft.bending_stiffness");
  const bool has_throws = in.has("crankshaft.throw_positions"), has_bearings = in.has("crankshaft.bearing_positions");
  if (!has_throws && !has_bearings) return c;
  // One list without the other places nothing: a throw needs bearings to share its force between.
  if (!has_bearings)
    doc.failMissing("crankshaft.bearing_positions",
                    "a list of two or more axial positions z of the main bearings [m], ascending (needed with "
                    "crankshaft.throw_positions)");
  if (!has_throws)
    doc.failMissing("crankshaft.throw_positions",
                    "a list of " + std::to_string(cart_count) +
                        " axial positions z [m], one per cart's crank throw (needed with crankshaft.bearing_positions)");
  double uniform = 0.0;
  c.throw_positions = in.perCartNumbers("crankshaft.throw_positions", cart_count, uniform);
  if (c.throw_positions.empty())  // one number would put every throw in one plane: say where each is
    doc.fail("crankshaft.throw_positions", describeExpectedList(*findSceneKey("crankshaft.throw_positions"), cart_count),
             formatNumber(uniform));
  c.bearing_positions = in.numberList("crankshaft.bearing_positions");
  if (c.bearing_positions.size() < 2)
    doc.fail("crankshaft.bearing_positions",
             "a list of two or more axial positions [m], ascending (one bearing cannot carry a shaft's moments)",
             std::to_string(c.bearing_positions.size()) + " value" + (c.bearing_positions.size() == 1 ? "" : "s"));
  for (size_t k = 1; k < c.bearing_positions.size(); ++k)
    if (!(c.bearing_positions[k] > c.bearing_positions[k - 1]))
      doc.fail("crankshaft.bearing_positions[" + std::to_string(k) + "]",
               "a position greater than crankshaft.bearing_positions[" + std::to_string(k - 1) + "] = " +
                   formatNumber(c.bearing_positions[k - 1]) + " m (ascending, no two bearings in one place)",
               formatNumber(c.bearing_positions[k]));
  return c;
}

}  // namespace rollerdyn::scene_detail
