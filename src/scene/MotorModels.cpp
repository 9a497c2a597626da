#include "scene/MotorModels.h"

#include <stdexcept>

#include "scene/SchemaSections.h"

namespace rollerdyn {

namespace {
// T_e of the dynamic Kloss characteristic; 0 in the Scene stands for its default 1/(ω1·s_kr),
// which MotorLawFactory.cpp computes.
KeySpec torqueTimeConstantKey() {
  using namespace schema_builders;
  return number("motor.torque_time_constant", "s", Presence::Conditional, positive(), 0.0,
                "T_e of the dynamic Kloss characteristic T_e·dM/dt + M = M_static")
      .from("Klyuchev (1985)")
      .when("1/(2π·f_n·s_kr)");
}
}  // namespace

const std::vector<MotorModelInfo>& motorModelTable() {
  static const std::vector<MotorModelInfo> table = {
      {MotorModel::Kloss, "kloss", "the static Kloss formula", "Loveikin, Pochka, Romasevych (2018) eq. (37)",
       "Kloss formula", true, false,
       "The static Kloss law cannot show the switching transient (the supply-frequency torque oscillation of "
       "several times the nominal torque right after switching on, which is what loads couplings and joints) and "
       "understates the starting torque: "},
      {MotorModel::KlossDynamic, "kloss_dynamic", "the Kloss torque lagging by T_e", "Klyuchev (1985)",
       "dynamic Kloss characteristic", true, false,
       "The dynamic Kloss characteristic shows the electromagnetic lag of the torque but not the supply-frequency "
       "oscillation after switching on, and its starting torque is Kloss's: ",
       {{torqueTimeConstantKey, &InductionMotor::torque_time_constant}}},
      {MotorModel::Circuit, "circuit", "the steady-state equivalent circuit (single or double cage)",
       "Pedra (2008) fig. 1", "equivalent circuit", false, false,
       "The equivalent circuit is quasi-static: it honours the catalogue's starting torque but shows no switching "
       "transient (motor.model: park does)."},
      {MotorModel::Park, "park", "the space-phasor machine with its flux linkages as states",
       "Krause, Wasynczuk, Sudhoff, ch. 6", "space-phasor model", false, true, ""},
  };
  return table;
}

const MotorModelInfo& motorModelInfo(MotorModel m) {
  for (const MotorModelInfo& row : motorModelTable())
    if (row.model == m) return row;
  throw std::logic_error("motorModelInfo: a motor.model without a row in the motor-law table");
}

std::string motorModelWords(bool kloss_curve, const std::string& conjunction) {
  std::vector<std::string> words;
  for (const MotorModelInfo& law : motorModelTable())
    if (law.kloss_curve == kloss_curve) words.push_back(law.word);
  std::string out;
  for (std::size_t i = 0; i < words.size(); ++i)
    out += (i == 0 ? "" : i + 1 == words.size() ? " " + conjunction + " " : ", ") + words[i];
  return out;
}

}  // namespace rollerdyn
