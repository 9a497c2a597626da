// comparison.json and the console text of `rollerdyn compare` (ModelComparison.h): how a
// comparison of the two models is written; the comparison itself is in ModelComparison.cpp.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include "compare/ModelComparison.h"
#include "io/FieldFormat.h"

namespace rollerdyn {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();


nlohmann::json statsJson(const DifferenceStats& s) {
  return {{"max_abs_diff", jsonNumber(s.max_abs_diff)},
          {"rms_diff", jsonNumber(s.rms_diff)},
          {"max_rel_diff", jsonNumber(s.max_rel_diff)},
          {"max_abs_multibody", jsonNumber(s.max_abs_a)},
          {"t_at_max_abs_diff", jsonNumber(s.t_at_max)},
          {"samples", s.samples}};
}

nlohmann::json runJson(const RunResult& r) {
  return {{"integrator", r.integrator},
          {"status", r.stats.status},
          {"complete", r.stats.complete},
          {"steps", r.stats.steps},
          {"realizations", r.stats.realizations},
          {"cpu_seconds", jsonNumber(r.stats.cpu_seconds)}};
}

// The compared span and how the rows were compared.
nlohmann::json comparedJson(const ModelComparison& c) {
  return {{"t_begin", jsonNumber(c.t_begin)},
          {"t_end", jsonNumber(c.t_end)},
          {"rows", c.rows},
          {"grid_max_time_offset", jsonNumber(c.grid_max_time_offset)},
          {"reference", "multibody"},
          {"max_rel_diff_definition", "max|multibody - reduced| / max|multibody|"},
          {"row_by_row_note",
           "quantities: row by row at equal times over the whole compared span (start-up included), so a phase drift "
           "between the models counts as a difference; max_rel_diff is normalised by the largest multibody value of "
           "the whole span"}};
}

// Statistics of each quantity by its name.
nlohmann::json quantitiesJson(const std::vector<QuantityComparison>& qs) {
  nlohmann::json q = nlohmann::json::object();
  for (const auto& x : qs) q[x.name] = statsJson(x.stats);
  return q;
}

nlohmann::json differencesDetailJson(const ModelComparison& c) {
  nlohmann::json detail = nlohmann::json::array();
  for (const auto& d : c.differences)
    detail.push_back({{"topic", d.topic},
                      {"affects_motion", d.affects_motion},
                      {"numerical", d.numerical},
                      {"sentence", d.sentence}});
  return detail;
}

// Steady running: each metric of both models, and each quantity's shape at the same crank angle.
void steadyJson(const ModelComparison& c, nlohmann::json& j) {
  nlohmann::json steady = nlohmann::json::object();
  for (const auto& m : c.steady)
    steady[m.name] = {{"multibody", jsonNumber(m.multibody)}, {"reduced", jsonNumber(m.reduced)}, {"rel_diff", jsonNumber(m.rel_diff)},
                      {"unit", m.unit}};
  j["steady"] = steady;
  nlohmann::json shapes = nlohmann::json::object();
  for (const auto& sh : c.shapes)
    shapes[sh.name] = {{"max_abs_diff", jsonNumber(sh.max_abs_diff)}, {"rel_diff_of_swing", jsonNumber(sh.rel_diff)}};
  j["shape_at_same_crank_angle"] = shapes;
}

nlohmann::json speedJson(const ModelComparison& c) {
  const double cm = c.cpuMultibody(), cr = c.cpuReduced();
  return {{"cpu_seconds_multibody", jsonNumber(cm)},
          {"cpu_seconds_reduced", jsonNumber(cr)},
          {"cpu_ratio_reduced_to_multibody", jsonNumber(cm > 0 ? cr / cm : kNaN)},
          {"speedup_reduced_over_multibody", jsonNumber(cr > 0 ? cm / cr : kNaN)}};
}

// Steady running, one line per metric: both models and their relative difference.
void steadyText(std::ostream& os, const ModelComparison& c) {
  os << "steady running (each model over its own steady window; rel. diff = (reduced - multibody)/|multibody|):\n";
  for (const auto& m : c.steady) {
    char buf[200];
    std::snprintf(buf, sizeof buf, "  %-22s multibody %-11.5g reduced %-11.5g rel. diff %+.2e  [%s]\n", m.name.c_str(),
                  m.multibody, m.reduced, m.rel_diff, m.unit.c_str());
    os << buf;
  }
  os << "shape at the same crank angle (steady windows folded onto one revolution; against the multibody swing):\n";
  for (const auto& sh : c.shapes) {
    char buf[200];
    std::snprintf(buf, sizeof buf, "  %-22s max diff %.4g (%.2e of its swing)\n", sh.name.c_str(), sh.max_abs_diff,
                  sh.rel_diff);
    os << buf;
  }
}

void phaseDriftText(std::ostream& os, const ModelComparison& c) {
  char buf[260];
  std::snprintf(buf, sizeof buf,
                "phase drift  the multibody crank is %.4g rad (%.3g°) %s the reduced one at t = %.4g s (mean "
                "speeds differ by %.3g rad/s): it shifts the time series against each other without changing "
                "their shape\n",
                std::abs(c.phase_drift), std::abs(c.phase_drift) * 180.0 / M_PI,
                c.phase_drift >= 0 ? "ahead of" : "behind", c.t_end, -c.speed_difference);
  os << buf;
}

// Row by row at equal times: crank speed and coupling torque, then the largest reaction difference.
void rowByRowText(std::ostream& os, const ModelComparison& c) {
  os << "row by row at equal times (whole span, start-up and phase drift included; normalised by the largest "
        "multibody value):\n";
  for (const char* name : {"omega_crank", "coupling_torque"}) {
    if (const QuantityComparison* q = c.find(name))
      os << "  " << name << std::string(17 - std::string(name).size(), ' ') << "max_rel_diff "
         << q->stats.max_rel_diff << "  max_abs_diff " << q->stats.max_abs_diff << "  rms_diff "
         << q->stats.rms_diff << '\n';
  }
  double worst = 0, worst_kin = 0;
  for (const auto& q : c.quantities)
    if (q.name != "omega_crank" && q.name != "coupling_torque") worst = std::max(worst, q.stats.max_rel_diff);
  for (const auto& q : c.kinetostatic) worst_kin = std::max(worst_kin, q.stats.max_rel_diff);
  if (c.kinetostatic.empty())
    os << "  reactions      not computed (simulation.reactions: false)\n";
  else
    os << "  reactions      largest max_rel_diff " << worst << " (the reduced run's own rows, "
       << (c.reduced_kinetostatic ? "kinetostatic" : "the papers' quasi-static") << " guide normals), " << worst_kin
       << " (the reduced rows with only the carts' d'Alembert forces added afterwards: no rod inertia, no "
          "friction loop)\n";
}

}  // namespace

