// Validation item: the drive-sizing answers (src/analysis/DriveSizing.h, summary.json `sizing`)
// recomputed by hand from the columns of the run's CSV tables, the files an engineer gets. The
// hand computation follows the definitions the documentation states (steady window = the last N
// whole crank revolutions; ω's extremes over its rows and the crank speed's extrema the
// integrator located between them, crank_speed_extrema.csv; time means and RMS by the trapezoidal rule over the window's rows;
// P = (∫|F|³·n dt / ∫n dt)^(1/3) with the joint's rotation or swing speed n; L10 = (C/P)³·10⁶
// revolutions, L10h = L10/(n̄/2π·3600), for the oscillating rod end L10·180°/(2γ)/(3600·f);
// M_n = M_kr/λ) and shares no code with the sizing: only
// the CSV text and the parsed summary.json are compared.
//
// Tolerance of every comparison: 1e-9 relative to the figure's scale, the size of the operands
// it is computed from (its own size, except for a difference of nearly equal numbers: the slip
// 1 - ω_r/ω0 against 1, δ = (ω_max - ω_min)/ω_mean against ω_max/ω_mean, ΔT = T_max - T_min
// against T_max, the mean of a swinging signal against its peak). The CSV keeps 12 significant digits (a relative rounding
// of 5e-13 per value) and the two sides sum the same ~600 trapezoids in different orders
// (~1e-13); 1e-9 leaves three orders of margin for that,
// while any error of definition moves a figure by far more: one row more or less at an end of
// the window moves an integral by ~1/600 ≈ 2e-3, a factor u·η by ~10, the life exponent 3 → 10/3
// moves L10 by (C/P)^(1/3), a few tens of per cent for the ratings used here. The window's ends
// (times interpolated between rows) are compared to 1e-8 s: φ in the CSV carries ~1e-11 rad.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "analysis/Summary.h"
#include "compare/SizingByHand.h"
#include "compare/ValidationItems.h"
#include "io/AtomicFile.h"
#include "io/CsvTable.h"
#include "multibody/MultibodySimulation.h"
#include "reduced/ReducedModel.h"
#include "compare/RunModel.h"
#include "io/FieldFormat.h"

