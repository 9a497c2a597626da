#include "studies/IdentifyOutputs.h"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "io/AtomicFile.h"
#include "io/FieldFormat.h"
#include "report/Gnuplot.h"
#include "report/HtmlReport.h"

namespace rollerdyn {

namespace {

nlohmann::json numbers(const std::vector<double>& v) {
  nlohmann::json a = nlohmann::json::array();
  for (double x : v) a.push_back(jsonNumber(x));
  return a;
}

std::string g(double v, int digits = 4) {
  if (!std::isfinite(v)) return std::isinf(v) ? "inf" : "n/a";
  return significant(v, digits);
}

std::string pad(const std::string& s, std::size_t width) {
  // widths in characters of ASCII text; a unit with · or Ω counts its bytes, a little wider
  return s.size() >= width ? s + " " : s + std::string(width - s.size(), ' ');
}

nlohmann::json keyJson(const IdentifiedKey& k) {
  return {{"key", k.key},
          {"unit", k.unit},
          {"value", jsonNumber(k.value)},
          {"text", k.text},
          {"std", jsonNumber(k.std)},
          {"relative_std", jsonNumber(k.relative_std)},
          {"start", jsonNumber(k.start)},
          {"lower", k.lower},
          {"upper", k.upper},
          {"bounds_from", k.bounds_from},
          {"log_scale", k.log_scale},
          {"at_bound", k.at_bound}};
}

nlohmann::json signalJson(const SignalFit& s) {
  return {{"column", s.name},
          {"unit", s.unit},
          {"sigma", jsonNumber(s.sigma)},
          {"sigma_from", s.sigma_from},
          {"rms_fit", jsonNumber(s.rms_fit)},
          {"rms_holdout", jsonNumber(s.rms_holdout)},
          {"data_rms", jsonNumber(s.data_rms)},
          {"integration_error", jsonNumber(s.integration_error)},
          {"samples_fit", s.samples_fit},
          {"samples_holdout", s.samples_holdout}};
}

nlohmann::json correlationJson(const IdentifyResult& r) {
  nlohmann::json names = nlohmann::json::array(), matrix = nlohmann::json::array();
  for (const IdentifiedKey& k : r.keys) names.push_back(k.key);
  for (const auto& row : r.correlation) matrix.push_back(numbers(row));
  return {{"keys", names}, {"matrix", matrix}};
}

nlohmann::json fitJson(const IdentifyOptions& o, const IdentifyResult& r) {
  return {{"residuals", r.residuals},
          {"rss", jsonNumber(r.rss)},
          {"sigma_hat2", jsonNumber(r.sigma_hat2)},
          {"condition", jsonNumber(r.condition)},
          {"weakest_direction", numbers(r.weakest_direction)},
          {"t_fit_end", r.t_fit_end},
          {"t_end", r.t_end},
          {"holdout", o.holdout}};
}

nlohmann::json convergenceJson(const IdentifyResult& r) {
  return {{"converged", r.converged},     {"reason", r.convergence},
          {"iterations", r.iterations},   {"runs", r.runs},
          {"failed_runs", r.failed_runs}, {"accuracy", r.accuracy},
          {"output_step", r.output_step}, {"wall_seconds", jsonNumber(r.wall_seconds)}};
}

}  // namespace

nlohmann::json identifyJson(const IdentifyOptions& o, const IdentifyResult& r) {
  nlohmann::json j;
  j["scene"] = r.scene;
  j["model"] = r.model;
  j["data"] = r.data_file;
  j["base_overrides"] = o.base_overrides;
  j["keys"] = nlohmann::json::array();
  for (const IdentifiedKey& k : r.keys) j["keys"].push_back(keyJson(k));
  j["correlation"] = correlationJson(r);
  j["signals"] = nlohmann::json::array();
  for (const SignalFit& s : r.signals) j["signals"].push_back(signalJson(s));
  j["warnings"] = nlohmann::json::array();
  for (const IdentifyWarning& w : r.warnings)
    j["warnings"].push_back({{"kind", w.kind}, {"keys", w.keys}, {"value", jsonNumber(w.value)}, {"text", w.text}});
  j["fit"] = fitJson(o, r);
  j["convergence"] = convergenceJson(r);
  return j;
}

namespace {

// Signal s measured and modelled over time; the dashed line ends the fitted part.
PlotSpec signalFitPlot(const IdentifyOptions& o, const IdentifyResult& r, std::size_t s, const std::string& fit_end) {
  const SignalFit& f = r.signals[s];
  PlotSpec fit;
  fit.title = escapeUnderscores("measured and identified model: " + f.name +
                                (o.holdout > 0 ? " (fitted left of the dashed line, predicted right)" : ""));
  fit.xlabel = "t [s]";
  fit.ylabel = escapeUnderscores(f.name) + " [" + f.unit + "]";
  fit.preamble = fit_end;
  PlotSeries measured{"measured", r.t, r.data_values[s], "points"};
  PlotSeries model{"model at the estimate", r.t, r.model_values[s], "lines"};
  model.line_width = 1.5;
  fit.series = {measured, model};
  return fit;
}

// Signal s's residuals, model minus measured, with its noise σ in the title.
PlotSpec signalResidualPlot(const IdentifyResult& r, std::size_t s, const std::string& fit_end) {
  const SignalFit& f = r.signals[s];
  PlotSpec res;
  res.title = escapeUnderscores("residual model - measured: " + f.name + " (σ = " + g(f.sigma) + " " + f.unit + ")");
  res.xlabel = "t [s]";
  res.ylabel = escapeUnderscores("model - measured, " + f.name) + " [" + f.unit + "]";
  res.preamble = fit_end;
  std::vector<double> diff(r.t.size());
  for (std::size_t i = 0; i < r.t.size(); ++i) diff[i] = r.model_values[s][i] - r.data_values[s][i];
  res.series = {PlotSeries{"residual", r.t, diff, "points"}};
  return res;
}

// Draws the fit and the residuals of every signal; returns why there are no figures ("": there are),
// `plots` the PNGs drawn.
std::string drawIdentifyFigures(const IdentifyOptions& o, const IdentifyResult& r, const std::string& out_dir,
                                std::vector<std::string>* plots) {
  if (r.model_values.empty()) return "no figures: no run at the estimate over the whole span";
  if (!gnuplotAvailable()) return "no figures: gnuplot not found on PATH";
  try {
    const std::string fit_end = "set arrow from " + std::to_string(r.t_fit_end) + ", graph 0 to " +
                                std::to_string(r.t_fit_end) + ", graph 1 nohead dashtype 2\n"
                                "set key below";
    std::vector<PlotJob> jobs;
    for (std::size_t s = 0; s < r.signals.size(); ++s) {
      const std::string& name = r.signals[s].name;
      jobs.push_back(plotJob(signalFitPlot(o, r, s, fit_end), out_dir + "/fit_" + name));
      jobs.push_back(plotJob(signalResidualPlot(r, s, fit_end), out_dir + "/residual_" + name));
      plots->push_back(out_dir + "/fit_" + name + ".png");
      plots->push_back(out_dir + "/residual_" + name + ".png");
    }
    renderPlots(jobs);
  } catch (const std::exception& e) {
    plots->clear();
    return std::string("plotting failed: ") + e.what();
  }
  return "";
}

// The page an engineer opens: the console's tables (one rendering of the result) and, per signal,
// the fit against the data and the residuals.
std::string identifyPage(const IdentifyOptions& o, const IdentifyResult& r, const std::string& plot_note,
                         bool with_figures) {
  std::ostringstream h;
  h << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>Identification: "
    << htmlEscape(r.scene) << "</title>\n<style>body{font-family:sans-serif;max-width:1000px;margin:1em auto}"
       "pre{background:#f6f6f6;padding:0.6em;overflow-x:auto}img{max-width:100%}</style></head><body>\n"
    << "<h1>Identification of " << htmlEscape(r.scene) << " from " << htmlEscape(r.data_file) << "</h1>\n"
    << "<p>" << htmlEscape(r.model) << " model; estimates with their standard uncertainty from the Jacobian at the "
       "estimate (σ̂²·(JᵀJ)⁻¹), the last part of the record "
    << (o.holdout > 0 ? "predicted, not fitted (right of the dashed line in the figures)" : "fitted too (no hold-out)")
    << "; method and warnings: docs/identify.md.</p>\n<pre>" << htmlEscape(describeIdentify(r)) << "</pre>\n";
  if (!plot_note.empty()) h << "<p>" << htmlEscape(plot_note) << "</p>\n";
  for (const SignalFit& f : r.signals)
    if (with_figures)
      h << "<h2>" << htmlEscape(f.name) << " [" << htmlEscape(f.unit) << "]</h2>\n<img src=\"fit_" << htmlEscape(f.name)
        << ".svg\" alt=\"measured and model: " << htmlEscape(f.name) << "\">\n<img src=\"residual_"
        << htmlEscape(f.name) << ".svg\" alt=\"residuals: " << htmlEscape(f.name) << "\">\n";
  h << "</body></html>\n";
  return h.str();
}

}  // namespace

std::vector<std::string> writeIdentifyOutputs(const IdentifyOptions& o, const IdentifyResult& r,
                                              const std::string& out_dir, std::string* plot_note_out) {
  std::vector<std::string> plots;
  const std::string plot_note = drawIdentifyFigures(o, r, out_dir, &plots);
  nlohmann::json j = identifyJson(o, r);
  j["plots"] = plots;
  j["plot_note"] = plot_note;
  if (plot_note_out) *plot_note_out = plot_note;
  writeFileAtomic(out_dir + "/identify.json", j.dump(2) + "\n");
  writeFileAtomic(out_dir + "/identify.html", identifyPage(o, r, plot_note, !plots.empty()));
  std::vector<std::string> files = plots;
  files.push_back(out_dir + "/identify.json");
  files.push_back(out_dir + "/identify.html");
  return files;
}

namespace {

void keysTable(const IdentifyResult& r, std::ostringstream& out) {
  out << pad("key", 28) << pad("estimate", 14) << pad("std", 12) << pad("rel. std", 10) << pad("start", 12)
      << "bounds\n";
  for (const IdentifiedKey& k : r.keys)
    out << pad(k.key, 28) << pad(k.text, 14) << pad(g(k.std, 3), 12)
        << pad(std::isfinite(k.relative_std) ? g(100 * k.relative_std, 2) + " %" : g(k.relative_std), 10)
        << pad(g(k.start, 6), 12) << g(k.lower, 6) << ":" << g(k.upper, 6) << " " << k.unit
        << (k.log_scale ? " (log)" : "") << "\n";
}

void signalsTable(const IdentifyResult& r, std::ostringstream& out) {
  out << "\n" << pad("signal", 28) << pad("sigma", 14) << pad("RMS fitted", 12) << pad("RMS held out", 14) << "unit\n";
  for (const SignalFit& s : r.signals)
    out << pad(s.name, 28) << pad(g(s.sigma, 3) + (s.sigma_from == "given" ? " (given)" : ""), 14)
        << pad(g(s.rms_fit, 3), 12) << pad(g(s.rms_holdout, 3), 14) << s.unit << "\n";
}

void strongCorrelations(const IdentifyResult& r, std::ostringstream& out) {
  bool header = false;
  for (std::size_t a = 0; a < r.correlation.size(); ++a)
    for (std::size_t b = a + 1; b < r.correlation.size(); ++b)
      if (std::abs(r.correlation[a][b]) > 0.5 || !std::isfinite(r.correlation[a][b])) {
        if (!header) out << "\ncorrelations above 0.5:\n";
        header = true;
        out << "  " << r.keys[a].key << " / " << r.keys[b].key << ": " << g(r.correlation[a][b], 3) << "\n";
      }
}

}  // namespace

std::string describeIdentify(const IdentifyResult& r) {
  std::ostringstream out;
  keysTable(r, out);
  signalsTable(r, out);
  strongCorrelations(r, out);
  if (!r.warnings.empty()) out << "\n";
  for (const IdentifyWarning& w : r.warnings) out << "warning: " << w.text << "\n";
  out << "\n" << (r.converged ? "" : "NOT CONVERGED: ") << r.convergence << "; " << r.iterations << " iterations, "
      << r.runs << " runs (" << r.failed_runs << " failed), σ̂² = " << g(r.sigma_hat2, 3) << ", " << g(r.wall_seconds, 3)
      << " s\n";
  return out.str();
}

}  // namespace rollerdyn
