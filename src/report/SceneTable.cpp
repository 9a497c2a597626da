#include "report/SceneTable.h"

#include <fstream>
#include <sstream>
#include <stdexcept>

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

std::vector<SceneParameterRow> derivedParameterRows(const Scene& s) {
  const double u = s.reducer.ratio;
  std::vector<SceneParameterRow> rows = {
      {"critical slip s_kr", formatNumber(s.motor.critical_slip), "-",
       "Kloss critical slip as the parser derived it (Loveikin, Pochka, Romasevych (2018) eq. (37), Loveikin and Pochka (2007) eq. (7))", "derived"},
      {"synchronous crank speed ω0/u", formatNumber(s.motor.omega_sync / u), "rad/s",
       "motor synchronous speed reduced to the crank axis", "derived"},
      {"breakdown torque at the crank M_kr·u·η",
       formatNumber(s.motor.breakdown_torque * u * s.reducer.efficiency), "N·m",
       "largest motor torque the crank can get", "derived"},
      {"motor-side inertia J_n1", formatNumber(s.motorSideInertia()), "kg·m²",
       "(J_p + J_m + J_red + motor-shaft flywheel)·δ·u², reduced to the crank axis (Loveikin, Pochka, Romasevych (2018) eq. (1))",
       "derived"},
      {"crank-side inertia", formatNumber(s.crankSideInertia()), "kg·m²",
       "cranks, shaft and crankshaft flywheel about the shaft axis, without rods and carts", "derived"},
      {"cart mass with rod share m_B", formatNumber(s.cartMassWithRodShare()), "kg",
       "cart mass plus half a rod under the split rod model (Loveikin, Pochka, Romasevych (2018) eq. (3))", "derived"},
  };
  if (s.rods.model != RodModel::Massless)
    rows.push_back({"rod inertia about its centre of mass", formatNumber(s.rods.inertia_com), "kg·m²",
                    "rods.inertia_com as used (default m·l²/12)", "derived"});
  return rows;
}

}  // namespace rollerdyn
