// The motor laws a scene can choose (motor.model), one row each: what every place that treats the
// laws alike reads (the schema's words and description, the run's effect line, the classification
// the plausibility warnings, the keys without effect, the breakdown torque, the scales and the motor
// figure ask, what a start-up with the law cannot show). A new law is described here once; its
// torque law itself lives in src/motor/ and is built by makeMotorLaw (motor/MotorLawFactory.h).
#pragma once

#include <string>
#include <vector>

#include "scene/Scene.h"

namespace rollerdyn {

struct KeySpec;  // scene/SceneSchema.h

// A scene key of one law's own, a number of InductionMotor: the row declares it, and the schema
// (its reference and checks), the parser and the scene's values read it from there. Absent from
// the file, the field takes the key's schema default.
struct MotorLawKey {
  KeySpec (*spec)();               // the key's schema row: path, unit, range, default, meaning, source
  double InductionMotor::*field;   // the Scene field the key sets
};

// One row of the table; the enumeration MotorModel (Scene.h) lists the laws in the table's order.
struct MotorModelInfo {
  MotorModel model;          // the enumerator this row describes
  const char* word;          // the motor.model word in scene files, summary.json and the console
  const char* meaning;       // what the law is, as the reference of motor.model says it
  const char* source;        // where the law comes from (authors, year, equation or chapter)
  const char* effect;        // the run's effect line, "induction motor, <effect> (motor.model: <word>)"
  bool kloss_curve;          // torque on the Kloss curve of motor.breakdown_torque and the critical
                             // slip (true), or the machine of motor.catalogue / motor.circuit (false)
  bool switching_transient;  // shows the supply-frequency torque oscillation after switching on
  const char* start_up_limit;  // what a start-up with this law cannot show ("" when nothing); a
                               // law on the Kloss curve adds the comparison of its starting torque
                               // with the catalogue's and the advice to use a catalogue law
  std::vector<MotorLawKey> own_keys{};  // keys only this law reads (motor.* after motor.model in the
                                        // reference, in the table's order); none for most laws
};

// Every law, in the order of the enumeration.
const std::vector<MotorModelInfo>& motorModelTable();

// The row of law `m`.
const MotorModelInfo& motorModelInfo(MotorModel m);

// Whether the law's torque follows the Kloss curve of motor.breakdown_torque and the critical slip
// (kloss, kloss_dynamic), rather than a machine of its own fitted to motor.catalogue or given as
// motor.circuit (circuit, park).
inline bool hasKlossCurve(MotorModel m) { return motorModelInfo(m).kloss_curve; }

// The words of the laws on the Kloss curve (kloss_curve true) or of the machine laws (false), joined
// as a sentence says them: "circuit or park" (conjunction "or"), "circuit and park" ("and").
std::string motorModelWords(bool kloss_curve, const std::string& conjunction);

// Whether the law is the machine of motor.catalogue or motor.circuit (circuit, park): it needs one
// of them, with motor.voltage and the pole pairs.
inline bool isMachineLaw(MotorModel m) { return !hasKlossCurve(m); }

}  // namespace rollerdyn
