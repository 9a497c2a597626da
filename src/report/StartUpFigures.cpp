#include "report/StartUpFigures.h"

#include "analysis/StartUpSummary.h"
#include "report/FigureSupport.h"

namespace rollerdyn {

namespace {

using namespace figures;  // FigureSupport.h

// Shades the steady window and marks switch-on and switch-off.
std::string startUpPreamble(const nlohmann::json& su, const TimeWindow& window) {
  std::string p = "set key outside below horizontal\n";
  const nlohmann::json& steady = su.value("steady", nlohmann::json::object());
  double t0 = window.t_begin, t1 = window.t_end;
  if (steady.value("t_begin", nlohmann::json()).is_number() && steady.value("t_end", nlohmann::json()).is_number())
    t0 = steady["t_begin"].get<double>(), t1 = steady["t_end"].get<double>();
  if (t1 > t0)
    p += "set object 1 rect from " + printfNumber("%.9g", t0) + ", graph 0 to " + printfNumber("%.9g", t1) +
         ", graph 1 fc rgb '#e8e8e8' fs solid noborder behind\nset label 1 'steady window' at " + printfNumber("%.9g", t0) +
         ", graph 0.96 offset 0.5,0 font ',9' tc rgb '#555555' front\n";
  auto vline = [&p](int id, double t, const std::string& text) {
    p += "set arrow " + std::to_string(id) + " from " + printfNumber("%.9g", t) + ", graph 0 to " + printfNumber("%.9g", t) +
         ", graph 1 nohead dt 3 lc rgb '#d62728' front\nset label " + std::to_string(id + 10) + " '" + text +
         "' at " + printfNumber("%.9g", t) + ", graph 0.90 offset 0.5,0 font ',9' tc rgb '#d62728' front\n";
  };
  if (su.value("t_on", nlohmann::json()).is_number()) vline(1, su["t_on"].get<double>(), "switch-on");
  const nlohmann::json& stop = su.value("stop", nlohmann::json());
  if (stop.is_object() && stop.value("t_off", nlohmann::json()).is_number()) vline(2, stop["t_off"].get<double>(), "switch-off");
  return p;
}

// What the start-up figures share: the time series, its time column, the scene's label and the
// preamble with the steady window and the switching times.
struct StartUpPlots {
  const Table& ts;
  std::vector<double> t;
  std::string scene_label, pre;
};

// A start-up figure against time with the shared preamble.
PlotSpec startUpSpec(const StartUpPlots& p, const std::string& title, const std::string& ylabel) {
  PlotSpec spec;
  spec.title = sceneTitle(p.scene_label, title);
  spec.xlabel = "t [s]";
  spec.ylabel = ylabel;
  spec.preamble = p.pre;
  return spec;
}

FigurePlan speedFigure(const StartUpPlots& p, const nlohmann::json& su) {
  const Table& ts = p.ts;
  const std::vector<double>& t = p.t;
  const std::string method = literal(su.value("method", std::string()));
  const std::string law = literal(su.value("motor_law", std::string()));
  PlotSpec speed = startUpSpec(p, "start-up: speeds (" + method + ", " + law + ")", "speed at the crank axis [rad/s]");
  speed.series.push_back(series("crank speed ω_2", t, col(ts, "omega_crank"), kBlue, 1.5));
  if (ts.has("omega_motor"))
    speed.series.push_back(series("motor speed ω_1 = ω_r/u", t, col(ts, "omega_motor"), kOrange, 1.0));
  const nlohmann::json mean = su.value("steady", nlohmann::json::object()).value("mean_speed", nlohmann::json());
  if (mean.is_number()) {
    PlotSeries level = series("95 % of the steady mean speed", {t.front(), t.back()},
                              {0.95 * mean.get<double>(), 0.95 * mean.get<double>()}, kGrey, 1.0);
    level.dash = 2;
    speed.series.push_back(level);
  }
  return {"start_up_speed",
          "Crank and motor speed over the run: the start from the switch-on (red dotted line), the run-up to "
          "95 % of the steady mean speed (grey dashed) and the steady window (shaded).",
          std::move(speed)};
}

FigurePlan torqueFigure(const StartUpPlots& p) {
  const Table& ts = p.ts;
  const std::vector<double>& t = p.t;
  PlotSpec torque = startUpSpec(p, "start-up: motor and coupling torque", "torque at the crank axis [N·m]");
  torque.series.push_back(series("motor torque M·u·η", t, col(ts, "motor_torque"), kRed, 1.0));
  if (ts.has("coupling_torque"))
    torque.series.push_back(series("coupling torque", t, col(ts, "coupling_torque"), kBlue, 1.2));
  if (ts.has("brake_torque")) torque.series.push_back(series("brake torque", t, col(ts, "brake_torque"), kGreen, 1.0));
  return {"start_up_torque",
          "Motor torque (M at the rotor × u·η) and coupling torque at the crank axis over the run, with the "
          "steady window shaded: the start's peaks against the steady state's (summary.json start_up).",
          std::move(torque)};
}

// Needs the stator_current column.
FigurePlan currentFigure(const StartUpPlots& p) {
  const Table& ts = p.ts;
  const std::vector<double>& t = p.t;
  PlotSpec current = startUpSpec(p, "start-up: stator current", "RMS stator phase current [A]");
  current.series.push_back(series("stator current I_s (RMS, phase)", t, col(ts, "stator_current"), kRed, 1.0));
  if (ts.has("supply_voltage_ratio")) {
    std::vector<double> u = col(ts, "supply_voltage_ratio");
    for (double& v : u) v *= 100.0;
    current.series.push_back(series("supply voltage U/U_n [%]", t, u, kGrey, 1.5));
  }
  return {"start_up_current",
          "RMS stator phase current over the run (and the supply voltage in per cent of U_n where the "
          "starting method changes it), the steady window shaded.",
          std::move(current)};
}

}  // namespace

const std::vector<std::string>& startUpFigureNames() {
  static const std::vector<std::string> names = {"start_up_speed", "start_up_torque", "start_up_current"};
  return names;
}

void planStartUpFigures(const OutputFolder& out, const TimeWindow& window, const std::string& scene_label,
                        std::vector<FigurePlan>& plans, std::vector<std::string>& notes) {
  const nlohmann::json su = out.has_summary && out.summary.contains("start_up") ? out.summary["start_up"] : nlohmann::json();
  // A static Kloss start direct on line is drawn by the time figures already (crank speed, motor
  // and coupling torque against time); no motor switched on: nothing to draw.
  if (!startUpHasOwnFigures(su)) return;
  const StartUpPlots p{out.timeseries, col(out.timeseries, "t"), scene_label, startUpPreamble(su, window)};
  if (p.t.empty()) return;
  plans.push_back(speedFigure(p, su));
  plans.push_back(torqueFigure(p));
  if (!out.timeseries.has("stator_current")) {
    notes.push_back("start-up current figure left out: the motor law models no stator current (motor.model kloss, "
                    "kloss_dynamic)");
    return;
  }
  plans.push_back(currentFigure(p));
}

}  // namespace rollerdyn
