#include "report/SceneTable.h"

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "motor/BreakdownTorque.h"
#include "scene/SceneDocument.h"
#include "scene/SceneError.h"
#include "scene/SceneSchema.h"

namespace rollerdyn {

namespace {

// A YAML value as it reads in a table: the scalar, or a flow list/map.
std::string valueText(const YAML::Node& node) {
  if (!node.IsDefined() || node.IsNull()) return "";
  if (node.IsScalar()) return node.Scalar();
  std::string s;
  if (node.IsSequence()) {
    for (size_t i = 0; i < node.size(); ++i) s += (i ? ", " : "") + valueText(node[i]);
    return "[" + s + "]";
  }
  for (auto it = node.begin(); it != node.end(); ++it)
    s += (s.empty() ? "" : ", ") + valueText(it->first) + ": " + valueText(it->second);
  return "{" + s + "}";
}

}  // namespace

std::vector<SceneParameterRow> sceneParameterRows(const std::string& scene_path,
                                                  const std::vector<std::string>& overrides) {
  std::ifstream in(scene_path, std::ios::binary);
  if (!in) throw SceneError::inFile(scene_path, 0, "", "a readable scene file", "cannot open it");
  std::ostringstream text;
  text << in.rdbuf();
  return sceneParameterRows(SceneInput{scene_path, text.str(), false}, overrides);
}

std::vector<SceneParameterRow> sceneParameterRows(const SceneInput& input,
                                                  const std::vector<std::string>& overrides) {
  SceneDocument doc(input.text, input.label, !input.from_data);
  for (size_t i = 0; i < overrides.size(); ++i) doc.applyOverride(static_cast<int>(i) + 1, overrides[i]);

  std::vector<SceneParameterRow> rows;
  for (const KeySpec& spec : sceneSchema()) {
    if (spec.path == "source") continue;  // the citation heads the report instead
    const YAML::Node node = doc.find(spec.path);
    SceneParameterRow row{spec.path, "", spec.unit, spec.meaning, ""};
    if (node.IsDefined() && !node.IsNull()) {
      row.value = valueText(node);
      const int n = doc.overrideFor(spec.path);
      row.origin = n > 0 ? "--set #" + std::to_string(n) : "file";
    } else if (spec.presence == Presence::Optional) {
      row.value = defaultText(spec);
      row.origin = "default";
    } else {
      continue;  // conditional key the file leaves to the parser: see derivedParameterRows()
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

// A per-cart value as it reads in a table: one number when every cart has it, else the list.
std::string perCartText(const Scene& s, double (*value)(const Scene&, int)) {
  std::string list;
  bool same = true;
  for (int j = 0; j < s.carts.count; ++j) {
    list += (j ? ", " : "") + formatNumber(value(s, j));
    same = same && value(s, j) == value(s, 0);
  }
  return same ? formatNumber(value(s, 0)) : "[" + list + "]";
}

namespace {

// The motor's figures the parser derived, and the motor reduced to the crank axis.
std::vector<SceneParameterRow> motorDerivedRows(const Scene& s) {
  const double u = s.reducer.ratio;
  return {
      {"critical slip s_kr", formatNumber(s.motor.critical_slip), "-",
       "Kloss critical slip as the parser derived it (Loveikin, Pochka, Romasevych (2018) eq. (37), Loveikin and Pochka (2007) eq. (7))", "derived"},
      {"synchronous crank speed ω0/u", formatNumber(s.motor.omega_sync / u), "rad/s",
       "motor synchronous speed reduced to the crank axis", "derived"},
      {"breakdown torque at the crank M_kr·u·η",
       formatNumber(motorBreakdownTorque(s) * u * s.reducer.efficiency), "N·m",
       "largest motor torque the crank can get", "derived"},
  };
}

// The machine's inertias and moving masses as the models use them.
std::vector<SceneParameterRow> inertiaDerivedRows(const Scene& s) {
  return {
      {"motor-side inertia J_n1", formatNumber(s.motorSideInertia()), "kg·m²",
       "(J_p + J_m + J_red + motor-shaft flywheel)·δ·u², reduced to the crank axis (Loveikin, Pochka, Romasevych (2018) eq. (1))",
       "derived"},
      {"crank-side inertia", formatNumber(s.crankSideInertia()), "kg·m²",
       "cranks, shaft and crankshaft flywheel about the shaft axis, without rods and carts", "derived"},
      {"cart mass with rod share m_B",
       perCartText(s, [](const Scene& sc, int j) { return sc.cartMassWithRodShare(j); }), "kg",
       "cart mass plus half a rod under the split rod model (Loveikin, Pochka, Romasevych (2018) eq. (3)); a list: "
       "cart 1, 2, ...",
       "derived"},
  };
}

}  // namespace

std::vector<SceneParameterRow> derivedParameterRows(const Scene& s) {
  std::vector<SceneParameterRow> rows = motorDerivedRows(s);
  for (SceneParameterRow& r : inertiaDerivedRows(s)) rows.push_back(std::move(r));
  if (!s.crank.angles.empty() || !s.crank.angle_errors.empty())
    rows.push_back({"crank angles θ_j − φ2",
                    perCartText(s, [](const Scene& sc, int j) { return sc.crankPhase(j) * 180.0 / M_PI; }), "deg",
                    "each cart's crank from the shaft's reference (cart 1's nominal crank): crank.angles_deg or "
                    "j·Δφ, plus crank.angle_error_deg",
                    "derived"});
  if (s.rods.model != RodModel::Massless)
    rows.push_back({"rod inertia about its centre of mass", formatNumber(s.rods.inertia_com), "kg·m²",
                    "rods.inertia_com as used (default m·l²/12)", "derived"});
  return rows;
}

}  // namespace rollerdyn