nlohmann::json comparisonJson(const ModelComparison& c) {
  nlohmann::json j;
  j["scene"] = c.scene_name;
  j["compared"] = comparedJson(c);
  j["quantities"] = quantitiesJson(c.quantities);
  j["kinetostatic_reactions"] = quantitiesJson(c.kinetostatic);
  steadyJson(c, j);
  j["phase_drift"] = jsonNumber(c.phase_drift);
  j["mean_speed_difference"] = jsonNumber(c.speed_difference);
  std::vector<std::string> sentences;
  for (const auto& d : c.differences) sentences.push_back(d.sentence);
  j["differences"] = sentences;
  j["differences_detail"] = differencesDetailJson(c);
  j["identical_physics"] = c.identical;
  j["motion_equivalent"] = c.motion_equivalent;
  j["speed"] = speedJson(c);
  j["runs"] = {{"multibody", runJson(c.multibody)}, {"reduced", runJson(c.reduced)}};
  return j;
}

std::string comparisonText(const ModelComparison& c) {
  std::ostringstream os;
  os.precision(3);
  os << "scene        " << c.scene_name << "  (" << c.rows << " rows, t = " << c.t_begin << " ... "
     << c.t_end << " s)\n";
  os << "runs         multibody: " << c.multibody.stats.status << "; reduced: " << c.reduced.stats.status
     << '\n';
  steadyText(os, c);
  phaseDriftText(os, c);
  rowByRowText(os, c);
  os << "physics      " << (c.motion_equivalent ? "the same equations of motion" : "the models differ in what they model (below)")
     << '\n';
  for (const auto& d : c.differences) os << "  - " << d.sentence << '\n';
  os << "cpu          multibody " << c.cpuMultibody() << " s, reduced " << c.cpuReduced() << " s";
  if (c.cpuReduced() > 0) os << " (reduced " << c.cpuMultibody() / c.cpuReduced() << "x faster)";
  os << '\n';
  return os.str();
}

}  // namespace rollerdyn
