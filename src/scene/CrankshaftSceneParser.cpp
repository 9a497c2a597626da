// crankshaft.*: where the throws and the main bearings sit along the shaft (Scene.h,
// CrankshaftLayout; analysis/CrankshaftBearings.h uses them).
#include <algorithm>

#include "scene/SceneReader.h"

namespace rollerdyn::scene_detail {

namespace {

// One axial position per throw: one number would put every throw in one plane, so say where each is.
std::vector<double> readThrowPositions(const Reader& in, int cart_count) {
  double uniform = 0.0;
  std::vector<double> z = in.perCartNumbers("crankshaft.throw_positions", cart_count, uniform);
  if (z.empty())
    in.doc().fail("crankshaft.throw_positions",
                  describeExpectedList(*findSceneKey("crankshaft.throw_positions"), cart_count), formatNumber(uniform));
  return z;
}

// Two or more main bearings (one cannot carry a shaft's moments), ascending, no two in one place.
std::vector<double> readBearingPositions(const Reader& in) {
  const SceneDocument& doc = in.doc();
  const std::vector<double> z = in.numberList("crankshaft.bearing_positions");
  if (z.size() < 2)
    doc.fail("crankshaft.bearing_positions",
             "a list of two or more axial positions [m], ascending (one bearing cannot carry a shaft's moments)",
             std::to_string(z.size()) + " value" + (z.size() == 1 ? "" : "s"));
  for (size_t k = 1; k < z.size(); ++k)
    if (!(z[k] > z[k - 1]))
      doc.fail("crankshaft.bearing_positions[" + std::to_string(k) + "]",
               "a position greater than crankshaft.bearing_positions[" + std::to_string(k - 1) + "] = " +
                   formatNumber(z[k - 1]) + " m (ascending, no two bearings in one place)",
               formatNumber(z[k]));
  return z;
}

// The shaft's stiffnesses: in bending, and in torsion with its damping (which only a torsional
// chain's segments can carry).
void readShaftStiffness(const Reader& in, CrankshaftLayout& c) {
  c.bending_stiffness = in.number("crankshaft.bending_stiffness");
  c.torsional_stiffness = in.number("crankshaft.torsional_stiffness");
  c.torsional_damping = in.number("crankshaft.torsional_damping");
  if (c.torsional_damping > 0 && !c.torsionalChain())
    in.doc().fail("crankshaft.torsional_damping",
                  "crankshaft.torsional_stiffness beside it (the damping acts across the chain's shaft segments; a "
                  "rigid crankshaft does not twist)",
                  formatNumber(c.torsional_damping) + " without crankshaft.torsional_stiffness");
}

// The position lists that need each other: a torsional chain needs the throws (the segment lengths
// between them set their stiffness); otherwise one list without the other places nothing (a throw
// needs bearings to share its force between).
void requirePositionLists(const SceneDocument& doc, const CrankshaftLayout& c, int cart_count, bool has_throws,
                          bool has_bearings) {
  if (c.torsionalChain() && !has_throws)
    doc.failMissing("crankshaft.throw_positions",
                    "a list of " + std::to_string(cart_count) +
                        " axial positions z [m], one per cart's crank throw (needed with crankshaft.torsional_stiffness: "
                        "the segment lengths between throws set their stiffness)");
  if (!has_throws && !has_bearings) return;
  if (!has_bearings && !c.torsionalChain())
    doc.failMissing("crankshaft.bearing_positions",
                    "a list of two or more axial positions z of the main bearings [m], ascending (needed with "
                    "crankshaft.throw_positions)");
  if (!has_throws)
    doc.failMissing("crankshaft.throw_positions",
                    "a list of " + std::to_string(cart_count) +
                        " axial positions z [m], one per cart's crank throw (needed with crankshaft.bearing_positions)");
}

// A torsional chain's drive and formulation: not under a cam drive, only in the constrained formulation.
void checkChainFormulation(const SceneDocument& doc, const Scene& s) {
  const std::string key = "crankshaft.torsional_stiffness";
  if (s.drive == DriveType::Cam)
    doc.fail(key, "no torsional chain under drive.type: cam (the cams sit on one rigid shaft); remove the key",
             formatNumber(s.crankshaft.torsional_stiffness));
  if (s.simulation.formulation != Formulation::Constrained)
    doc.fail(key,
             "simulation.formulation: constrained beside it (the torsional chain, one body per throw, is built by "
             "the constrained formulation; it needs loads.guide_friction.normal_force: lagged where guides have "
             "friction), or no crankshaft.torsional_stiffness for a rigid crankshaft",
             formatNumber(s.crankshaft.torsional_stiffness) + " with simulation.formulation: minimal");
}

// A chain's throws at distinct positions: a segment of zero length would be infinitely stiff.
void checkDistinctThrows(const SceneDocument& doc, std::vector<double> z) {
  std::sort(z.begin(), z.end());
  for (size_t k = 1; k < z.size(); ++k)
    if (!(z[k] > z[k - 1]))
      doc.fail("crankshaft.throw_positions",
               "distinct positions with crankshaft.torsional_stiffness (a segment of zero length would be "
               "infinitely stiff: two throws in one plane cannot twist against each other)",
               "two throws at z = " + formatNumber(z[k]) + " m");
}

// Each throw turns against its neighbours on its own: it needs an inertia at every angle, its own
// or its rod's (a distributed rod's, or a split rod's pin mass); a cart's alone vanishes at the
// dead centres (the rigid shaft's rule, physics/CrankInertia.h, per throw).
void checkThrowInertia(const SceneDocument& doc, const Scene& s) {
  const bool rod_inertia = s.rods.model == RodModel::Distributed || (s.rods.model == RodModel::Split && s.rods.mass > 0);
  if (!(s.crank.inertia_per_crank > 0 || s.crank.shaft_inertia > 0 || rod_inertia))
    doc.fail("crank.inertia_per_crank",
             "a number > 0 [kg·m²] with crankshaft.torsional_stiffness and " + std::string(toString(s.rods.model)) +
                 " rods (each throw of the chain turns on its own and needs an inertia at the dead centres: "
                 "crank.inertia_per_crank, or crank.shaft_inertia shared equally)",
             formatNumber(s.crank.inertia_per_crank));
}

}  // namespace

CrankshaftLayout readCrankshaft(const Reader& in, int cart_count) {
  CrankshaftLayout c;
  readShaftStiffness(in, c);
  const bool has_throws = in.has("crankshaft.throw_positions"), has_bearings = in.has("crankshaft.bearing_positions");
  requirePositionLists(in.doc(), c, cart_count, has_throws, has_bearings);
  if (!has_throws && !has_bearings) return c;
  c.throw_positions = readThrowPositions(in, cart_count);
  if (has_bearings) c.bearing_positions = readBearingPositions(in);
  return c;
}

// The torsional chain is built by the constrained formulation only (one Simbody body per throw,
// a spring between neighbours); the minimal formulation's closed-form loops turn one rigid
// crankshaft, and a cam's follower reads one crank angle.
void checkTorsionalChain(const Reader& in, const Scene& s) {
  if (!s.crankshaft.torsionalChain()) return;
  const SceneDocument& doc = in.doc();
  checkChainFormulation(doc, s);
  checkDistinctThrows(doc, s.crankshaft.throw_positions);
  checkThrowInertia(doc, s);
}

}  // namespace rollerdyn::scene_detail
