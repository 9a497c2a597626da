// The reducer's teeth in the steady window of a run with backlash (reducer.backlash > 0,
// physics/CouplingLaw.h): how often they part and meet again and how hard. Computed once here from
// the run's timeseries (twist, tooth_contact, coupling_torque, phi_crank); summary.json
// ("backlash"), the console and the report render it.
//
//   impacts_per_revolution   contacts re-established (teeth apart → a flank in contact, or one
//                            flank → the other between two rows) per crank revolution [1/rev]
//   out_of_contact_fraction  share of the window's time with |φ1 − φ2| ≤ b, the twist taken
//                            piecewise linear between the rows [-]
//   peak_impact_torque       largest |coupling torque| from an impact to the next parting of the
//                            teeth, over the impacts in the window [N·m at the crank axis]
// Read off the output rows: a contact shorter than simulation.output_step is not counted.
//
// Verdict: "teeth stay in contact" | "teeth separate" (one warning: the drive runs through its
// backlash in steady running, and the linear modes' permanent contact does not hold) | "not
// applicable" with the reason: no backlash, or no steady window.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "analysis/RunResult.h"
#include "analysis/SteadyState.h"
#include "scene/Scene.h"

namespace rollerdyn {

struct ToothContactSummary {
  std::string verdict;         // "teeth stay in contact" | "teeth separate" | "not applicable"
  std::string reason;          // why not applicable, and what to do; empty otherwise
  double backlash = 0;         // total backlash 2b [rad]
  double t_begin = 0, t_end = 0;  // the window judged [s]
  double revolutions = 0;      // crank revolutions in the window [-]
  int impacts = 0;             // contacts re-established in the window [-]
  double impacts_per_revolution = 0;   // [1/rev]
  double out_of_contact_fraction = 0;  // [-]
  double peak_impact_torque = 0;       // [N·m at the crank axis]
  std::vector<std::string> warnings;
};

// `steady`: the steady window was reached with the crank turning (the window of `ss` is judged).
ToothContactSummary computeToothContact(const Scene& scene, const RunResult& run, const SteadyState& ss, bool steady);

nlohmann::json toothContactJson(const ToothContactSummary& c);

// The console's line for summary.json "backlash" (empty where the scene has no backlash).
std::string toothContactText(const nlohmann::json& backlash);

}  // namespace rollerdyn
