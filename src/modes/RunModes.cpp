#include "modes/RunModes.h"

#include <cmath>
#include <cstdio>

#include "io/AtomicFile.h"

namespace rollerdyn::modes {

namespace {

constexpr const char* kFirstEstimateLabel =
    "first estimate (two constant inertias, Dyomin (two rotors) eq. (10)): ";

// Why the coupling mode is not in resonance: the excitation orders just below and above its band.
std::string conclusion(const ModesReport& r) {
  char b[640];
  const Band& p = r.frozen[0].torsional;
  const double w = r.steady.omega_mean;
  int below = 0, above = 0, inside = 0;
  for (int k : r.orders.all) {
    if (k * w < p.min && k > below) below = k;
    if (k * w > p.max && (above == 0 || k < above)) above = k;
    if (k * w >= p.min && k * w <= p.max && inside == 0) inside = k;
  }
  std::string between;
  if (inside)  // the order meets the band: only the mode's damping keeps it from resonating
    between = "around excitation order " + std::to_string(inside) + ", which it meets, but the mode is too strongly "
              "damped to resonate";
  else if (below && above)
    between = "between the excitation orders " + std::to_string(below) + " and " + std::to_string(above);
  else if (above)
    between = "below the lowest excitation order " + std::to_string(above);
  else if (below)
    between = "above the excitation orders up to " + std::to_string(below);
  const FloquetVerdict& v = r.steady.verdict;
  std::string floquet;
  if (v.has_torsional && v.torsional_resolved) {
    char f[160];
    std::snprintf(f, sizeof f, "; its Floquet frequency is %.4g rad/s (%.3g times the crank speed)", v.torsional_frequency,
                  v.torsional_frequency / w);
    floquet = f;
  } else if (v.has_torsional) {
    floquet = "; it decays more than a million-fold per revolution";
  }
  std::snprintf(b, sizeof b,
                "no torsional resonance at omega = %.4g rad/s: the coupling mode's frozen-angle frequency p = %.4g ... "
                "%.4g rad/s (%.3g ... %.3g times the crank speed) lies %s%s, and the steady motion is %s (largest "
                "Floquet multiplier %.3g per revolution)",
                w, p.min, p.max, p.min / w, p.max / w, between.c_str(), floquet.c_str(), v.text.c_str(), v.max_modulus);
  return b;
}

nlohmann::json num(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

}  // namespace

std::vector<std::string> writeResonanceVerdict(const Scene& scene, nlohmann::json& summary,
                                               const std::vector<std::string>& first_estimate,
                                               const ModesReport* analysis) {
  std::vector<std::string> lines;
  if (!summary.contains("warnings") || !summary["warnings"].is_array()) summary["warnings"] = nlohmann::json::array();
  // Relabel the first estimate's warnings where they stand.
  for (auto& w : summary["warnings"])
    for (const std::string& f : first_estimate)
      if (w.is_string() && w.get<std::string>() == f) w = kFirstEstimateLabel + f;
  for (const std::string& f : first_estimate) lines.push_back(kFirstEstimateLabel + f);
  if (summary.contains("resonance") && summary["resonance"].is_object())
    summary["resonance"]["method"] =
        "first estimate: two constant inertias (Dyomin (two rotors) eq. (10), crank side at its mean inertia); "
        "the verdict is resonance_modal";
  if (scene.coupling.type != CouplingType::Elastic) {
    summary["resonance_modal"] = {{"applicable", false}, {"note", "rigid coupling: no torsional mode"}};
    return lines;
  }
  ModesReport light;
  if (!analysis) {
    ModesOptions o;
    o.multibody = false;
    o.campbell = false;
    o.charts = false;
    o.angles = 36;
    light = analyseModes(scene, o);
    analysis = &light;
  }
  const ModesReport& r = *analysis;
  nlohmann::json j;
  j["method"] = "drive linearized about its steady motion: frozen-angle band of the coupling mode against the "
                "layout's excitation orders, Floquet multipliers over one crank revolution (reduced model)";
  j["applicable"] = r.steady.found && !r.frozen.empty();
  if (!r.steady.found) {
    // Never silent: the analysis' own warning (a driven machine), or, beside a first-estimate
    // warning, a verdict line saying that the first estimate stands unchecked.
    j["note"] = "no steady motion: " + r.steady.failure;
    j["warnings"] = r.warnings;
    summary["resonance_modal"] = j;
    for (const std::string& w : r.warnings) {
      summary["warnings"].push_back(w);
      lines.push_back(w);
    }
    if (!first_estimate.empty())
      lines.push_back("resonance verdict: the modal analysis could not be made (no steady motion: " + r.steady.failure +
                      "); the first estimate above is unchecked");
    return lines;
  }
  const Band& p = r.frozen[0].torsional;
  j["omega"] = r.steady.omega_mean;
  j["p_band"] = {{"mean", num(p.mean)}, {"min", num(p.min)}, {"max", num(p.max)}};
  j["excitation_orders"] = r.orders.all;
  j["floquet_verdict"] = r.steady.verdict.text;
  j["max_multiplier_modulus"] = r.steady.verdict.max_modulus;
  j["warnings"] = r.warnings;
  if (r.warnings.empty()) j["conclusion"] = conclusion(r);
  summary["resonance_modal"] = j;
  for (const std::string& w : r.warnings) {
    summary["warnings"].push_back(w);
    lines.push_back(w);
  }
  // The first estimate warned and the analysis does not: say so, so the two never stand unreconciled.
  if (!first_estimate.empty() && r.warnings.empty()) lines.push_back("resonance verdict: " + conclusion(r));
  return lines;
}

OrderSpectrum runSpectrum(const Scene& scene, const RunResult& run) {
  const double window = scene.simulation.steady_window_revolutions;
  OrderSpectrum s = orderSpectrum(run.timeseries, run.timeseries, {"coupling_torque", "motor_torque"}, window);
  if (!run.reactions.columns.empty() && s.ok) {
    std::vector<std::string> cols;
    for (const std::string& c : run.reactions.columns)
      if (c != "t" && c != "coupling_torque") cols.push_back(c);
    const OrderSpectrum r = orderSpectrum(run.timeseries, run.reactions, cols, window);
    if (r.ok && r.orders.size() == s.orders.size())
      for (size_t i = 0; i < r.signals.size(); ++i) {
        s.signals.push_back(r.signals[i]);
        s.amplitude.push_back(r.amplitude[i]);
        s.peaks.push_back(r.peaks[i]);
        s.whole_order_share.push_back(r.whole_order_share[i]);
      }
  }
  return s;
}

RunModal analyseRunModes(const Scene& scene, const RunResult& run, bool charts) {
  ModesOptions o;
  o.charts = charts;
  o.chart_c = 12;
  o.chart_y = 8;
  RunModal m;
  m.report = analyseModes(scene, o);
  m.spectrum = runSpectrum(scene, run);
  return m;
}

void addRunModes(const RunModal& modal, nlohmann::json& summary) {
  summary["modes"] = modesJson(modal.report);
  const OrderSpectrum& spectrum = modal.spectrum;
  if (spectrum.ok) {
    nlohmann::json sp;
    sp["revolutions"] = spectrum.revolutions;
    sp["window"] = {spectrum.t_begin, spectrum.t_end};
    for (size_t i = 0; i < spectrum.signals.size(); ++i) {
      nlohmann::json peaks = nlohmann::json::array();
      for (const SpectrumPeak& p : spectrum.peaks[i]) peaks.push_back({{"order", p.order}, {"amplitude", p.amplitude}});
      sp["signals"][spectrum.signals[i]] = {{"mean", spectrum.amplitude[i][0]},
                                            {"peaks", peaks},
                                            {"whole_order_share", spectrum.whole_order_share[i]}};
    }
    summary["order_spectrum"] = sp;
  } else {
    summary["order_spectrum"] = {{"note", spectrum.note}};
  }
}

void writeRunModesFiles(const std::string& out_dir, const RunModal& modal) {
  const ModesReport& report = modal.report;
  writeFileAtomic(out_dir + "/modes.json", modesJson(report).dump(2) + "\n");
  writeCsvAtomic(out_dir + "/frozen.csv", frozenTable(report));
  if (report.campbell.applicable) writeCsvAtomic(out_dir + "/campbell.csv", campbellTable(report));
  if (!report.charts.empty()) writeCsvAtomic(out_dir + "/stability.csv", stabilityTable(report));
  if (modal.spectrum.ok) writeCsvAtomic(out_dir + "/spectrum.csv", spectrumTable(modal.spectrum));
}

}  // namespace rollerdyn::modes
