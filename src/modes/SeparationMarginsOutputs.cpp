#include <cstdio>
#include <sstream>

#include "analysis/SizingCheckJson.h"
#include "modes/SeparationMargins.h"
#include "io/FieldFormat.h"

namespace rollerdyn::modes {
namespace {

nlohmann::json marginJson(const SeparationMargin& m) {
  return {{"mode", m.mode},
          {"order", m.order},
          {"excitation_frequency", jsonNumber(m.excitation)},
          {"exciting_torque", jsonNumber(m.exciting_torque)},
          {"mode_frequency_low", jsonNumber(m.p_low)},
          {"mode_frequency_high", jsonNumber(m.p_high)},
          {"mode_frequency_source", m.frequency_source},
          {"undamped_frequency_low", jsonNumber(m.undamped_low)},
          {"undamped_frequency_high", jsonNumber(m.undamped_high)},
          {"margin", jsonNumber(m.margin)},
          {"damping_ratio", jsonNumber(m.damping_ratio)},
          {"amplification_factor", jsonNumber(m.amplification)},
          {"verdict", m.verdict},
          {"reason", m.reason}};
}

// The orders' rows and the verdict over them: FAIL if any fails, not applicable when none is judged.
void addOrdersJson(nlohmann::json& j, const SeparationMargins& s) {
  nlohmann::json rows = nlohmann::json::array();
  bool fail = false, judged = false;
  for (const SeparationMargin& m : s.rows) {
    fail = fail || m.verdict == "FAIL";
    judged = judged || m.verdict != "n/a";
    rows.push_back(marginJson(m));
  }
  j["orders"] = rows;
  j["verdict"] = !judged ? "not applicable" : fail ? "FAIL" : "pass";
  if (!judged) j["reason"] = "no order drives the coupling mode (every harmonic below 1 % of the largest)";
}

nlohmann::json startCrossingsJson(const SeparationMargins& s) {
  nlohmann::json sc = nlohmann::json::array();
  for (const StartCrossing& c : s.start_crossings) sc.push_back({{"order", c.order}, {"omega", c.omega}});
  return sc;
}

nlohmann::json checksJson(const SeparationMargins& s) {
  nlohmann::json checks = nlohmann::json::array();
  for (const SizingCheck& c : separationChecks(s)) checks.push_back(sizingCheckJson(c));
  return checks;
}

}  // namespace

nlohmann::json separationJson(const SeparationMargins& s) {
  nlohmann::json j;
  j["method"] = "separation margin SM = |p - k*omega|/(k*omega) of the natural frequency p of the coupling mode's damped pair "
                "(and of each crankshaft mode's frozen-angle band where the crankshaft is a torsional chain) "
                "from each order k that drives it, at the operating crank speed omega; required >= 10 % "
                "(API 617 / API 684 practice)";
  j["applicable"] = s.applicable;
  if (!s.applicable) {
    j["verdict"] = "not applicable";
    j["reason"] = s.not_applicable;
    j["checks"] = nlohmann::json::array({sizingCheckJson(separationChecks(s).front())});
    return j;
  }
  j["omega"] = s.omega;
  j["required"] = s.required;
  addOrdersJson(j, s);
  j["start_crossings"] = startCrossingsJson(s);
  j["checks"] = checksJson(s);
  j["start_crossings_note"] = "forced crossings p = k*omega below the operating speed within the Campbell diagram's "
                              "speed range, passed through in a start: a transient, judged by the start's torques";
  return j;
}

namespace {

// The mode's frequency, one value or a band.
std::string modeFrequencyText(const SeparationMargin& m) {
  char b[600];
  if (m.p_low == m.p_high)
    std::snprintf(b, sizeof b, "%.4g rad/s", m.p_low);
  else
    std::snprintf(b, sizeof b, "%.4g ... %.4g rad/s", m.p_low, m.p_high);
  return b;
}

// A heavy damper moves the damped pair's natural frequency away from the undamped one the
// Campbell diagram draws: name both then (empty otherwise).
std::string undampedText(const SeparationMargin& m) {
  if (!(std::abs(m.undamped_low / m.p_low - 1) > 0.01 || std::abs(m.undamped_high / m.p_high - 1) > 0.01)) return "";
  char b[600];
  std::snprintf(b, sizeof b, "; undamped %.4g ... %.4g rad/s, the Campbell diagram's", m.undamped_low, m.undamped_high);
  return b;
}

// A crankshaft mode's order line (its mode named above its first order).
void chainOrderText(std::ostringstream& os, const SeparationMargins& s, const SeparationMargin& m) {
  char b[600];
  if (&m == &s.rows.front() || (&m)[-1].mode != m.mode) os << "    " << m.mode << ":\n";
  std::snprintf(b, sizeof b, "      order %d: k*omega = %.4g rad/s, mode band p = %s (%s): SM = %.3g %%: %s\n", m.order,
                m.excitation, modeFrequencyText(m).c_str(), m.frequency_source.c_str(), 100 * m.margin,
                (m.verdict + (m.verdict == "pass" ? "" : ", " + m.reason)).c_str());
  os << b;
}

void couplingOrderText(std::ostringstream& os, const SeparationMargin& m) {
  char b[600];
  std::snprintf(b, sizeof b, "    order %d: k*omega = %.4g rad/s, mode p = %s (%s, damping ratio %.3g%s): SM = %.3g %%, AF = %.3g: %s\n",
                m.order, m.excitation, modeFrequencyText(m).c_str(), m.frequency_source.c_str(), m.damping_ratio,
                undampedText(m).c_str(), 100 * m.margin, m.amplification,
                (m.verdict == "n/a" ? "n/a, " + m.reason : m.verdict).c_str());
  os << b;
}

void startCrossingsText(std::ostringstream& os, const SeparationMargins& s) {
  if (s.start_crossings.empty()) return;
  char b[600];
  os << "    Campbell crossings passed through in a start (no verdict: a transient):";
  for (const StartCrossing& c : s.start_crossings) {
    std::snprintf(b, sizeof b, " p=%d*omega at %.4g rad/s;", c.order, c.omega);
    os << b;
  }
  os << "\n";
}

}  // namespace

std::string separationText(const SeparationMargins& s) {
  std::ostringstream os;
  char b[600];
  if (!s.applicable) {
    os << "  separation margins (API 617 / API 684, >= 10 %): n/a: " << s.not_applicable << "\n";
    return os.str();
  }
  bool judged = false;
  for (const SeparationMargin& m : s.rows) judged = judged || m.verdict != "n/a";
  if (!judged) {
    os << "  separation margins (API 617 / API 684, >= 10 %): n/a: no order drives the coupling mode\n";
    return os.str();
  }
  std::snprintf(b, sizeof b, "  separation margins at omega = %.4g rad/s (SM = |p - k*omega|/(k*omega), >= 10 %%, API 617 / API 684):\n",
                s.omega);
  os << b;
  for (const SeparationMargin& m : s.rows) {
    if (m.mode != "coupling mode")
      chainOrderText(os, s, m);
    else
      couplingOrderText(os, m);
  }
  startCrossingsText(os, s);
  return os.str();
}

}  // namespace rollerdyn::modes