namespace rollerdyn::validation {
namespace {

using namespace sizing_by_hand;
constexpr double kTimeSeconds = 1e-8; // window ends [s], file comment

// The tool's one reader (io/CsvTable.h), its rows turned into columns.
Csv columnsOf(const std::string& text, const std::string& file) {
  const Table t = parseCsv(text, file);
  Csv c;
  c.names = t.columns;
  c.columns.assign(t.columns.size(), {});
  for (const std::vector<double>& row : t.rows)
    for (std::size_t i = 0; i < row.size(); ++i) c.columns[i].push_back(row[i]);
  return c;
}

Window lastRevolutions(const std::vector<double>& t, const std::vector<double>& phi, int n) {
  std::vector<double> cross{t.front()};
  for (std::size_t i = 1; i < t.size(); ++i) {
    double target = phi.front() + kTwoPi * double(cross.size());
    while (phi[i] >= target && phi[i - 1] < target) {
      cross.push_back(t[i - 1] + (target - phi[i - 1]) / (phi[i] - phi[i - 1]) * (t[i] - t[i - 1]));
      target = phi.front() + kTwoPi * double(cross.size());
    }
  }
  Window w;
  w.crossings = cross;
  const int whole = int(cross.size()) - 1;
  w.revolutions = std::min(n, whole);
  if (w.revolutions < 1) return w;
  w.t_begin = cross[cross.size() - 1 - std::size_t(w.revolutions)];
  w.t_end = cross.back();
  while (w.b < t.size() && t[w.b] < w.t_begin) ++w.b;
  w.e = w.b;
  while (w.e < t.size() && t[w.e] <= w.t_end) ++w.e;
  return w;
}

// The crank speed over the steady window, computed by hand.
struct CrankSpeedByHand {
  double revolutions_in_rows = 0;  // (φ at its last row - φ at its first)/2π
  double mean = 0, lowest = 0, highest = 0;  // [rad/s]
  double delta = 0;
};

// The window and the crank-speed metrics (Loveikin and Pochka (2007), eq. (12)-(14)); the mean
// speed of whole revolutions in closed form, 2πN/(t_end - t_begin).
CrankSpeedByHand crankSpeedByHand(const RunFiles& f) {
  const std::vector<double>& phi = f.ts.col("phi_crank");
  const std::vector<double>& w = f.ts.col("omega_crank");
  const Window& win = f.win;
  CrankSpeedByHand c;
  c.revolutions_in_rows = (phi[f.e - 1] - phi[f.b]) / kTwoPi;
  c.mean = kTwoPi * win.revolutions / (win.t_end - win.t_begin);
  // ω's extremes: the window's rows and the extrema of crank_speed_extrema.csv inside the window.
  const auto [row_lo, row_hi] = std::minmax_element(w.begin() + long(f.b), w.begin() + long(f.e));
  c.lowest = *row_lo, c.highest = *row_hi;
  for (std::size_t i = 0; i < f.ex.col("t").size(); ++i)
    if (f.ex.col("t")[i] >= win.t_begin && f.ex.col("t")[i] <= win.t_end) {
      c.lowest = std::min(c.lowest, f.ex.col("omega_crank")[i]);
      c.highest = std::max(c.highest, f.ex.col("omega_crank")[i]);
    }
  c.delta = (c.highest - c.lowest) / c.mean;
  return c;
}

CrankSpeedByHand checkWindow(ValidationSection& s, const std::string& who, const RunFiles& f) {
  const Window& win = f.win;
  const double dtb = std::abs(win.t_begin - jsonAt(f.sz, "window.t_begin").get<double>());
  const double dte = std::abs(win.t_end - jsonAt(f.sz, "window.t_end").get<double>());
  const CrankSpeedByHand c = crankSpeedByHand(f);
  double eps_max = 0;
  for (std::size_t i = f.b; i < f.e; ++i) eps_max = std::max(eps_max, std::abs(f.ts.col("eps_crank")[i]));
  const double H = eps_max / (c.mean * c.mean);
  Comparison cw;
  cw.add("revolutions in the window's rows", c.revolutions_in_rows, jsonAt(f.sz, "window.revolutions"));
  cw.add("ω_mean = 2πN/Δt", c.mean, jsonAt(f.summary, "omega_crank.mean"));
  cw.add("ω_min", c.lowest, jsonAt(f.summary, "omega_crank.min"));
  cw.add("ω_max", c.highest, jsonAt(f.summary, "omega_crank.max"));
  cw.add("δ", c.delta, jsonAt(f.summary, "delta"), c.highest / c.mean);  // a difference: judged against its operands
  cw.add("H", H, jsonAt(f.summary, "H"));
  cw.add("k_p", c.delta * c.delta + H, jsonAt(f.summary, "k_p"));
  s.claim(cw.holds() && dtb <= kTimeSeconds && dte <= kTimeSeconds,
          who + ": steady window = the last " + std::to_string(win.revolutions) + " whole crank revolutions, t = " +
              g(win.t_begin, 6) + " ... " + g(win.t_end, 6) + " s by hand (summary.json differs by " + g(dtb, 2) +
              " and " + g(dte, 2) + " s, at most " + g(kTimeSeconds) + " s required); its mean crank speed " +
              g(c.mean, 6) + " rad/s, δ = " + g(c.delta, 4) + ", H = " + g(H, 4) + ": " + cw.sentence() + ".");
  return c;
}

// Motor (DriveSizing.h notation): rotor torque M = motor_torque/(u·η), rotor speed ω_r =
// u·omega_motor, slip s = 1 - ω_r/ω0, energy per crank revolution ∫M·ω_r dt / revolutions.
// The motor's figures by hand over the window (DriveSizing.h notation).
struct MotorByHand {
  double mean = 0, rms = 0, peak = 0;  // M at the rotor [N·m]
  double M_n = 0;                      // M_kr/λ [N·m]
  double energy = 0;                   // ∫M·ω_r dt per crank revolution [J]
  double slip_lo = 0, slip_hi = 0;
};

MotorByHand motorByHand(const Scene& sc, const RunFiles& f, const CrankSpeedByHand& crank) {
  const std::vector<double>& t = f.ts.col("t");
  const std::size_t b = f.b, e = f.e;
  const double u = sc.reducer.ratio, eta = sc.reducer.efficiency, w0 = sc.motor.omega_sync;
  std::vector<double> M, M2, P, slip;
  for (std::size_t i = 0; i < t.size(); ++i) {
    const double m = f.ts.col("motor_torque")[i] / (u * eta), wr = u * f.ts.col("omega_motor")[i];
    M.push_back(m);
    M2.push_back(m * m);
    P.push_back(m * wr);
    slip.push_back(1.0 - wr / w0);
  }
  MotorByHand x;
  for (std::size_t i = b; i < e; ++i) x.peak = std::max(x.peak, std::abs(M[i]));
  x.mean = integral(t, M, b, e) / f.span, x.rms = std::sqrt(integral(t, M2, b, e) / f.span);
  x.M_n = sc.motor.breakdown_torque / sc.sizing.motor_overload_ratio;
  x.energy = integral(t, P, b, e) / crank.revolutions_in_rows;
  const auto [slo, shi] = std::minmax_element(slip.begin() + long(b), slip.begin() + long(e));
  x.slip_lo = *slo, x.slip_hi = *shi;
  return x;
}

void checkMotor(ValidationSection& s, const Scene& sc, const std::string& who, const RunFiles& f,
                const CrankSpeedByHand& crank) {
  const double u = sc.reducer.ratio, eta = sc.reducer.efficiency;
  const MotorByHand x = motorByHand(sc, f, crank);
  const json& m = jsonAt(f.sz, "motor");
  Comparison c;
  c.add("mean M", x.mean, jsonAt(m, "torque_shaft.mean"), x.peak);
  c.add("RMS M", x.rms, jsonAt(m, "torque_shaft.rms"));
  c.add("peak |M|", x.peak, jsonAt(m, "torque_shaft.peak"));
  c.add("RMS at the crank", x.rms * u * eta, jsonAt(m, "torque_crank.rms"));
  c.add("M_n = M_kr/λ", x.M_n, jsonAt(m, "nominal_torque"));
  c.add("RMS/M_n", x.rms / x.M_n, jsonAt(m, "rms_over_nominal"));
  c.add("peak/M_kr", x.peak / sc.motor.breakdown_torque, jsonAt(m, "peak_over_breakdown"));
  c.add("energy per revolution", x.energy, jsonAt(m, "energy_per_revolution"));
  c.add("slip min", x.slip_lo, jsonAt(m, "slip.min"), 1.0);  // s = 1 - ω_r/ω0: operands of size 1
  c.add("slip max", x.slip_hi, jsonAt(m, "slip.max"), 1.0);
  s.claim(c.holds(), who + ": motor at the rotor, M = motor_torque/(u·η) (u = " + g(u) + ", η = " + g(eta) +
                         "): mean " + g(x.mean, 4) + ", RMS " + g(x.rms, 4) + ", peak " + g(x.peak, 4) + " N·m; RMS/M_n = " +
                         g(x.rms / x.M_n, 3) + " with M_n = M_kr/λ = " + g(x.M_n, 4) + " N·m; ∫M·ω_r dt per crank "
                         "revolution " + g(x.energy, 5) + " J; slip " + g(x.slip_lo, 3) + " ... " + g(x.slip_hi, 3) + ": " +
                         c.sentence() + ".");
}

// The machine's kinetic energy T at each row and its effective inertia 2T/ω² (at the crank).
struct KineticEnergyRows {
  std::vector<double> T, J;
};

// T = ½J_n1·ω_motor² + ½(J_c + n·m_rod/2·r²)·ω² + Σ ½(m'_B + m_rod/2)·v_j² (DriveSizing.h).
KineticEnergyRows kineticEnergyRows(const Scene& sc, const Csv& ts) {
  const std::vector<double>& t = ts.col("t");
  const std::vector<double>& w = ts.col("omega_crank");
  const double m_rod_half = sc.rods.model == RodModel::Massless ? 0.0 : 0.5 * sc.rods.mass;
  const double J1 = sc.motorSideInertia(),
               Jc = sc.crankSideInertia() + sc.carts.count * m_rod_half * sc.crank.radius * sc.crank.radius;
  KineticEnergyRows k{std::vector<double>(t.size()), std::vector<double>(t.size())};
  for (std::size_t i = 0; i < t.size(); ++i) {
    const double w1 = ts.has("omega_motor") ? ts.col("omega_motor")[i] : w[i];
    k.T[i] = 0.5 * J1 * w1 * w1 + 0.5 * Jc * w[i] * w[i];
    for (int j = 1; j <= sc.carts.count; ++j) {
      const double v = ts.col("v_cart_" + std::to_string(j))[i];
      k.T[i] += 0.5 * (sc.carts.mass + m_rod_half) * v * v;
    }
    k.J[i] = 2.0 * k.T[i] / (w[i] * w[i]);
  }
  return k;
}

// ΔT, the largest max - min of T within one whole revolution of the window, and the largest T
// (the size of its operands).
std::pair<double, double> kineticEnergySwing(const RunFiles& f, const std::vector<double>& T) {
  const std::vector<double>& t = f.ts.col("t");
  double dT = 0, T_max = 0;
  const std::vector<double>& cross = f.win.crossings;
  for (std::size_t k = cross.size() - 1 - std::size_t(f.win.revolutions); k + 1 < cross.size(); ++k) {
    double lo = INFINITY, hi = -INFINITY;
    for (std::size_t i = f.b; i < f.e; ++i)
      if (t[i] >= cross[k] && t[i] <= cross[k + 1]) lo = std::min(lo, T[i]), hi = std::max(hi, T[i]);
    if (hi >= lo) dT = std::max(dT, hi - lo), T_max = std::max(T_max, hi);
  }
  return {dT, T_max};
}

// The flywheel to add for the target δ* by both methods, compared; returns the one proposed.
double addedFlywheel(Comparison& k, const json& fw, double J, const CrankSpeedByHand& crank, double target) {
  const double added_energy = target > 0 ? std::max(0.0, J * (crank.delta / target - 1.0)) : kNaN;
  // ΔJ inherits δ's operands: judged against J·(ω_max/ω_mean)/δ*.
  k.add("ΔJ = J·(δ/δ* - 1)", added_energy, jsonAt(fw, "added_inertia_energy_method"),
        J * (crank.highest / crank.mean) / target);
  // The excess-work method: ΔA (from the load law at constant speed, checked on its own in the
  // tests against ½ω²(J_max - J_min) of a load-free machine) over δ*·ω̄², ω̄ from the rows here.
  const json& dA = jsonAt(fw, "excess_work");
  if (!(dA.is_number() && target > 0)) {
    k.add("ΔJ (no ΔA: energy method)", added_energy, jsonAt(fw, "added_inertia_crankshaft"),
          J * (crank.highest / crank.mean) / target);
    return added_energy;
  }
  const double J_req = dA.get<double>() / (target * crank.mean * crank.mean);
  const double added = std::max(std::max(0.0, J_req - J), added_energy);
  k.add("J* = ΔA/(δ*·ω̄²)", J_req, jsonAt(fw, "inertia_required"));
  k.add("ΔJ = max(J* - J, J·(δ/δ* - 1))", added, jsonAt(fw, "added_inertia_crankshaft"), J_req);
  return added;
}

// Coupling torque and the flywheel's two estimates: ΔT per revolution, J = time mean of 2T/ω²,
// ΔJ = J·(δ/δ* - 1) for the target δ* (energy method) and ΔJ = ΔA/(δ*·ω̄²) - J (excess work, the
// proposal when ΔA is known).
void checkCouplingAndFlywheel(ValidationSection& s, const Scene& sc, const std::string& who, const RunFiles& f,
                              const CrankSpeedByHand& crank) {
  const std::vector<double>& t = f.ts.col("t");
  const std::size_t b = f.b, e = f.e;
  const std::vector<double>& Mc = f.ts.col("coupling_torque");
  const auto [clo, chi] = std::minmax_element(Mc.begin() + long(b), Mc.begin() + long(e));
  const double cpeak = std::max(std::abs(*clo), std::abs(*chi));
  const KineticEnergyRows kinetic = kineticEnergyRows(sc, f.ts);
  const auto [dT, T_max] = kineticEnergySwing(f, kinetic.T);
  const double J = integral(t, kinetic.J, b, e) / f.span;
  const json& c = jsonAt(f.sz, "coupling");
  const json& fw = jsonAt(f.sz, "flywheel");
  Comparison k;
  k.add("coupling mean", integral(t, Mc, b, e) / f.span, jsonAt(c, "mean"), cpeak);
  k.add("coupling peak", cpeak, jsonAt(c, "peak"));
  k.add("coupling swing", *chi - *clo, jsonAt(c, "swing"));
  k.add("ΔT per revolution", dT, jsonAt(fw, "kinetic_energy_swing"), T_max);  // a difference of T values
  k.add("J = mean 2T/ω²", J, jsonAt(fw, "inertia_effective"));
  const double target = sc.sizing.target_delta;
  const double added = addedFlywheel(k, fw, J, crank, target);
  s.claim(k.holds(), who + ": coupling torque mean " + g(integral(t, Mc, b, e) / f.span, 4) + ", peak " + g(cpeak, 4) +
                         ", swing " + g(*chi - *clo, 4) + " N·m; kinetic energy swing per revolution ΔT = " + g(dT, 4) +
                         " J, J = " + g(J, 5) + " kg·m², flywheel to add for δ* = " + g(target) + ": " + g(added, 4) +
                         " kg·m²: " + k.sentence() + ".");
}

// The checks on one run of the scene: its CSV text and its summary.json, as a user gets them.
void checkRun(ValidationSection& s, const Scene& sc, const std::string& who, const std::string& ts_csv,
              const std::string& rx_csv, const std::string& extrema_csv, const json& summary) {
  RunFiles f{columnsOf(ts_csv, "timeseries.csv"), columnsOf(extrema_csv, "crank_speed_extrema.csv"),
             rx_csv.empty() ? Csv{} : columnsOf(rx_csv, "reactions.csv"), summary,
             summary.at("sizing"), {}};
  const int N = std::max(1, int(std::floor(sc.simulation.steady_window_revolutions)));
  f.win = lastRevolutions(f.ts.col("t"), f.ts.col("phi_crank"), N);
  f.b = f.win.b, f.e = f.win.e;
  if (f.win.revolutions < 1 || f.e < f.b + 2) throw std::runtime_error(who + ": fewer than one whole crank revolution");
  f.span = f.ts.col("t")[f.e - 1] - f.ts.col("t")[f.b];
  const CrankSpeedByHand crank = checkWindow(s, who, f);
  if (jsonAt(f.sz, "motor").is_object()) checkMotor(s, sc, who, f, crank);
  checkCouplingAndFlywheel(s, sc, who, f, crank);
  if (!f.rx.names.empty()) checkJoints(s, sc, who, f);
}

// What is recomputed, by which definitions, and the tolerance (`command`: the run's command).
void sizingIntroduction(std::ostream& text, const std::string& command) {
  text << "The scene `model/balanced-4cart.yaml` as shipped, run by both models, with bearing ratings C and a "
          "target δ* given only so that every figure is computed: `"
       << command
       << "` (and `--model reduced`). Every figure of the drive sizing (summary.json `sizing`, the table the "
          "console prints) is recomputed here from the columns of timeseries.csv and reactions.csv as written, "
          "by the definitions the documentation states, sharing no code with the sizing: the steady window as "
          "the last N whole crank revolutions (N = simulation.steady_window_revolutions), time means and RMS by "
          "trapezoids over its rows, the equivalent load P = (∫|F|³·n dt / ∫n dt)^(1/3) (F: joint force, n: the "
          "joint's rotation speed), L10 = (C/P)³·10⁶ revolutions (ball-bearing exponent 3), L10h = "
          "L10/(n̄/2π·3600), M_n = M_kr/λ. Tolerance 1e-9 of each figure's scale, the size of the operands "
          "it is computed from (for the slip 1 − ω_r/ω0: 1; for δ: ω_max/ω_mean; for ΔT: the largest T; for "
          "a mean of a swinging signal: its peak): the CSV's 12 digits and the summation order account for ~1e-12 of that, a wrong "
          "definition moves a figure by 1e-3 or more.\n\n";
}

}  // namespace

ValidationSection driveSizingChecks(const ItemContext& ctx) {
  ValidationSection s("sizing", "Drive sizing recomputed by hand from the run's tables");
  // Ratings and a target δ, so that every sizing figure is computed (the scene gives none):
  // assumed catalogue-like values, not a design; they only set C and δ* in the formulas.
  const std::vector<std::string> sets = {"sizing.target_delta=0.005",       "sizing.bearing_rating.guide_roller=60000",
                                         "sizing.bearing_rating.rod_end=150000", "sizing.bearing_rating.crank_pin=150000",
                                         "sizing.bearing_rating.main_bearing=400000"};
  const Scene sc = ctx.load("balanced-4cart.yaml", sets);
  sizingIntroduction(s.text(), ctx.command("simulate", "balanced-4cart.yaml", sets));
  for (const bool multibody : {true, false}) {
    if (ctx.interrupted()) break;
    const RunResult run = runModel(sc, multibody ? "multibody" : "reduced");
    if (!run.stats.complete) throw std::runtime_error(run.model + " run ended early: " + run.stats.status);
    const json summary = json::parse(makeSummary(sc, run).dump());  // as summary.json stores it
    checkRun(s, sc, multibody ? "multibody model" : "reduced model", toCsv(run.timeseries),
             run.reactions.columns.empty() ? std::string() : toCsv(run.reactions),
             toCsv(crankSpeedExtremaTable(run.crank_speed_extrema)), summary);
  }
  return s;
}

}  // namespace rollerdyn::validation
