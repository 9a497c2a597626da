#include "analysis/ToothContact.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "physics/CouplingLaw.h"

namespace rollerdyn {

namespace {

// Share of a row interval during which the twist, linear from x0 to x1, lies in [-b, b].
double shareInGap(double x0, double x1, double b) {
  if (x0 == x1) return std::abs(x0) <= b ? 1.0 : 0.0;
  const double lo = std::min(x0, x1), hi = std::max(x0, x1);
  const double in = std::max(0.0, std::min(hi, b) - std::max(lo, -b));
  return in / (hi - lo);
}

// Why the teeth's contact is not judged in this run; "" when it is.
std::string notJudgedReason(const Scene& scene, const CouplingLaw& law, const Table& ts, const SteadyState& ss,
                            bool steady) {
  if (!law.hasBacklash())
    return scene.coupling.type == CouplingType::Rigid
               ? "rigid coupling (coupling.type: rigid): motor and crank turn together"
               : "no backlash (reducer.backlash: 0): the teeth never part; give reducer.backlash to see impacts";
  if (!steady)
    return ss.not_reached.empty() ? std::string("the crank does not turn steadily in this run, so there is no "
                                                "steady window to count the teeth's impacts in")
                                  : ss.not_reached;
  if (!ts.has("tooth_contact") || !ts.has("twist") || ss.row_end <= ss.row_begin + 1)
    return "the steady window holds fewer than two rows of the timeseries";
  return "";
}

// Over the steady window's rows: the time the twist spends inside the gap, the impacts (the teeth
// meeting again) and the largest coupling torque from an impact until the teeth part.
void countImpacts(ToothContactSummary& c, const Table& ts, const SteadyState& ss, double half_gap) {
  const int it = ts.index("t"), iq = ts.index("twist"), ic = ts.index("tooth_contact"), im = ts.index("coupling_torque"),
            ip = ts.index("phi_crank");
  const auto& rows = ts.rows;
  const std::size_t a = ss.row_begin, e = ss.row_end;  // half-open
  c.revolutions = std::abs(rows[e - 1][ip] - rows[a][ip]) / (2.0 * M_PI);
  double gap_time = 0.0;
  bool in_episode = false;  // between an impact in the window and the next parting
  for (std::size_t i = a + 1; i < e; ++i) {
    const double dt = rows[i][it] - rows[i - 1][it];
    gap_time += dt * shareInGap(rows[i - 1][iq], rows[i][iq], half_gap);
    const int before = static_cast<int>(rows[i - 1][ic]), now = static_cast<int>(rows[i][ic]);
    if (now == 0) {
      in_episode = false;
    } else if (now != before) {  // teeth meet again (from the gap, or flank to flank within a row)
      ++c.impacts;
      in_episode = true;
    }
    if (in_episode) c.peak_impact_torque = std::max(c.peak_impact_torque, std::abs(rows[i][im]));
  }
  const double span = rows[e - 1][it] - rows[a][it];
  c.out_of_contact_fraction = span > 0 ? gap_time / span : 0.0;
}

std::string teethSeparateWarning(const ToothContactSummary& c) {
  char buf[512];
  std::snprintf(buf, sizeof buf,
                "the reducer's teeth separate in steady running (t = %.4g ... %.4g s, backlash %.4g rad): apart %.3g %% "
                "of the time, %.3g impacts per crank revolution, peak impact torque %.4g N·m at the crank axis; the "
                "linear torsional modes assume permanent contact and do not hold (summary.json backlash)",
                c.t_begin, c.t_end, c.backlash, 100.0 * c.out_of_contact_fraction, c.impacts_per_revolution,
                c.peak_impact_torque);
  return buf;
}

}  // namespace

ToothContactSummary computeToothContact(const Scene& scene, const RunResult& run, const SteadyState& ss, bool steady) {
  ToothContactSummary c;
  c.verdict = "not applicable";
  c.backlash = scene.reducer.backlash;
  const CouplingLaw law = couplingLaw(scene);
  c.reason = notJudgedReason(scene, law, run.timeseries, ss, steady);
  if (!c.reason.empty()) return c;
  c.t_begin = ss.t_begin;
  c.t_end = ss.t_end;
  countImpacts(c, run.timeseries, ss, law.half_gap);
  c.impacts_per_revolution = c.revolutions > 0 ? c.impacts / c.revolutions : 0.0;
  c.verdict = c.out_of_contact_fraction > 0.0 || c.impacts > 0 ? "teeth separate" : "teeth stay in contact";
  if (c.verdict == "teeth separate") c.warnings.push_back(teethSeparateWarning(c));
  return c;
}

nlohmann::json toothContactJson(const ToothContactSummary& c) {
  using nlohmann::json;
  const bool judged = c.verdict != "not applicable";
  auto val = [judged](double v) { return judged ? json(v) : json(nullptr); };
  return {{"verdict", c.verdict},
          {"reason", c.reason.empty() ? json(nullptr) : json(c.reason)},
          {"backlash", c.backlash},
          {"t_begin", val(c.t_begin)},
          {"t_end", val(c.t_end)},
          {"revolutions", val(c.revolutions)},
          {"impacts", judged ? json(c.impacts) : json(nullptr)},
          {"impacts_per_revolution", val(c.impacts_per_revolution)},
          {"out_of_contact_fraction", val(c.out_of_contact_fraction)},
          {"peak_impact_torque", judged && c.impacts > 0 ? json(c.peak_impact_torque) : json(nullptr)}};
}

std::string toothContactText(const nlohmann::json& j) {
  if (!j.is_object() || !(j.value("backlash", 0.0) > 0.0) || !j["verdict"].is_string()) return "";
  const std::string verdict = j["verdict"].get<std::string>();
  char buf[512];
  if (verdict == "not applicable") {
    std::snprintf(buf, sizeof buf, "backlash     %.4g rad: n/a, %s\n", j.value("backlash", 0.0),
                  j["reason"].is_string() ? j["reason"].get<std::string>().c_str() : "");
    return buf;
  }
  auto num = [&j](const char* k) { return j[k].is_number() ? j[k].get<double>() : NAN; };
  std::snprintf(buf, sizeof buf,
                "backlash     %.4g rad: %s in the steady window: apart %.3g %% of the time, %.3g impacts per crank "
                "revolution, peak impact torque %.4g N·m at the crank axis\n",
                j.value("backlash", 0.0), verdict.c_str(), 100.0 * num("out_of_contact_fraction"),
                num("impacts_per_revolution"), num("peak_impact_torque"));
  return buf;
}

}  // namespace rollerdyn
