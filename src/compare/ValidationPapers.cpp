// Section (3) of the validation suite: the papers' tables swept with our models, and the
// sensitivity table. The findings beside each table are computed in PaperFindings.cpp.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "analysis/Metrics.h"
#include "analysis/SteadyState.h"
#include "compare/PaperFindings.h"
#include "compare/SuiteInternal.h"

namespace rollerdyn::validation::detail {
namespace {

// The published row whose key columns match (within 1e-9).
bool findPublished(const Table& t, const std::vector<std::pair<std::string, double>>& keys,
                   std::map<std::string, double>& row) {
  for (const auto& rw : t.rows) {
    bool ok = true;
    for (const auto& [col, val] : keys) ok = ok && std::abs(rw[t.index(col)] - val) < 1e-9;
    if (!ok) continue;
    row.clear();
    for (std::size_t i = 0; i < t.columns.size(); ++i) row[t.columns[i]] = rw[i];
    return true;
  }
  return false;
}

std::vector<double> range(double a, double b, double step) {
  std::vector<double> v;
  for (double x = a; x <= b + 1e-9; x += step) v.push_back(x);
  return v;
}

bool contains(const std::vector<double>& v, double x) {
  for (double y : v)
    if (std::abs(x - y) < 1e-9) return true;
  return false;
}

// The published value at a point of a paper's sweep (x, and k for Loveikin, Pochka, Romasevych
// (2018), else 0), from the paper's table as read for section (3); NaN when not published.
double publishedAt(const ValidationResults& r, const std::string& id, double x, double k, const std::string& col) {
  for (const auto& p : r.papers)
    if (p.id == id)
      for (const auto& s : p.points)
        if (std::abs(s.x - x) < 1e-9 && std::abs(s.k - k) < 1e-9 && s.has_published) {
          const auto it = s.published.find(col);
          return it == s.published.end() ? kNaN : it->second;
        }
  return kNaN;
}

}  // namespace

// One point of a paper sweep, placed by `sets`: the reduced model on the scene as shipped and
// with the paper's own modelling choices (`variant`); the multibody model only when
// `multibody_log` (its line in the log) is given: it costs a hundred reduced runs or more.
SweepPoint Suite::paperPoint(const PaperSweep& p, const std::vector<std::string>& point,
                             const std::vector<std::string>& variant, const std::string& multibody_log) const {
  const std::vector<std::string> sets = concat(p.start, point);
  SweepPoint sp;
  sp.reduced = reducedMetrics(p.scene_file, sets);
  sp.variant = reducedMetrics(p.scene_file, concat(sets, variant));
  sp.has_variant = true;
  if (!multibody_log.empty()) {
    log(multibody_log);
    sp.multibody = multibodyMetrics(p.scene_file, sets);
    sp.has_multibody = true;
  }
  return sp;
}

// Loveikin and Pochka (2007) and the energy-balanced drive paper: p.x_key over xs, the papers' Baranov scheme as the variant, the multibody
// model at multibody_at, each point beside the published row whose published_key column is x.
// `describe` names a point in the log. False when interrupted (p is then incomplete).
// Not runSweep (studies/Sweep.h): studies is the layer above this one (it links compare), and
// a point here is three runs (reduced, reduced variant, multibody at chosen points only) read
// as RunMetrics (`rotating`, the integration's CPU time), where a Sweep point is one model's
// summary.json over a full grid.
bool Suite::sweepPaper(PaperSweep& p, const std::vector<double>& xs, const std::vector<double>& multibody_at,
                       const std::string& published_key, const std::function<std::string(double)>& describe) {
  const Table pub = readPublishedTable(o_.published_dir + "/" + p.published_file);
  for (double x : xs) {
    if (interrupted()) return false;
    SweepPoint sp = paperPoint(p, {p.x_key + "=" + exact(x)}, {"reduced.integrator=baranov"},
                               contains(multibody_at, x) ? describe(x) : "");
    sp.x = x;
    sp.has_published = findPublished(pub, {{published_key, x}}, sp.published);
    p.points.push_back(sp);
  }
  return true;
}

void Suite::papers(ValidationResults& r) {
  for (auto sweep : {&Suite::loveikin2007Sweep, &Suite::energyBalancedSweep, &Suite::loveikin2018Sweep}) {
    PaperSweep p;
    if (!(this->*sweep)(p)) return;  // interrupted: p is incomplete
    r.papers.push_back(p);
  }
}

// Loveikin and Pochka (2007): Δφ sweep.
bool Suite::loveikin2007Sweep(PaperSweep& p) {
  p.id = "loveikin2007";
  p.title = "Loveikin and Pochka (2007): two carts on opposite sides, rigid drive, delta/H/k_p vs crank offset";
  p.scene_file = "recuperative-2cart.yaml";
  p.x_key = "crank.offset_deg";
  p.x_label = "crank offset Δφ [°]";
  p.variant_label = "reduced model with the papers' Baranov scheme, 1 deg step";
  p.published_file = "loveikin2007_table.csv";
  const std::vector<double> mb = o_.quick ? std::vector<double>{90} : std::vector<double>{0, 30, 60, 90, 120, 150, 180};
  std::vector<double> xs = range(0, 180, o_.quick ? 20 : 10);
  if (!contains(xs, 90)) {  // the papers' optimum, always in
    xs.push_back(90);
    std::sort(xs.begin(), xs.end());
  }
  return sweepPaper(p, xs, mb, "dphi_deg", [](double x) { return "Loveikin and Pochka (2007): multibody at Δφ = " + g(x) + "°"; });
}

// The energy-balanced drive paper: flywheel sweep.
bool Suite::energyBalancedSweep(PaperSweep& p) {
  p.id = "energy_balanced";
  p.title = "the energy-balanced drive paper: three carts at 120 deg, rigid drive, delta/H/k_p vs flywheel inertia";
  p.scene_file = "energy-balanced-3cart.yaml";
  p.x_key = "flywheel.inertia";
  p.x_label = "flywheel inertia [kg·m²]";
  p.variant_label = "reduced model with the papers' Baranov scheme, 1 deg step";
  p.published_file = "energy_balanced_table1.csv";
  const std::vector<double> mb = o_.quick ? std::vector<double>{0} : std::vector<double>{0, 250, 500, 1000};
  if (!sweepPaper(p, range(0, 1000, o_.quick ? 250 : 50), mb, "flywheel_inertia",
                  [](double x) { return "the energy-balanced drive paper: multibody at flywheel inertia " + g(x) + " kg m^2"; }))
    return false;
  return fittedBaranovStep(p);
}

// Could a coarser step of the papers' scheme be the cause of the gap? The scheme is first
// order (D5), so its move of δ grows in proportion to the step: the step that closes the
// gap without a flywheel is h* = 1°·(δ_pub/δ − 1)/(δ_1°/δ − 1). Run the scheme at h* over
// the whole table: if the scheme caused the gap, the gap would close everywhere at h*.
// A step of a quarter revolution or more (or none) is no integration: not run. The scene
// accepts steps up to 10° (reduced.baranov_step_deg); a larger h* runs at 10°.
bool Suite::fittedBaranovStep(PaperSweep& p) {
  const SweepPoint& p0 = p.points.front();
  const double move = p0.variant.delta / p0.reduced.delta - 1.0;
  const double need = p0.has_published ? p0.published.at("delta") / p0.reduced.delta - 1.0 : kNaN;
  const double h = need / move;
  if (!(std::isfinite(h) && h > 0 && h < 90)) return true;
  p.fitted_step_deg = h;
  const double step = std::min(h, 10.0);
  log("the energy-balanced drive paper: the Baranov scheme at a " + g(step) + "° step");
  for (SweepPoint& sp : p.points) {
    if (interrupted()) return false;
    sp.fitted = reducedMetrics(p.scene_file, concat(p.start, {p.x_key + "=" + exact(sp.x), "reduced.integrator=baranov",
                                                              "reduced.baranov_step_deg=" + exact(step)}));
    sp.has_fitted = true;
  }
  return true;
}

// Loveikin, Pochka, Romasevych (2018): Table 1, Δφ × k.
bool Suite::loveikin2018Sweep(PaperSweep& p) {
  p.id = "loveikin2018";
  p.title = "Loveikin, Pochka, Romasevych (2018): four carts, elastic coupling, coupling swings vs crank offset (Table 1)";
  p.scene_file = "balanced-4cart.yaml";
  p.x_key = "crank.offset_deg";
  p.x_label = "crank offset Δφ [°]";
  p.variant_label = "reduced model with the paper's own lumping and series: rods split, truncated kinematics";
  p.published_file = "loveikin2018_table1.csv";
  // Started at the nominal crank speed ω_n/u = 102.1/9.8 = 10.42 rad/s and run for 20 s, as
  // validation/studies/run.sh does for the same table: Table 1 lists steady swings, and from
  // rest (the scene's own start) the motor's starting torque cannot turn the as-printed roller
  // loads at some offsets at all (the sensitivity table shows the start from rest), so those
  // points would have no steady state to compare. 20 s leaves at least five steady revolutions.
  p.start = {"initial.crank_speed=10.42", "simulation.t_end=20"};
  return loveikin2018Points(p) && otherReadingPoints(p);
}

// Table 1's points, Δφ for each coupling damping k, beside the published rows.
bool Suite::loveikin2018Points(PaperSweep& p) {
  const Table pub = readPublishedTable(o_.published_dir + "/" + p.published_file);
  for (double k : {2000.0, 8000.0}) {
    std::vector<double> mb;
    if (o_.quick) mb = k == 8000 ? std::vector<double>{90} : std::vector<double>{};
    else mb = {60, 90};  // the multibody points of validation/studies/run.sh
    for (double x : range(0, 90, o_.quick ? 30 : 10)) {
      if (interrupted()) return false;
      SweepPoint sp = paperPoint(p, {p.x_key + "=" + exact(x), "coupling.damping=" + exact(k)},
                                 {"rods.model=split", "reduced.kinematics=truncated"},
                                 contains(mb, x) ? "Loveikin, Pochka, Romasevych (2018): multibody at Δφ = " + g(x) + "°, k = " + g(k) : "");
      sp.x = x;
      sp.k = k;
      sp.has_published = findPublished(pub, {{"dphi_deg", x}, {"k", k}}, sp.published);
      p.points.push_back(sp);
    }
  }
  return true;
}

// The other reading of the roller forces, same start, k = 8000, every offset.
bool Suite::otherReadingPoints(PaperSweep& p) {
  for (double x : range(0, 90, o_.quick ? 30 : 10)) {
    if (interrupted()) return false;
    SweepPoint sp;
    sp.x = x;
    sp.k = 8000;
    sp.reduced = reducedMetrics(p.scene_file, concat(p.start, {p.x_key + "=" + exact(x), "coupling.damping=8000",
                                                                "loads.roller_force_direction=opposes_velocity"}));
    p.other_reading.push_back(sp);
  }
  return true;
}

// One input or modelling choice changed at a time, at one point per paper: how strongly the
// metric depends on what the papers leave open. Reported beside the baseline, never adopted.
void Suite::sensitivity(ValidationResults& r) {
  sensitivityLoveikin2007(r);
  sensitivityEnergyBalanced(r);
  sensitivityLoveikin2018(r);
}

// One row of the sensitivity table: the metric at the point as the scene ships and with `change`.
void Suite::sensitivityRow(ValidationResults& r, const SensitivityPoint& at, const std::string& change_label,
                           const std::vector<std::string>& change) const {
  const RunMetrics b = reducedMetrics(at.file, at.base);
  const RunMetrics c = reducedMetrics(at.file, concat(at.base, change));
  r.sensitivity.push_back({at.paper, at.point, change_label, at.metric, b.*at.field, c.*at.field, at.published});
}

void Suite::sensitivityLoveikin2007(ValidationResults& r) const {
  const SensitivityPoint at{"Loveikin and Pochka (2007)", "Δφ = 90°", "recuperative-2cart.yaml",
                            {"crank.offset_deg=90"}, "delta", publishedAt(r, "loveikin2007", 90, 0, "delta"),
                            &RunMetrics::delta};
  sensitivityRow(r, at, "reducer inertia 0.046 kg·m² (the printed sum I_o = 0.504)", {"reducer.inertia=0.046"});
  sensitivityRow(r, at, "Baranov scheme, 5° step", {"reduced.integrator=baranov", "reduced.baranov_step_deg=5"});
  sensitivityRow(r, at, "rods split into two point masses (Loveikin, Pochka, Romasevych (2018), eq. (2)-(3))",
                 {"rods.model=split"});
  sensitivityRow(r, at, "no rod gravity (g = 0)", {"loads.gravity=0"});
}

void Suite::sensitivityEnergyBalanced(ValidationResults& r) const {
  const SensitivityPoint at{"the energy-balanced drive paper", "no flywheel", "energy-balanced-3cart.yaml",
                            {"flywheel.inertia=0"}, "delta", publishedAt(r, "energy_balanced", 0, 0, "delta"),
                            &RunMetrics::delta};
  sensitivityRow(r, at, "reducer inertia 0.046 kg·m²", {"reducer.inertia=0.046"});
  sensitivityRow(r, at, "Baranov scheme, 5° step", {"reduced.integrator=baranov", "reduced.baranov_step_deg=5"});
  sensitivityRow(r, at, "no rod gravity (g = 0)", {"loads.gravity=0"});
}

void Suite::sensitivityLoveikin2018(ValidationResults& r) const {
  // Same start as the Table 1 sweep (PaperSweep::start of section (3)).
  const std::vector<std::string> start = {"initial.crank_speed=10.42", "simulation.t_end=20"};
  const std::string L18 = "Loveikin, Pochka, Romasevych (2018)";
  const SensitivityPoint at{L18, "Δφ = 90°, k = 8000", "balanced-4cart.yaml",
                            concat(start, {"crank.offset_deg=90", "coupling.damping=8000"}),
                            "coupling torque swing [N·m]",
                            publishedAt(r, "loveikin2018", 90, 8000, "coupling_torque_swing"), &RunMetrics::torque_swing};
  sensitivityRow(r, at, "no guide friction", {"loads.guide_friction.coefficient=0"});
  sensitivityRow(r, at, "reducer efficiency η = 1 (not given)", {"reducer.efficiency=1"});
  sensitivityRow(r, at, "crank inertia J'_K = 5 kg·m² per crank (not given)", {"crank.inertia_per_crank=5"});
  sensitivityRow(r, at, "no gravity (rod weight)", {"loads.gravity=0"});
  const SensitivityPoint from_rest{L18, "Δφ = 80°, k = 8000", "balanced-4cart.yaml",
                                   concat(start, {"crank.offset_deg=80", "coupling.damping=8000"}),
                                   "mean crank speed [rad/s]", kNaN, &RunMetrics::omega_mean};
  sensitivityRow(r, from_rest, "start from rest (the scene's own start) instead of 10.42 rad/s", {"initial.crank_speed=0"});
}

void Suite::findings(ValidationResults& r) {
  for (PaperSweep& p : r.papers) {
    const Scene sc = load(p.scene_file, {});
    if (p.id == "loveikin2007") p.findings = findingsLoveikin2007(p, r.sensitivity);
    if (p.id == "energy_balanced") p.findings = findingsEnergyBalanced(p, r.sensitivity, sc);
    if (p.id == "loveikin2018") p.findings = findingsLoveikin2018(p, r.sensitivity, sc);
  }
}

}  // namespace rollerdyn::validation::detail
