#include "modes/RunModes.h"

#include <cmath>

#include "io/AtomicFile.h"

namespace rollerdyn::modes {

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

RunModal analyseRunModes(const Scene& scene, const RunResult& run, bool charts, PhaseClock* clock) {
  ModesOptions o;
  o.clock = clock;
  o.charts = charts;
  o.chart_c = 12;
  o.chart_y = 8;
  RunModal m;
  m.report = analyseModes(scene, o);
  m.spectrum = runSpectrum(scene, run);
  markPhase(clock, "modes: order spectrum of the run");
  return m;
}

std::string runStabilityNotApplicable(const nlohmann::json& summary) {
  if (!summary.contains("stability") || !summary["stability"].is_object()) return "";
  const nlohmann::json& s = summary["stability"];
  if (s.value("verdict", "") != "not applicable") return "";
  return s.value("reason", "no steady motion");
}

namespace {

// summary.json's order_spectrum: the window, and per signal its mean, strongest orders and the
// share of whole orders; the reason instead where there is no spectrum.
nlohmann::json orderSpectrumJson(const OrderSpectrum& spectrum) {
  if (!spectrum.ok) return {{"note", spectrum.note}};
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
  return sp;
}

}  // namespace

void addRunModes(const RunModal& modal, nlohmann::json& summary) {
  summary["modes"] = modesJson(modal.report);
  // A run without a steady motion: the analysis' stability verdict is not the run's.
  const std::string na = runStabilityNotApplicable(summary);
  if (!na.empty() && summary["modes"].contains("steady_motion")) {
    nlohmann::json& sm = summary["modes"]["steady_motion"];
    sm["verdict"] = "not applicable";
    sm["stable"] = nullptr;
    sm["not_applicable_reason"] = na;
    summary["modes"]["warnings"] = nlohmann::json::array();
  }
  summary["order_spectrum"] = orderSpectrumJson(modal.spectrum);
}

void writeRunModesFiles(const std::string& out_dir, const RunModal& modal, const nlohmann::json& modes_json) {
  const ModesReport& report = modal.report;
  writeFileAtomic(out_dir + "/modes.json", (modes_json.empty() ? modesJson(report) : modes_json).dump(2) + "\n");
  writeCsvAtomic(out_dir + "/frozen.csv", frozenTable(report));
  if (report.campbell.applicable) writeCsvAtomic(out_dir + "/campbell.csv", campbellTable(report));
  if (!report.charts.empty()) writeCsvAtomic(out_dir + "/stability.csv", stabilityTable(report));
  if (modal.spectrum.ok) writeCsvAtomic(out_dir + "/spectrum.csv", spectrumTable(modal.spectrum));
}

}  // namespace rollerdyn::modes
