#include "studies/ResonanceCheck.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "analysis/RunMotion.h"
#include "reduced/ReducedModel.h"
#include "io/FieldFormat.h"

namespace rollerdyn {

double naturalFrequency(double c, double J1, double J2) {
  return std::sqrt(c * (J1 + J2) / (J1 * J2));  // Dyomin (two rotors) eq. (10)
}

double meanCrankSideInertia(const Scene& scene) { return modes::twoMassEstimate(ReducedModel(scene)).J2_mean; }

std::vector<ResonanceHit> resonanceHits(double p0, double omega, double tolerance, const std::vector<int>& orders) {
  std::vector<ResonanceHit> hits;
  const double w = std::abs(omega);
  if (!(w > 0) || !std::isfinite(w) || !std::isfinite(p0)) return hits;
  for (int k : orders) {
    const double ratio = p0 / (k * w);
    if (std::abs(ratio - 1.0) <= tolerance) hits.push_back({k, ratio});
  }
  return hits;
}

namespace {

std::string firstEstimateHitSentence(double p0, const ResonanceHit& h, double omega, double tolerance) {
  char buf[400];
  std::snprintf(buf, sizeof buf,
                "first estimate (two constant inertias, Dyomin (two rotors) eq. (10)): the coupling's natural frequency "
                "p0 = %.4g rad/s is within %.0f %% of order %d of the crank speed, %d*omega = %.4g rad/s at omega = "
                "%.4g rad/s (p0/(k*omega) = %.3f), an order that drives the coupling",
                p0, 100 * tolerance, h.harmonic, h.harmonic, h.harmonic * std::abs(omega), std::abs(omega), h.ratio);
  return buf;
}

ResonanceReport firstEstimate(const ReducedModel& model, double omega, const modes::ExcitationOrders& orders,
                              double tolerance) {
  ResonanceReport r;
  r.omega = omega;
  const modes::TwoMassEstimate t = modes::twoMassEstimate(model);
  r.J1 = t.J1;
  r.J2_mean = t.J2_mean;
  if (!t.applicable) return r;
  r.stiffness = t.stiffness;
  r.p0 = t.p0;
  r.orders = orders.forced;
  r.applicable = std::isfinite(omega) && std::abs(omega) > 0;
  if (!r.applicable) return r;
  r.hits = resonanceHits(r.p0, omega, tolerance, r.orders);
  for (const ResonanceHit& h : r.hits) r.sentences.push_back(firstEstimateHitSentence(r.p0, h, omega, tolerance));
  return r;
}

}  // namespace

ResonanceReport checkResonance(const Scene& scene, double omega, double tolerance) {
  const double w = std::isfinite(omega) && omega != 0 ? std::abs(omega) : 1.0;
  const ReducedModel model(scene);
  return firstEstimate(model, omega, modes::excitationOrders(model, w), tolerance);
}

RunState runStateOf(const nlohmann::json& s) {
  RunState r;
  if (s.contains("motion") && s["motion"].is_string()) r.motion = s["motion"].get<std::string>();
  if (s.contains("steady_state") && s["steady_state"].is_object())
    r.steady = s["steady_state"].value("reached", false);
  if (s.contains("omega_crank") && s["omega_crank"].is_object() && s["omega_crank"].contains("mean") &&
      s["omega_crank"]["mean"].is_number())
    r.omega = s["omega_crank"]["mean"].get<double>();
  return r;
}

namespace {

// Why a run has no steady motion to judge, and what to do ("" when it has one).
std::string noSteadyMotion(const Scene& scene, const RunState& st) {
  if (!scene.motor.enabled) return "no motor: the machine has no steady running to judge";
  if (st.motion == "stalled")
    return "the drive does not turn (the motor stalled; the status says why): it has no steady motion, so there is "
           "no resonance or stability to judge; make it start first";
  if (st.motion == "rocking")
    return "the drive does not turn (the crank rocks back and forth): it has no steady motion, so there is no "
           "resonance or stability to judge; make it start first";
  if (st.motion == "starting")
    return kStillStartingWords;
  if (st.motion == "at_rest" || st.motion == "coasting")
    return "the drive does not turn steadily (" + st.motion + "): no steady motion to judge";
  if (st.motion != "turning") return "the crank's motion is not known (" + st.motion + "): no steady motion to judge";
  if (!st.steady)
    return "steady state not reached: the run's mean crank speed is not yet the steady one; run longer "
           "(simulation.t_end)";
  if (!(std::isfinite(st.omega) && std::abs(st.omega) > 0)) return "no finite mean crank speed";
  return "";
}

std::string pct(double x) { return significant(x, 2); }

// 1/|μ| in words an engineer reads: three significant digits, thousands separated below 1e9
// (269,542 -> "270,000"), else as a power of ten.
std::string foldOf(double modulus) {
  const double x = 1 / modulus;
  if (!(x < 1e9) || x < 100) return significant(x, 3);
  const double scale = std::pow(10.0, std::floor(std::log10(x)) - 2);
  std::string digits = std::to_string(static_cast<long long>(std::llround(std::round(x / scale) * scale)));
  for (int i = int(digits.size()) - 3; i > 0; i -= 3) digits.insert(size_t(i), ",");
  return digits;
}

// The coupling mode's damping ratio the verdict rests on: Floquet's where its multiplier is resolved,
// else the frozen-angle mean (the Floquet multiplier is then below 1e-6: heavily damped).
double verdictDampingRatio(const modes::ModesReport& r, bool* from_floquet) {
  const modes::FloquetVerdict& v = r.steady.verdict;
  *from_floquet = v.has_torsional && v.torsional_resolved && std::isfinite(v.torsional_damping_ratio);
  return *from_floquet ? v.torsional_damping_ratio : r.frozen[0].torsional_damping.mean;
}

// Where p lies against the orders that drive the coupling mode, at ω.
std::string whereAmongOrders(double ratio, const std::vector<int>& orders) {
  int below = 0, above = 0;
  for (int k : orders) {
    if (k <= ratio && k > below) below = k;
    if (k > ratio && (above == 0 || k < above)) above = k;
  }
  auto off = [&](int k) {
    const double d = 100 * (ratio / k - 1);
    return pct(std::abs(d)) + " % " + (d >= 0 ? "above" : "below") + " order " + std::to_string(k);
  };
  const std::string which = "the nearest orders that drive the coupling (each at least 1 % of the largest harmonic of "
                            "the load and inertia torque)";
  if (below && above) {
    const bool lower_first = ratio / below - 1 <= 1 - ratio / above;  // the nearer one first
    return (lower_first ? off(below) + " and " + off(above) : off(above) + " and " + off(below)) + ", " + which;
  }
  if (above) return off(above) + ", the lowest order that drives the coupling";
  if (below) return off(below) + ", the highest order that drives the coupling up to order 24";
  return "clear of every order (none drives the coupling up to order 24)";
}

// What the coupling mode's damping ratio means for a forced response.
std::string dampingSentence(const modes::ModesReport& r) {
  bool floquet_zeta = false;
  const double zeta = verdictDampingRatio(r, &floquet_zeta);
  char z[300];
  if (zeta >= 1)
    std::snprintf(z, sizeof z, "it does not oscillate (%s damping ratio %.3g >= 1: overdamped), so a forced response "
                  "has no resonance peak", floquet_zeta ? "Floquet" : "frozen-angle", zeta);
  else if (zeta >= 1 / std::sqrt(2.0))
    std::snprintf(z, sizeof z,
                  "its damping ratio %.2g (%s) is above 1/sqrt(2) = 0.71, where a forced response has no resonance peak",
                  zeta, floquet_zeta ? "Floquet" : "frozen-angle mean");
  else
    std::snprintf(z, sizeof z,
                  "its damping ratio %.2g (%s) limits a forced response at resonance to 1/(2*zeta*sqrt(1 - zeta^2)) = "
                  "%.3g times the static one",
                  zeta, floquet_zeta ? "Floquet" : "frozen-angle mean", 1 / (2 * zeta * std::sqrt(1 - zeta * zeta)));
  return z;
}

// How the coupling mode oscillates and decays by the Floquet multipliers ("" without a coupling mode).
std::string floquetDecaySentence(const modes::ModesReport& r, double w) {
  const modes::FloquetVerdict& v = r.steady.verdict;
  if (v.has_torsional && v.torsional_resolved) {
    // With heavy damping the mode no longer oscillates at p: its natural frequency from the
    // multipliers is √(σ² + ω_d²) (where a forced response peaks, as the warnings compare it).
    const double sigma = std::log(v.torsional_modulus) / r.steady.period;
    const double pf = std::hypot(sigma, v.torsional_frequency);
    char f[320];
    std::snprintf(f, sizeof f,
                  "; from the Floquet multipliers, with the motor's slope and the coupling's damping, the mode "
                  "oscillates at %.4g rad/s (damped) about an undamped natural frequency of %.4g rad/s (%.3g times "
                  "the crank speed), and it decays %s-fold per revolution",
                  v.torsional_frequency, pf, pf / w, foldOf(v.torsional_modulus).c_str());
    return f;
  }
  if (v.has_torsional)
    return "; the coupling mode decays more than a million-fold per revolution (its multiplier is below 1e-6, too "
           "small to resolve)";
  return "";
}

// Why the coupling mode is not in resonance at ω, every word from the analysis' numbers.
std::string conclusionOf(const modes::ModesReport& r, double w, const modes::ExcitationOrders& orders) {
  const modes::Band& p = r.frozen[0].torsional;
  const double ratio = p.mean / w;
  const std::string where = whereAmongOrders(ratio, orders.forced);
  const std::string z = dampingSentence(r);
  const std::string decay = floquetDecaySentence(r, w);
  const modes::FloquetVerdict& v = r.steady.verdict;
  char b[1600];
  std::snprintf(b, sizeof b,
                "no torsional resonance at omega = %.4g rad/s: the coupling mode's frozen-angle frequency p = %.4g ... "
                "%.4g rad/s (p/omega = %.3g on the mean) lies %s; %s%s; the steady motion is %s, every disturbance "
                "decays at least %s-fold per revolution (largest Floquet multiplier %.3g)",
                w, p.min, p.max, ratio, where.c_str(), z.c_str(), decay.c_str(), v.text.c_str(),
                foldOf(v.max_modulus).c_str(), v.max_modulus);
  return b;
}

// The modal analysis for a run without one: reduced model, no Campbell diagram or charts.
modes::ModesReport lightAnalysis(const Scene& scene) {
  modes::ModesOptions o;
  o.multibody = false;
  o.campbell = false;
  o.charts = false;
  o.angles = 36;
  return modes::analyseModes(scene, o);
}

// A run without a steady motion: nothing to judge, the first estimate without a speed.
void markNoSteadyMotion(RunResonance* v, const ReducedModel& model, const std::string& no_steady) {
  v->reason = no_steady;
  v->verdict = "not applicable";
  v->first_estimate_status = "not applicable";
  v->stability = "not applicable";
  v->stability_reason = no_steady;
  v->first_estimate = firstEstimate(model, NAN, {}, kResonanceTolerance);
}

// A rigid coupling has no torsional mode; the speed mode's stability is judged only by a modal
// analysis made for the run (`analysed`).
void markRigidCoupling(RunResonance* v, bool analysed) {
  v->reason = "rigid coupling: no torsional mode";
  v->verdict = "not applicable";
  v->first_estimate_status = "not applicable";
  if (analysed) return;
  v->stability = "not assessed";
  v->stability_reason = "rigid coupling: the speed mode's stability is assessed by the modal analysis "
                        "(simulate --modes, report, rollerdyn modes)";
}

// The linearized drive has no steady motion: no stability, and the first estimate's hits stand unchecked.
void markAnalysisNotMade(RunResonance* v, const modes::ModesReport& r) {
  v->modal_note = "no steady motion of the linearized drive: " + r.steady.failure;
  v->stability = "not applicable";
  v->stability_reason = v->modal_note;
  if (!v->elastic) return;
  // The analysis could not be made: its own warning, and the first estimate's hits stand unchecked.
  v->warnings = r.warnings;
  for (const std::string& s : v->first_estimate.sentences)
    v->warnings.push_back(s + " (unchecked: " + v->modal_note + ")");
  v->first_estimate_status = v->first_estimate.hits.empty() ? "no order within 10 %" : "unchecked";
  v->verdict = v->first_estimate.hits.empty() ? "no hit" : "unchecked first estimate";
  if (!v->first_estimate.hits.empty())
    v->verdict_line = "resonance verdict: the modal analysis could not be made (" + v->modal_note +
                      "); the first estimate above is unchecked";
}

// The modal analysis' warnings give the verdict; without any, why there is no resonance.
void judgeByModalWarnings(RunResonance* v, const modes::ModesReport& r) {
  v->warnings = modes::modalWarnings(r, v->omega, v->orders);
  bool resonance = false;
  for (const std::string& w : v->warnings) resonance = resonance || w.find("resonance") != std::string::npos;
  v->verdict = v->warnings.empty() ? "no resonance" : resonance ? "resonance" : "unstable";
  if (v->warnings.empty()) v->conclusion = conclusionOf(r, v->omega, v->orders);
}

// The first estimate's hits, each in words, for the line that says the analysis refutes them.
std::string refutedHits(const RunResonance& v) {
  std::string hits;
  for (const ResonanceHit& h : v.first_estimate.hits) {
    char f[160];
    std::snprintf(f, sizeof f, "%sp0 = %.4g rad/s within 10 %% of %d*omega = %.4g rad/s", hits.empty() ? "" : "; ",
                  v.first_estimate.p0, h.harmonic, h.harmonic * v.omega);
    hits += f;
  }
  return hits;
}

// The first estimate against the modal analysis: no hit, refuted (with the verdict line) or confirmed.
void judgeFirstEstimate(RunResonance* v) {
  if (v->first_estimate.hits.empty()) {
    v->first_estimate_status = "no order within 10 %";
  } else if (v->warnings.empty()) {
    v->first_estimate_status = "refuted by the modal analysis";
    v->verdict_line = "resonance verdict: the modal analysis refutes the first estimate (two constant inertias, Dyomin "
                      "(two rotors) eq. (10): " + refutedHits(*v) + "): " + v->conclusion;
  } else {
    v->first_estimate_status = "confirmed by the modal analysis";
  }
}

// The verdict by the modal analysis (the one made for the run, else a light one): stability from
// its Floquet multipliers; for an elastic coupling its warnings and the first estimate against them.
void judgeByModalAnalysis(RunResonance* v, const Scene& scene, const modes::ModesReport* analysis) {
  v->modal = std::make_shared<const modes::ModesReport>(analysis ? *analysis : lightAnalysis(scene));
  const modes::ModesReport& r = *v->modal;
  v->modal_made = r.steady.found && !r.frozen.empty() && r.frozen[0].ok;
  if (!v->modal_made) {
    markAnalysisNotMade(v, r);
    return;
  }
  v->analysis_omega = r.steady.omega_mean;
  v->stability = r.steady.verdict.text;
  v->max_multiplier_modulus = r.steady.verdict.max_modulus;
  v->stability_reason = "Floquet multipliers of the drive linearized about its steady motion (reduced model)";
  if (!v->elastic) return;
  judgeByModalWarnings(v, r);
  judgeFirstEstimate(v);
}

}  // namespace

RunResonance judgeRunResonance(const Scene& scene, const RunState& st, const modes::ModesReport* analysis) {
  RunResonance v;
  v.elastic = scene.coupling.type == CouplingType::Elastic;
  const ReducedModel model(scene);  // the first estimate's inertias and the exciting orders
  const std::string no_steady = noSteadyMotion(scene, st);
  v.applicable = no_steady.empty();
  if (!v.applicable) {
    markNoSteadyMotion(&v, model, no_steady);
    return v;
  }
  v.omega = std::abs(st.omega);
  v.orders = modes::excitationOrders(model, v.omega);
  v.first_estimate = firstEstimate(model, v.omega, v.orders, kResonanceTolerance);
  if (!v.elastic) {
    markRigidCoupling(&v, analysis != nullptr);
    if (!analysis) return v;
  }
  judgeByModalAnalysis(&v, scene, analysis);
  return v;
}

namespace {


nlohmann::json firstEstimateJson(const RunResonance& v) {
  const ResonanceReport& r = v.first_estimate;
  if (!v.elastic) return {{"applicable", false}, {"note", "rigid coupling: no torsional mode"}};
  nlohmann::json hits = nlohmann::json::array();
  for (const ResonanceHit& h : r.hits) hits.push_back({{"harmonic", h.harmonic}, {"ratio", h.ratio}});
  nlohmann::json j = {{"applicable", r.applicable},
                      {"method", "first estimate: two constant inertias (Dyomin (two rotors) eq. (10), crank side at "
                                 "its mean inertia); the verdict is resonance_verdict"},
                      {"J1", jsonNumber(r.J1)},
                      {"J2_mean", jsonNumber(r.J2_mean)},
                      {"stiffness", jsonNumber(r.stiffness)},
                      {"p0", jsonNumber(r.p0)},
                      {"omega", jsonNumber(r.omega)},
                      {"p0_over_omega", jsonNumber(r.p0 / r.omega)},
                      {"tolerance", kResonanceTolerance},
                      {"harmonics_checked", r.orders},
                      {"harmonics_basis",
                       "the orders of the crank speed that drive the coupling mode at omega: harmonics of the load "
                       "torque plus the inertia torque J_n2'*omega^2/2 of at least 1 % of the largest"},
                      {"hits", hits},
                      {"status", v.first_estimate_status}};
  if (!v.applicable) j["note"] = v.reason;
  return j;
}

// The analysis' numbers the verdict rests on (the analysis was made, the coupling is elastic).
void putModalNumbers(const RunResonance& v, nlohmann::json& j) {
  const modes::ModesReport& r = *v.modal;
  const modes::Band& p = r.frozen[0].torsional;
  j["omega"] = v.omega;
  j["analysis_omega"] = jsonNumber(v.analysis_omega);
  j["p_band"] = {{"mean", jsonNumber(p.mean)}, {"min", jsonNumber(p.min)}, {"max", jsonNumber(p.max)}};
  // The orders the verdict names (the ones that drive the coupling mode at ω); the layout's and the
  // measured ones beside them.
  j["excitation_orders"] = v.orders.forced;
  j["excitation_threshold"] = "at least 1 % of the largest harmonic of the load torque plus J_n2'*omega^2/2";
  j["layout_orders"] = v.orders.layout;
  j["measured_orders"] = v.orders.all;
  j["floquet_verdict"] = r.steady.verdict.text;
  j["max_multiplier_modulus"] = r.steady.verdict.max_modulus;
  j["torsional_multiplier_modulus"] =
      r.steady.verdict.has_torsional ? jsonNumber(r.steady.verdict.torsional_modulus) : nlohmann::json(nullptr);
  bool floquet_zeta = false;
  j["damping_ratio"] = jsonNumber(verdictDampingRatio(r, &floquet_zeta));
  j["damping_ratio_source"] = floquet_zeta ? "Floquet multipliers" : "frozen-angle mean (Floquet multiplier below 1e-6)";
  j["warnings"] = v.warnings;
  if (!v.conclusion.empty()) j["conclusion"] = v.conclusion;
}

nlohmann::json modalJson(const RunResonance& v) {
  nlohmann::json j;
  j["method"] = "drive linearized about its steady motion: frozen-angle band of the coupling mode against the orders "
                "that drive it, Floquet multipliers over one crank revolution (reduced model)";
  j["applicable"] = v.applicable && v.elastic && v.modal_made;
  if (!v.elastic) {
    j["note"] = "rigid coupling: no torsional mode";
    return j;
  }
  if (!v.applicable) {
    j["note"] = v.reason;
    j["warnings"] = nlohmann::json::array();
    return j;
  }
  if (!v.modal_made) {
    j["note"] = v.modal_note;
    j["warnings"] = v.modal ? v.modal->warnings : std::vector<std::string>{};
    return j;
  }
  putModalNumbers(v, j);
  return j;
}

}  // namespace

void putRunResonance(const RunResonance& v, nlohmann::json& summary) {
  if (!summary.contains("warnings") || !summary["warnings"].is_array()) summary["warnings"] = nlohmann::json::array();
  summary["resonance"] = firstEstimateJson(v);
  summary["resonance_modal"] = modalJson(v);
  std::string reason = v.reason;
  if (v.verdict == "no resonance") reason = v.conclusion;
  else if (!v.warnings.empty()) reason = v.warnings.front();
  summary["resonance_verdict"] = {{"verdict", v.verdict},
                                  {"omega", jsonNumber(v.omega)},
                                  {"reason", reason},
                                  {"first_estimate", v.first_estimate_status},
                                  {"line", v.verdict_line}};
  summary["stability"] = {{"verdict", v.stability},
                          {"reason", v.stability_reason},
                          {"max_multiplier_modulus", jsonNumber(v.max_multiplier_modulus)}};
  for (const std::string& w : v.warnings) summary["warnings"].push_back(w);
}

}  // namespace rollerdyn
