#include "modes/RunModes.h"

#include <cmath>
#include <cstdio>

#include "io/AtomicFile.h"

namespace rollerdyn::modes {

namespace {

constexpr const char* kFirstEstimateLabel =
    "first estimate (two constant inertias, Dyomin (two rotors) eq. (10)): ";

// 1/|μ| in words an engineer reads: three significant digits, thousands separated below 1e9
// (269,542 -> "270,000"), else as a power of ten.
std::string foldOf(double modulus) {
  const double x = 1 / modulus;
  char b[64];
  if (!(x < 1e9)) {
    std::snprintf(b, sizeof b, "%.3g", x);
    return b;
  }
  const double scale = std::pow(10.0, std::floor(std::log10(x)) - 2);
  const double rounded = x >= 100 ? std::round(x / scale) * scale : x;
  if (x < 100) {
    std::snprintf(b, sizeof b, "%.3g", x);
    return b;
  }
  std::string digits = std::to_string(static_cast<long long>(std::llround(rounded)));
  for (int i = int(digits.size()) - 3; i > 0; i -= 3) digits.insert(size_t(i), ",");
  return digits;
}

// The coupling mode's damping ratio the verdict rests on: Floquet's where its multiplier is resolved,
// else the frozen-angle mean (the Floquet multiplier is then below 1e-6: heavily damped).
double verdictDampingRatio(const ModesReport& r, bool* from_floquet) {
  const FloquetVerdict& v = r.steady.verdict;
  *from_floquet = v.has_torsional && v.torsional_resolved && std::isfinite(v.torsional_damping_ratio);
  return *from_floquet ? v.torsional_damping_ratio : r.frozen[0].torsional_damping.mean;
}

// Why the coupling mode is not in resonance, every word from the analysis' numbers: where its
// frequency lies against the orders the layout excites (the list `modes` prints), its damping ratio
// and what that does to a forced response, and how fast disturbances die out.
std::string conclusion(const ModesReport& r) {
  const Band& p = r.frozen[0].torsional;
  const double w = r.steady.omega_mean;
  const double ratio = p.mean / w;
  // The layout's orders just below and above p (mean over the crank angle).
  int below = 0, above = 0;
  for (int k : r.orders.layout) {
    if (k <= ratio && k > below) below = k;
    if (k > ratio && (above == 0 || k < above)) above = k;
  }
  auto off = [&](int k) {
    char f[96];
    const double d = 100 * (ratio / k - 1);
    std::snprintf(f, sizeof f, "%.2g %% %s order %d", std::abs(d), d >= 0 ? "above" : "below", k);
    return std::string(f);
  };
  std::string where;
  if (below && above) {
    // the nearer one first
    const bool lower_first = ratio / below - 1 <= 1 - ratio / above;
    where = (lower_first ? off(below) + " and " + off(above) : off(above) + " and " + off(below)) +
            ", the nearest orders the layout excites";
  } else if (above) {
    where = off(above) + ", the lowest order the layout excites";
  } else if (below) {
    where = off(below) + ", the highest order the layout excites up to order 24";
  } else {
    where = "clear of every order (the layout excites none up to order 24)";
  }
  bool floquet_zeta = false;
  const double zeta = verdictDampingRatio(r, &floquet_zeta);
  char z[256];
  if (zeta >= 1)
    std::snprintf(z, sizeof z, "it does not oscillate (%s: over-damped), so a forced response has no resonance peak",
                  floquet_zeta ? "Floquet" : "frozen-angle");
  else if (zeta >= 1 / std::sqrt(2.0))
    std::snprintf(z, sizeof z,
                  "its damping ratio %.2g (%s) is above 1/sqrt(2) = 0.71, where a forced response has no resonance peak",
                  zeta, floquet_zeta ? "Floquet" : "frozen-angle mean");
  else
    std::snprintf(z, sizeof z,
                  "its damping ratio %.2g (%s) limits a forced response at resonance to 1/(2*zeta*sqrt(1 - zeta^2)) = "
                  "%.3g times the static one",
                  zeta, floquet_zeta ? "Floquet" : "frozen-angle mean", 1 / (2 * zeta * std::sqrt(1 - zeta * zeta)));
  const FloquetVerdict& v = r.steady.verdict;
  std::string decay;
  if (v.has_torsional && v.torsional_resolved) {
    // With heavy damping the mode no longer oscillates at p: its natural frequency from the
    // multipliers is √(σ² + ω_d²) (where a forced response peaks, as the warnings compare it).
    const double sigma = std::log(v.torsional_modulus) / r.steady.period;
    const double pf = std::hypot(sigma, v.torsional_frequency);
    char f[300];
    std::snprintf(f, sizeof f,
                  "; from the Floquet multipliers, with the motor's slope and the coupling's damping, the mode "
                  "oscillates at %.4g rad/s (damped) about an undamped natural frequency of %.4g rad/s (%.3g times "
                  "the crank speed), and it decays %s-fold per revolution",
                  v.torsional_frequency, pf, pf / w, foldOf(v.torsional_modulus).c_str());
    decay = f;
  } else if (v.has_torsional) {
    decay = "; the coupling mode decays more than a million-fold per revolution (its multiplier is below 1e-6, too "
            "small to resolve)";
  }
  char b[1400];
  if (v.stable)
    std::snprintf(b, sizeof b,
                  "no torsional resonance at omega = %.4g rad/s: the coupling mode's frozen-angle frequency p = %.4g ... "
                  "%.4g rad/s (p/omega = %.3g on the mean) lies %s; %s%s; the steady motion is stable, every "
                  "disturbance decays at least %s-fold per revolution (largest Floquet multiplier %.3g)",
                  w, p.min, p.max, ratio, where.c_str(), z, decay.c_str(), foldOf(v.max_modulus).c_str(),
                  v.max_modulus);
  else
    std::snprintf(b, sizeof b,
                  "no forced torsional resonance at omega = %.4g rad/s: the coupling mode's frozen-angle frequency "
                  "p = %.4g ... %.4g rad/s (p/omega = %.3g on the mean) lies %s; %s%s; but the steady motion is %s "
                  "(largest Floquet multiplier %.3g per revolution)",
                  w, p.min, p.max, ratio, where.c_str(), z, decay.c_str(), v.text.c_str(), v.max_modulus);
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
  // The orders the verdict names: those the layout excites (the list `modes` prints); the orders
  // measured in J_n2 and the load torque (load-shape harmonics included) beside them.
  j["excitation_orders"] = r.orders.layout;
  j["measured_orders"] = r.orders.all;
  j["floquet_verdict"] = r.steady.verdict.text;
  j["max_multiplier_modulus"] = r.steady.verdict.max_modulus;
  j["torsional_multiplier_modulus"] =
      r.steady.verdict.has_torsional ? num(r.steady.verdict.torsional_modulus) : nlohmann::json(nullptr);
  {
    bool floquet_zeta = false;
    j["damping_ratio"] = num(verdictDampingRatio(r, &floquet_zeta));
    j["damping_ratio_source"] = floquet_zeta ? "Floquet multipliers" : "frozen-angle mean (Floquet multiplier below 1e-6)";
  }
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
