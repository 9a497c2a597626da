#include "studies/MotorStudy.h"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <memory>

#include "io/AtomicFile.h"
#include "motor/CatalogueFit.h"
#include "motor/CircuitLaw.h"
#include "motor/KlossLaw.h"
#include "motor/MotorLawFactory.h"
#include "motor/ParkLaw.h"
#include "report/Gnuplot.h"
#include "io/FieldFormat.h"

namespace rollerdyn {

namespace {

nlohmann::json machineJson(const InductionMachineParameters& m) {
  nlohmann::json j = {{"per_phase_of", "equivalent star"},
                      {"R_s[Ω]", m.R_s},
                      {"L_sigma_s[H]", m.L_sigma_s},
                      {"L_m[H]", m.L_m},
                      {"R_r[Ω]", m.R_r[0]},
                      {"L_sigma_r[H]", m.L_sigma_r[0]},
                      {"cages", m.cages},
                      {"pole_pairs", m.pole_pairs},
                      {"phase_voltage[V]", m.phase_voltage},
                      {"frequency[Hz]", m.frequency}};
  if (m.cages == 2) {
    j["R_r2[Ω]"] = m.R_r[1];
    j["L_sigma_r2[H]"] = m.L_sigma_r[1];
  }
  return j;
}

std::string machineText(const InductionMachineParameters& m, WindingConnection connection) {
  std::string text;
  const double w1 = m.supplyAngularFrequency();
  text += printfText("  per phase of the equivalent star (U_ph = %.5g V, f_n = %.4g Hz, p = %d):\n", m.phase_voltage, m.frequency,
              m.pole_pairs);
  text += printfText("    R_s      = %-10.5g Ω\n    L_sigma_s = %-10.5g H   (X = %.4g Ω)\n    L_m      = %-10.5g H   (X = %.4g Ω)\n",
              m.R_s, m.L_sigma_s, w1 * m.L_sigma_s, m.L_m, w1 * m.L_m);
  text += printfText("    R_r      = %-10.5g Ω\n    L_sigma_r = %-10.5g H   (X = %.4g Ω)\n", m.R_r[0], m.L_sigma_r[0],
              w1 * m.L_sigma_r[0]);
  if (m.cages == 2)
    text += printfText("    R_r2     = %-10.5g Ω\n    L_sigma_r2 = %-9.5g H   (X = %.4g Ω)\n", m.R_r[1], m.L_sigma_r[1],
                w1 * m.L_sigma_r[1]);
  if (connection == WindingConnection::Delta)
    text += printfText("  the winding is in delta: its own per-winding values are 3× these resistances and inductances\n");
  return text;
}

// The machine: the scene's circuit, else fitted to the catalogue; none: Kloss only. `points`: the
// model at every catalogue point, when the scene has a catalogue.
std::unique_ptr<InductionMachineParameters> sceneMachine(const Scene& scene, std::vector<CatalogueComparison>& points,
                                                         std::string& text, nlohmann::json& j) {
  const InductionMotor& im = scene.induction;
  std::unique_ptr<InductionMachineParameters> machine;
  if (im.circuit.given()) {
    machine = std::make_unique<InductionMachineParameters>(InductionMachineParameters::fromScene(im));
    text += printfText("equivalent circuit from motor.circuit (%s cage):\n", machine->cages == 2 ? "double" : "single");
    j["machine_source"] = "motor.circuit";
    if (im.catalogue.given()) points = compareWithCatalogue(*machine, im.catalogue);
  } else if (im.catalogue.given()) {
    const CatalogueFit fit = fitSceneCatalogue(scene, im.catalogue.cages);
    machine = std::make_unique<InductionMachineParameters>(fit.machine);
    points = fit.points;
    text += printfText("equivalent circuit fitted to motor.catalogue (%s cage; weighted least squares, Pedra (2008); "
                "%d optimizer starts, %d evaluations):\n",
                fit.machine.cages == 2 ? "double" : "single", fit.starts, fit.evaluations);
    text += "  " + fit.origin.describe() + "\n";
    j["machine_source"] = "motor.catalogue (fitted)";
    j["fit"] = {{"starts", fit.starts}, {"evaluations", fit.evaluations}, {"max_relative_error", fit.max_relative_error},
                {"origin", fit.origin.describe()}};
  } else {
    text += printfText("no equivalent circuit: the scene gives neither motor.circuit nor motor.catalogue (Kloss curves only)\n");
  }
  return machine;
}

// The catalogue's rated slip s_n against the Kloss law's synchronous speed.
double catalogueRatedSlip(const Scene& scene) {
  return 1.0 - scene.induction.catalogue.omega_nominal / scene.motor.omega_sync;
}

// Kloss's torque at a catalogue point where it has one (M_n, M_s, M_k), else NaN.
double klossAtCataloguePoint(const Scene& scene, const KlossLaw& kloss, const CatalogueComparison& p) {
  if (p.symbol == "M_n") return kloss.steadyTorque({}, scene.induction.catalogue.omega_nominal);
  if (p.symbol == "M_s") return kloss.steadyTorque({}, 0.0);
  if (p.symbol == "M_k") return scene.motor.breakdown_torque;
  return NAN;
}

std::string catalogueCsvRow(const CatalogueComparison& p, double k) {
  return p.quantity + "," + p.symbol + "," + p.unit + "," + printfNumber("%.10g", p.catalogue) + "," +
         printfNumber("%.10g", p.model) + "," + printfNumber("%.6g", p.relativeError()) + "," +
         (std::isfinite(k) ? printfNumber("%.10g", k) : std::string("")) + "\n";
}

nlohmann::json catalogueJsonRow(const CatalogueComparison& p, double k) {
  return {{"quantity", p.quantity}, {"symbol", p.symbol}, {"unit", p.unit}, {"catalogue", p.catalogue},
          {"model", p.model}, {"relative_error", p.relativeError()},
          {"kloss", std::isfinite(k) ? nlohmann::json(k) : nlohmann::json(nullptr)}};
}

// Catalogue points: model beside catalogue, with Kloss's torque where it has one. Returns the
// catalogue CSV's text (empty: no catalogue points).
std::string cataloguePoints(const Scene& scene, const KlossLaw& kloss, const std::vector<CatalogueComparison>& points,
                            std::string& text, nlohmann::json& j) {
  if (points.empty()) return "";
  std::string cat_csv = "quantity,symbol,unit,catalogue,model,relative_error[-],kloss\n";
  text += printfText("\nthe model at every catalogue point (rated slip s_n = %.4g):\n", catalogueRatedSlip(scene));
  text += printfText("  %-20s %-8s %12s %12s %10s %12s\n", "quantity", "symbol", "catalogue", "model", "error", "Kloss");
  nlohmann::json pj = nlohmann::json::array();
  for (const CatalogueComparison& p : points) {
    const double k = klossAtCataloguePoint(scene, kloss, p);
    text += printfText("  %-20s %-8s %12.5g %12.5g %+9.2f%% %12s\n", p.quantity.c_str(), p.symbol.c_str(), p.catalogue, p.model,
                100 * p.relativeError(), std::isfinite(k) ? printfNumber("%.5g", k).c_str() : "–");
    cat_csv += catalogueCsvRow(p, k);
    pj.push_back(catalogueJsonRow(p, k));
  }
  text += printfText("  (points 1-7: M_n, I_n, cos φ_n, η_n at s_n; M_s, I_s at standstill; M_k the largest torque; "
              "torques [N·m], currents RMS line [A]; the circuit has copper losses only, see docs/motor.md)\n");
  j["catalogue_points"] = pj;
  return cat_csv;
}

// Steady curves over 0 ≤ s ≤ 1 (each law at its own synchronous speed); without a machine only Kloss's.
Table steadyCurves(const Scene& scene, const KlossLaw& kloss, const InductionMachineParameters* machine,
                   const CircuitLaw* circuit, const ParkLaw* park) {
  Table curves;
  // ASCII units in the header, as every CSV of rollerdyn (io/Table.h).
  curves.columns = {"slip[-]", "omega_rotor_kloss[rad/s]", "omega_rotor_circuit[rad/s]", "M_kloss[N*m]",
                    "M_circuit[N*m]", "M_park[N*m]", "I_circuit[A]", "I_park[A]"};
  const int n = 500;
  for (int i = 0; i <= n; ++i) {
    const double s = double(i) / n;
    const double wk = scene.motor.omega_sync * (1 - s);
    std::vector<double> row = {s, wk, NAN, kloss.steadyTorque({}, wk), NAN, NAN, NAN, NAN};
    if (machine) {
      const double w = machine->synchronousSpeed() * (1 - s);
      row[2] = w;
      row[4] = circuit->steadyTorque({}, w);
      row[5] = park->steadyTorque({}, w);
      row[6] = circuit->steadyCurrent({}, w);
      row[7] = park->steadyCurrent({}, w);
    }
    curves.rows.push_back(row);
  }
  return curves;
}

}  // namespace

namespace {

// The Kloss law's lines of the text, and the study's json with the scene and the law.
nlohmann::json klossHeader(const Scene& scene, const std::string& scene_label, const std::vector<std::string>& overrides,
                           std::string& text) {
  const InductionMotor& im = scene.induction;
  const auto dynamic = makeMotorLaw(scene, MotorModel::KlossDynamic);
  text += printfText("motor of %s (motor.model: %s)\n", scene.name.c_str(), toString(im.model));
  text += printfText("  Kloss: omega0 = %.5g rad/s, M_kr = %.5g N·m, s_kr = %.4g; dynamic Kloss T_e = %.4g s\n",
              scene.motor.omega_sync, scene.motor.breakdown_torque, scene.motor.critical_slip,
              dynamic->fastestTimeConstant());
  return {{"scene", scene_label},
          {"overrides", overrides},
          {"motor_model", toString(im.model)},
          {"kloss", {{"omega_sync[rad/s]", scene.motor.omega_sync},
                     {"breakdown_torque[N·m]", scene.motor.breakdown_torque},
                     {"critical_slip", scene.motor.critical_slip},
                     {"dynamic_time_constant[s]", dynamic->fastestTimeConstant()}}}};
}

// The machine's circuit, its breakdown point and its fastest electrical time constant.
void describeMachine(const InductionMachineParameters& machine, WindingConnection connection, const ParkLaw& park,
                     std::string& text, nlohmann::json& j) {
  text += machineText(machine, connection);
  double m_k = NAN;
  const double s_k = breakdownSlip(machine, &m_k);
  text += printfText("  breakdown: M_k = %.5g N·m at slip %.4g; fastest electrical time constant %.3g ms\n", m_k, s_k,
              1e3 * park.fastestTimeConstant());
  j["machine"] = machineJson(machine);
  j["machine"]["breakdown_slip"] = s_k;
  j["machine"]["breakdown_torque[N·m]"] = m_k;
  j["machine"]["fastest_time_constant[s]"] = park.fastestTimeConstant();
}

}  // namespace

MotorStudy studyMotor(const Scene& scene, const std::string& scene_label, const std::vector<std::string>& overrides) {
  MotorStudy study;
  std::string& text = study.text;
  const KlossLaw kloss(scene.motor);
  nlohmann::json j = klossHeader(scene, scene_label, overrides, text);

  std::vector<CatalogueComparison> points;
  std::unique_ptr<InductionMachineParameters> machine = sceneMachine(scene, points, text, j);
  std::unique_ptr<CircuitLaw> circuit;
  std::unique_ptr<ParkLaw> park;
  if (machine) {
    circuit = std::make_unique<CircuitLaw>(*machine);
    park = std::make_unique<ParkLaw>(*machine);
    describeMachine(*machine, scene.induction.connection, *park, text, j);
  }

  const std::string cat_csv = cataloguePoints(scene, kloss, points, text, j);
  if (!cat_csv.empty()) study.catalogue_csv = cat_csv;

  study.curves = steadyCurves(scene, kloss, machine.get(), circuit.get(), park.get());
  study.has_machine = machine != nullptr;
  study.json = std::move(j);
  return study;
}


namespace {

// One steady curve of the study's table against slip.
PlotSeries slipCurve(const Table& curves, const std::string& title, const std::string& column,
                     const std::string& color, int dash, double line_width) {
  PlotSeries p;
  p.title = title;
  p.x = curves.column("slip[-]");
  p.y = curves.column(column);
  p.color = color;
  p.dash = dash;
  p.line_width = line_width;
  return p;
}

// Catalogue values at their slips, drawn as black points.
PlotSeries cataloguePointsSeries(const std::string& title, double s_n, double at_s_n, double at_standstill) {
  PlotSeries pts;
  pts.title = title;
  pts.x = {s_n, 1.0};
  pts.y = {at_s_n, at_standstill};
  pts.style = "points";
  pts.color = "#000000";
  pts.line_width = 2;
  return pts;
}

// The catalogue's torques: M_n and M_s as points, M_k as a dashed line across all slips.
std::vector<PlotSeries> catalogueTorqueMarks(const Scene& scene) {
  const MotorCatalogue& c = scene.induction.catalogue;
  const double s_n = catalogueRatedSlip(scene), m_n = c.nominalTorque();
  PlotSeries mk;
  mk.title = "catalogue breakdown torque M_k";
  mk.x = {0.0, 1.0};
  mk.y = {c.breakdown_torque_ratio * m_n, c.breakdown_torque_ratio * m_n};
  mk.color = "#000000";
  mk.dash = 3;
  return {cataloguePointsSeries("catalogue: M_n at s_n, M_s at s = 1", s_n, m_n, c.starting_torque_ratio * m_n), mk};
}

PlotSeries catalogueCurrentMarks(const Scene& scene) {
  const MotorCatalogue& c = scene.induction.catalogue;
  return cataloguePointsSeries("catalogue: I_n at s_n, I_s at s = 1", catalogueRatedSlip(scene), c.current,
                               c.starting_current_ratio * c.current);
}

// The y range's top: head room above the curves for the key.
std::string topWithKeyRoom(const PlotSpec& p) {
  double m = 0;
  for (const auto& ser : p.series)
    for (double v : ser.y)
      if (std::isfinite(v)) m = std::max(m, v);
  return printfNumber("%.6g", 1.45 * m);
}

PlotSpec torqueSlipPlot(const Scene& scene, const Table& curves, bool machine) {
  PlotSpec tq;
  tq.title = "torque-slip curves, " + escapeUnderscores(scene.name) + ", rated supply";
  tq.xlabel = "slip s [-]";
  tq.ylabel = "torque at the rotor M [N·m]";
  tq.series.push_back(slipCurve(curves, "Kloss (static; dynamic Kloss: same static curve)", "M_kloss[N*m]", "#1f77b4", 0, 2));
  if (machine) {
    tq.series.push_back(slipCurve(curves, "equivalent circuit", "M_circuit[N*m]", "#d62728", 0, 2));
    tq.series.push_back(slipCurve(curves, "Park machine, steady state", "M_park[N*m]", "#2ca02c", 2, 1.5));
  }
  if (scene.induction.catalogue.given())
    for (const PlotSeries& mark : catalogueTorqueMarks(scene)) tq.series.push_back(mark);
  tq.preamble = "set key inside top right\nset xrange [0:1]\nset yrange [0:" + topWithKeyRoom(tq) + "]";
  return tq;
}

PlotSpec currentSlipPlot(const Scene& scene, const Table& curves, bool machine) {
  PlotSpec cur;
  cur.title = "stator current-slip curves, " + escapeUnderscores(scene.name) + ", rated supply";
  cur.xlabel = "slip s [-]";
  cur.ylabel = "RMS stator (line) current I [A]";
  if (machine) {
    cur.series.push_back(slipCurve(curves, "equivalent circuit", "I_circuit[A]", "#d62728", 0, 2));
    cur.series.push_back(slipCurve(curves, "Park machine, steady state", "I_park[A]", "#2ca02c", 2, 1.5));
  }
  if (scene.induction.catalogue.given()) cur.series.push_back(catalogueCurrentMarks(scene));
  cur.preamble = "set key inside top left\nset xrange [0:1]\nset yrange [0:" + topWithKeyRoom(cur) + "]";
  return cur;
}

}  // namespace

std::string writeMotorStudy(const std::string& out, const Scene& scene, const MotorStudy& study) {
  writeFileAtomic(out + "/motor.json", study.json.dump(2) + "\n");
  writeCsvAtomic(out + "/motor_curves.csv", study.curves);
  if (!study.catalogue_csv.empty()) writeFileAtomic(out + "/motor_catalogue.csv", study.catalogue_csv);
  if (!gnuplotAvailable()) return "gnuplot not found (Debian package gnuplot-nox): no figures";
  renderPlot(torqueSlipPlot(scene, study.curves, study.has_machine), out + "/motor_torque_slip");
  const PlotSpec cur = currentSlipPlot(scene, study.curves, study.has_machine);
  if (!cur.series.empty()) renderPlot(cur, out + "/motor_current_slip");
  return "";
}

}  // namespace rollerdyn
