// The files of `rollerdyn bench`'s studies (BenchStudies.h): each study's CSV, its figures
// (through gnuplot; a figure that cannot be drawn is a note on the page) and its markdown page.
#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "bench/BenchStudies.h"
#include "bench/BenchText.h"
#include "io/AtomicFile.h"
#include "report/Gnuplot.h"

namespace rollerdyn::bench {

namespace {

PlotSeries series(const std::string& title, const std::string& style) {
  PlotSeries s;
  s.title = title;
  s.style = style;
  return s;
}

// Draws a figure; a missing or failing gnuplot is reported in the returned note, not thrown, so
// the CSV and markdown are still written.
std::string tryPlot(const PlotSpec& spec, const std::string& base, std::vector<std::string>& written) {
  try {
    renderPlot(spec, base);
    written.push_back(base + ".png");
    written.push_back(base + ".svg");
    return "";
  } catch (const std::exception& ex) {
    return std::string("\nFigure not drawn: ") + ex.what() + "\n";
  }
}


// Error against CPU time, one line per model and integrator: of the crank speed, or of the
// coupling torque.
PlotSpec workPrecisionFigure(const Scene& scene, const std::vector<BenchRow>& rows, bool coupling) {
  PlotSpec spec;
  spec.title = scene.name + ": work-precision, " + (coupling ? "coupling torque" : "crank speed") +
               (scene.simulation.reactions ? "" : " (without joint reactions)");
  spec.xlabel = "CPU time [s]";
  spec.ylabel = coupling ? "max |M_{c} - M_{c,ref}| / max |M_{c,ref}| [-]" : "max |ω - ω_{ref}| / max |ω_{ref}| [-]";
  spec.logx = spec.logy = true;
  std::map<std::string, size_t> line_of;
  for (const BenchRow& r : rows) {
    const double e = coupling ? r.error_coupling : r.error_omega;
    if (r.reference || !usable(r.m.outcome) || !std::isfinite(e)) continue;
    const std::string title = r.m.setting.model + " " + r.m.setting.integrator;
    if (!line_of.count(title)) {
      line_of[title] = spec.series.size();
      spec.series.push_back(series(title, "linespoints"));
    }
    PlotSeries& s = spec.series[line_of[title]];
    s.x.push_back(r.m.cpu_seconds);
    s.y.push_back(e);
  }
  return spec;
}

// CPU time per cart against the number of carts: per run and per RHS evaluation (× 1000).
PlotSpec cartsCostFigure(const Scene& scene, const std::vector<BenchRow>& rows) {
  PlotSpec spec;
  spec.title = scene.name + ": CPU time per cart vs number of carts" +
               (scene.simulation.reactions ? "" : " (without joint reactions)");
  spec.xlabel = "carts n [-]";
  spec.ylabel = "CPU time / n [s]";
  spec.logx = spec.logy = true;
  for (const char* model : {kMultibody, kMinimal, kReduced}) {
    PlotSeries s = series(std::string(model) + " (per run)", "linespoints");
    PlotSeries e = series(std::string(model) + " (per RHS evaluation × 1000)", "linespoints");
    for (const BenchRow& r : rows)
      if (r.m.setting.model == model && usable(r.m.outcome)) {
        s.x.push_back(r.x);
        s.y.push_back(r.m.cpu_seconds / r.x);
        if (r.m.realizations > 0) {
          e.x.push_back(r.x);
          e.y.push_back(1000.0 * r.m.cpu_seconds / r.m.realizations / r.x);
        }
      }
    spec.series.push_back(s);
    spec.series.push_back(e);
  }
  return spec;
}

}  // namespace

std::vector<std::string> writeIntegratorStudy(const std::string& dir, const Scene& scene,
                                              const std::vector<BenchRow>& rows, const BenchOptions& opt) {
  std::vector<std::string> written;
  writeFileAtomic(dir + "/bench.csv", rowsCsv(rows));
  written.push_back(dir + "/bench.csv");
  std::string notes;
  for (bool coupling : {false, true})
    notes += tryPlot(workPrecisionFigure(scene, rows, coupling),
                     dir + (coupling ? "/work_precision_coupling" : "/work_precision_omega"), written);
  writeFileAtomic(dir + "/bench.md", integratorReport(scene, rows, opt) + notes);
  written.push_back(dir + "/bench.md");
  return written;
}

std::vector<std::string> writeCartsStudy(const std::string& dir, const Scene& scene,
                                         const std::vector<BenchRow>& rows, const BenchOptions& opt) {
  std::vector<std::string> written;
  writeFileAtomic(dir + "/carts.csv", rowsCsv(rows));
  written.push_back(dir + "/carts.csv");
  const std::string notes = tryPlot(cartsCostFigure(scene, rows), dir + "/carts_cost", written);
  writeFileAtomic(dir + "/carts.md", cartsReport(scene, rows, opt) + notes);
  written.push_back(dir + "/carts.md");
  return written;
}

namespace {

// The model's run with a rigid coupling (the scene's baseline when the scene's coupling is rigid)
// as a level over the stiffness range [lo, hi]; false when there is none.
bool addRigidLevel(PlotSpec& spec, const Scene& scene, const std::vector<BenchRow>& rows, const char* model,
                   const PlotSeries& elastic) {
  const BenchRow* rigid = findRow(rows, "rigid coupling", model);
  if (!rigid && scene.coupling.type == CouplingType::Rigid) rigid = findRow(rows, "baseline", model);
  if (!(rigid && usable(rigid->m.outcome) && !elastic.x.empty())) return false;
  const auto [lo, hi] = std::minmax_element(elastic.x.begin(), elastic.x.end());
  PlotSeries r = series(std::string(model) + " rigid", "lines");
  r.x = {*lo, *hi};
  r.y = {rigid->m.cpu_seconds, rigid->m.cpu_seconds};
  spec.series.push_back(r);
  return true;
}

// CPU time against the coupling stiffness, each model's elastic runs and its rigid level.
PlotSpec stiffnessFigure(const Scene& scene, const std::vector<BenchRow>& rows) {
  PlotSpec spec;
  spec.title = scene.name + ": CPU time vs coupling stiffness";
  spec.xlabel = "coupling stiffness c [N·m/rad]";
  spec.ylabel = "CPU time [s]";
  spec.logx = spec.logy = true;
  for (const char* model : {kMultibody, kMinimal, kReduced}) {
    PlotSeries s = series(std::string(model) + " elastic", "linespoints");
    for (const BenchRow& r : rows)
      if (r.m.setting.model == model && r.x > 0 && usable(r.m.outcome)) {
        s.x.push_back(r.x);
        s.y.push_back(r.m.cpu_seconds);
      }
    spec.series.push_back(s);
    addRigidLevel(spec, scene, rows, model, s);
  }
  return spec;
}

// One model's CPU time of each variant over its baseline's, at the variant's number in effects.md.
PlotSeries relativeCostSeries(const std::vector<BenchRow>& rows, const char* model) {
  PlotSeries s = series(model, "points");
  const BenchRow* base = findRow(rows, "baseline", model);
  std::map<std::string, int> index;
  for (const BenchRow& r : rows) {
    if (!index.count(r.variant)) {
      const int k = int(index.size());
      index[r.variant] = k;
    }
    if (r.m.setting.model == model && usable(r.m.outcome) && base && usable(base->m.outcome)) {
      s.x.push_back(index[r.variant]);
      s.y.push_back(r.m.cpu_seconds / base->m.cpu_seconds);
    }
  }
  return s;
}

PlotSpec relativeCostFigure(const Scene& scene, const std::vector<BenchRow>& rows) {
  PlotSpec spec;
  spec.title = scene.name + ": relative cost of each variant (numbers as in effects.md)";
  spec.xlabel = "variant # [-]";
  spec.ylabel = "CPU time / baseline CPU time [-]";
  spec.logy = true;
  for (const char* model : {kMultibody, kMinimal, kReduced}) spec.series.push_back(relativeCostSeries(rows, model));
  return spec;
}

}  // namespace

std::vector<std::string> writeEffectsStudy(const std::string& dir, const Scene& scene,
                                           const std::vector<BenchRow>& rows, const BenchOptions& opt) {
  std::vector<std::string> written;
  writeFileAtomic(dir + "/effects.csv", rowsCsv(rows));
  written.push_back(dir + "/effects.csv");
  std::string notes;
  notes += tryPlot(stiffnessFigure(scene, rows), dir + "/effects_stiffness", written);
  notes += tryPlot(relativeCostFigure(scene, rows), dir + "/effects_relative", written);
  writeFileAtomic(dir + "/effects.md", effectsReport(scene, rows, opt) + notes);
  written.push_back(dir + "/effects.md");
  return written;
}

std::vector<std::string> writeMotorsStudy(const std::string& dir, const Scene& scene, const std::vector<BenchRow>& rows,
                                          const BenchOptions& opt) {
  writeFileAtomic(dir + "/motors.csv", rowsCsv(rows));
  writeFileAtomic(dir + "/motors.md", motorsReport(scene, rows, opt));
  return {dir + "/motors.csv", dir + "/motors.md"};
}

}  // namespace rollerdyn::bench
