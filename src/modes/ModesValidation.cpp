#include "modes/ModesValidation.h"

#include "modes/ChainModes.h"

#include <cmath>
#include <complex>
#include <cstdarg>
#include <cstdio>
#include <ctime>
#include <sstream>

#include "modes/DriveModels.h"
#include "modes/DriveOrbit.h"
#include "modes/Floquet.h"
#include "modes/FrozenModes.h"
#include "modes/GrowthCheck.h"
#include "modes/PeriodicFlow.h"
#include "physics/TwoRotorClosedForm.h"
#include "reduced/ReducedModel.h"
#include "scene/SceneParser.h"
#include "io/FieldFormat.h"

namespace rollerdyn::modes {

int ModesValidationResult::failed() const {
  int n = 0;
  for (const ModesCheck& c : checks) n += c.is_claim && !c.pass;
  return n;
}

namespace {

double mathieuTrace(double delta, double eps) {
  PeriodicSystem s;
  s.n = 2;
  s.period = 2 * M_PI;
  s.scale = Eigen::Vector2d(1, 1);
  s.rhs = [=](double t, const Eigen::VectorXd& x, Eigen::VectorXd& f) {
    f.resize(2);
    f << x(1), -(delta + eps * std::cos(t)) * x(0);
  };
  s.jacobian = [=](double t, const Eigen::VectorXd&, Eigen::MatrixXd& A) {
    A.resize(2, 2);
    A << 0, 1, -(delta + eps * std::cos(t)), 0;
  };
  FlowOptions o;
  o.rtol = 1e-12;
  o.atol_scale = 1e-12;
  return flowOverPeriod(s, Eigen::Vector2d(1, 0), o).monodromy.trace();
}

double mathieuTransition(double eps, double target, double lo, double hi) {
  double flo = mathieuTrace(lo, eps) - target;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi), fm = mathieuTrace(mid, eps) - target;
    if (fm * flo > 0) {
      lo = mid;
      flo = fm;
    } else {
      hi = mid;
    }
  }
  return 0.5 * (lo + hi);
}

// The chain's eigen-solution against Holzer's search at four frozen crank angles.
struct HolzerComparison {
  double worst = 0;           // largest relative difference of the frequencies (infinite: counts differ)
  std::vector<double> first;  // the elastic modes' p at crank angle 0 [rad/s]
  size_t count_eig = 0, count_holzer = 0;  // elastic modes each finds
};
HolzerComparison compareWithHolzer(const Scene& s) {
  HolzerComparison h;
  for (double phi : {0.0, 0.7, 2.0, 4.5}) {
    std::vector<double> J, c;
    chainAtAngle(s, phi, J, c);
    const std::vector<double> eig = chainNaturalFrequencies(J, c);
    const std::vector<double> holzer = holzerFrequencies(J, c, 1.2 * eig.back(), 40000);
    h.count_eig = std::max(h.count_eig, eig.size() - 1);
    h.count_holzer = std::max(h.count_holzer, holzer.size());
    if (holzer.size() + 1 != eig.size()) {
      h.worst = INFINITY;
      continue;
    }
    for (size_t m = 0; m < holzer.size(); ++m)
      h.worst = std::max(h.worst, std::abs(holzer[m] - eig[m + 1]) / eig[m + 1]);
    if (h.first.empty()) h.first.assign(eig.begin() + 1, eig.end());
  }
  return h;
}

// The chain's frequencies of the eigen-solution (ChainModes.h) against Holzer's residual-torque
// search, which finds its roots without being told them, at four frozen crank angles: the same
// numbers to the bisection's 1e-12 and the eigen-solver's round-off, so 1e-9 relative.
ModesCheck chainAgainstHolzer(const Scene& s, nlohmann::json& out) {
  const HolzerComparison h = compareWithHolzer(s);
  ModesCheck ck;
  ck.name = "crankshaft_chain_holzer";
  ck.pass = h.worst <= 1e-9;
  std::string list;
  for (double p : h.first) list += (list.empty() ? "" : ", ") + printfText("%.6g", p);
  ck.line = printfText("modes: crankshaft as a torsional chain (4 throws 0.3 m apart, G*I_p = 7.85e5 N*m^2, 100 mm steel "
                "shaft): %zu elastic modes by the eigen-solution, %zu by Holzer's residual torque; at crank angle 0: "
                "p = %s rad/s; largest relative difference over 4 angles %.2e (<= 1e-9): %s",
                h.count_eig, h.count_holzer, list.c_str(), h.worst, ck.pass ? "holds" : "FAILS");
  out["crankshaft_chain_holzer"] = {{"p_at_angle_0", h.first}, {"max_rel_diff", h.worst}, {"tolerance", 1e-9},
                                    {"pass", ck.pass}};
  return ck;
}

const char* verdictWord(bool pass) { return pass ? "holds" : "FAILS"; }

// Where the checks go: the result, in the order they ran, and the console, a line each as it comes.
struct CheckRecorder {
  ModesValidationResult& result;
  const std::function<void(const std::string&)>& log;
  void add(const ModesCheck& c) const {
    if (log) log(c.line);
    result.checks.push_back(c);
  }
};

// A shipped scene of model_dir with --set overrides.
Scene shippedScene(const std::string& model_dir, const std::string& name, const std::vector<std::string>& overrides) {
  return parseSceneFile(model_dir + "/" + name + ".yaml", overrides);
}

// The constant-inertia drive's frequencies at four frozen crank angles.
struct ConstantInertiaFrequencies {
  double worst = 0;               // largest relative difference of either model's p from p0
  double p_red = 0, p_mb = 0, p0 = 0;  // at the last angle [rad/s]: reduced, multibody, Dyomin's
};
ConstantInertiaFrequencies constantInertiaFrequencies(const Scene& s) {
  const ReducedModel rm(s);
  ConstantInertiaFrequencies f;
  auto red = makeReducedDrive(s), mb = makeMultibodyDrive(s);
  for (double phi : {0.0, 0.7, 2.0, 4.5}) {
    DrivePoint p;
    p.phi = phi;
    p.omega = 10.6;
    TwoRotorParameters tp;
    tp.J1 = s.motorSideInertia();
    tp.J2 = rm.crankSideInertia(phi);
    tp.k = s.coupling.stiffness;
    f.p0 = naturalFrequency(tp);  // Dyomin (two rotors) eq. (10), physics/TwoRotorClosedForm
    f.p_red = frozenModes(*red, s, p).torsional_frequency();
    f.p_mb = frozenModes(*mb, s, p).torsional_frequency();
    f.worst = std::max({f.worst, std::abs(f.p_red - f.p0) / f.p0, std::abs(f.p_mb - f.p0) / f.p0});
  }
  return f;
}

// 1. Constant inertia: both models' frozen-angle frequency against Dyomin's two-rotor p0.
void checkConstantInertia(const std::string& model_dir, const CheckRecorder& rec) {
  const Scene s = shippedScene(model_dir, "balanced-4cart",
                               {"carts.mass=1e-6", "rods.model=massless", "flywheel.inertia=400",
                                "loads.roller_force_front=0", "loads.roller_force_rear=0",
                                "loads.roller_normal_front=0", "loads.roller_normal_rear=0",
                                "loads.guide_friction.coefficient=0", "loads.gravity=0"});
  const ConstantInertiaFrequencies f = constantInertiaFrequencies(s);
  ModesCheck c;
  c.name = "constant_inertia_p0";
  c.pass = f.worst <= 1e-8;
  c.line = printfText("modes: constant inertia (flywheel 400 kg*m^2, carts of 1 mg, no loads): frozen-angle p reduced "
               "%.12g, multibody %.12g, Dyomin p0 (two-rotor closed form) %.12g rad/s; largest relative "
               "difference %.2e (<= 1e-8): %s",
               f.p_red, f.p_mb, f.p0, f.worst, verdictWord(c.pass));
  rec.add(c);
  rec.result.json["constant_inertia"] = {{"p_reduced", f.p_red}, {"p_multibody", f.p_mb}, {"p0", f.p0},
                                         {"max_rel_diff", f.worst}, {"tolerance", 1e-8}, {"pass", c.pass}};
}

// A transition curve of the Mathieu equation: where Floquet's trace reaches `target` between lo
// and hi, against the published expansion to its first and to its next term, with their bounds.
struct MathieuCurve {
  const char* name;
  double target, lo, hi, first, second, bound_first, bound_second;
};

std::vector<MathieuCurve> mathieuCurves(double eps) {
  const double e2 = eps * eps, e3 = e2 * eps, e4 = e2 * e2;
  return {{"1/4 + eps/2", -2, 0.25, 0.25 + eps, 0.25 + eps / 2, 0.25 + eps / 2 - e2 / 8, e2 / 8 + 2 * e3, 2 * e3},
          {"1/4 - eps/2", -2, 0.25 - eps, 0.25, 0.25 - eps / 2, 0.25 - eps / 2 - e2 / 8, e2 / 8 + 2 * e3, 2 * e3},
          {"1 - eps^2/12", 2, 1 - e2 / 4, 1 + e2 / 8, 1 - e2 / 12, 1 - e2 / 12 + 0.00145 * e4, 0.01 * e4 + 1e-9,
           0.01 * e4 + 1e-9},
          {"1 + 5 eps^2/12", 2, 1 + e2 / 8, 1 + e2, 1 + 5 * e2 / 12, 1 + 5 * e2 / 12 - 0.2208 * e4, 0.25 * e4,
           0.05 * e4}};
}

// 2. The Mathieu equation's transition curves through the Floquet code.
void checkMathieuCurves(const CheckRecorder& rec) {
  nlohmann::json rows = nlohmann::json::array();
  for (double eps : {0.05, 0.1, 0.2})
    for (const MathieuCurve& cv : mathieuCurves(eps)) {
      const double d = mathieuTransition(eps, cv.target, cv.lo, cv.hi);
      ModesCheck c;
      c.name = std::string("mathieu ") + cv.name;
      const double err1 = std::abs(d - cv.first), err2 = std::abs(d - cv.second);
      c.pass = err1 <= cv.bound_first && err2 <= cv.bound_second;
      c.line = printfText("modes: Mathieu eps = %.2f, curve delta = %s: Floquet %.10f, expansion %.10f (diff %.2e, "
                   "bound %.1e), with the next term %.10f (diff %.2e, bound %.1e): %s",
                   eps, cv.name, d, cv.first, err1, cv.bound_first, cv.second, err2, cv.bound_second,
                   verdictWord(c.pass));
      rec.add(c);
      rows.push_back({{"eps", eps}, {"curve", cv.name}, {"delta", d}, {"expansion", cv.first},
                      {"expansion_next_term", cv.second}, {"pass", c.pass}});
    }
  rec.result.json["mathieu"] = rows;
}

// ẍ + 2ζωẋ + ω²x = 0 as a periodic system of period T.
PeriodicSystem dampedOscillator(double w, double zeta, double T) {
  PeriodicSystem s;
  s.n = 2;
  s.period = T;
  s.scale = Eigen::Vector2d(1, w);
  s.rhs = [=](double, const Eigen::VectorXd& x, Eigen::VectorXd& f) {
    f.resize(2);
    f << x(1), -w * w * x(0) - 2 * zeta * w * x(1);
  };
  return s;
}

// 3. A damped constant-coefficient system: its multipliers against exp(λT).
void checkDampedOscillator(const CheckRecorder& rec) {
  const double w = 7.0, zeta = 0.05, T = 2.3;
  FlowOptions o;
  o.rtol = 1e-12;
  o.atol_scale = 1e-12;
  const auto m =
      floquetMultipliers(flowOverPeriod(dampedOscillator(w, zeta, T), Eigen::Vector2d(0.3, -0.1), o).monodromy, T, w);
  const std::complex<double> e = std::exp(std::complex<double>(-zeta * w, w * std::sqrt(1 - zeta * zeta)) * T);
  double worst = 0;
  for (const auto& f : m) worst = std::max(worst, std::min(std::abs(f.mu - e), std::abs(f.mu - std::conj(e))) / std::abs(e));
  ModesCheck c;
  c.name = "damped_constant_coefficient";
  c.pass = m.size() == 2 && worst <= 1e-9;
  c.line = printfText("modes: damped oscillator (omega 7 rad/s, zeta 0.05, T 2.3 s): multipliers %.10f%+.10fi, "
               "exp(lambda*T) %.10f%+.10fi, relative difference %.2e (<= 1e-9); zeta from them %.10f: %s",
               m.empty() ? NAN : m[0].mu.real(), m.empty() ? NAN : std::abs(m[0].mu.imag()), e.real(),
               std::abs(e.imag()), worst, m.empty() ? NAN : m[0].damping_ratio, verdictWord(c.pass));
  rec.add(c);
  rec.result.json["damped_oscillator"] = {{"max_rel_diff", worst}, {"pass", c.pass}};
}

// The multibody model's frozen-angle frequencies against the reduced model's over 72 angles of
// the steady motion of one scene; its row of the results.
nlohmann::json modelsAgreeOn(const std::string& model_dir, const std::string& name, const std::vector<std::string>& ov,
                             const CheckRecorder& rec) {
  const Scene s = shippedScene(model_dir, name, ov);
  auto red = makeReducedDrive(s), mb = makeMultibodyDrive(s);
  SteadyMotionOptions so;
  so.samples = 72;
  const SteadyMotion m = steadyMotion(*red, s, so);
  double worst = 0, pmin = INFINITY, pmax = 0;
  for (const DrivePoint& p : m.samples) {
    const double a = frozenModes(*red, s, p).torsional_frequency(), b = frozenModes(*mb, s, p).torsional_frequency();
    worst = std::max(worst, std::abs(a - b) / a);
    pmin = std::min(pmin, a);
    pmax = std::max(pmax, a);
  }
  ModesCheck c;
  c.name = "models_agree_" + name;
  c.pass = m.found && worst <= 1e-6;
  std::string sets;
  for (const std::string& o : ov) sets += " --set " + o;
  c.line = printfText("modes: %s%s: frozen-angle p %.6g ... %.6g rad/s over 72 angles of the steady motion; "
               "multibody against reduced, largest relative difference %.2e (<= 1e-6): %s",
               name.c_str(), sets.c_str(), pmin, pmax, worst, verdictWord(c.pass));
  rec.add(c);
  return {{"scene", name}, {"overrides", ov}, {"max_rel_diff", worst}, {"pass", c.pass}};
}

// 4. Multibody against reduced where both describe the same physics (split rods, no guide friction).
void checkModelsAgree(const std::string& model_dir, const CheckRecorder& rec) {
  nlohmann::json rows = nlohmann::json::array();
  const std::vector<std::pair<std::string, std::vector<std::string>>> cases = {
      {"balanced-4cart", {"rods.model=split", "loads.guide_friction.coefficient=0"}},
      {"recuperative-2cart",
       {"rods.model=split", "loads.guide_friction.coefficient=0", "coupling.type=elastic", "coupling.stiffness=50000",
        "coupling.damping=500"}},
      {"cam-drive", {"loads.guide_friction.coefficient=0"}}};
  for (const auto& [name, ov] : cases) rows.push_back(modelsAgreeOn(model_dir, name, ov, rec));
  rec.result.json["models_agree"] = rows;
}

// 5a. A simulated run at a point the chart marks unstable grows by the predicted multiplier and
// shows the predicted order.
ModesCheck unstablePointGrows(const GrowthMeasurement& u) {
  ModesCheck c;
  c.name = "unstable_point_grows";
  c.pass = u.ok && u.predicted_modulus > 1 && u.revolutions_fitted >= 10 &&
           std::abs(u.measured_growth / u.predicted_modulus - 1) <= 0.06 &&
           std::abs(u.peak_order - u.predicted_order) <= 1.0 / 8 + 1e-9;
  c.line = printfText("modes: two-cart machine (Loveikin and Pochka (2007)) with an undamped elastic coupling c = 24000 "
               "N*m/rad: Floquet |mu| = %.4g per revolution, simulated growth %.4g per revolution over %d "
               "revolutions (ratio %.3f, within 6 %%); predicted order %.3f, spectrum peak at %.3f (resolution "
               "1/8): %s",
               u.predicted_modulus, u.measured_growth, u.revolutions_fitted, u.measured_growth / u.predicted_modulus,
               u.predicted_order, u.peak_order, verdictWord(c.pass));
  return c;
}

// 5b. One at a stable point does not grow. `worst`: its largest departure from the steady motion [rad].
ModesCheck stablePointDoesNotGrow(const GrowthMeasurement& st, double worst, const GrowthMeasurement& u) {
  ModesCheck c2;
  c2.name = "stable_point_does_not_grow";
  c2.pass = st.ok && st.predicted_modulus < 1 && st.deviation.size() >= 29 && worst < 1e-8;
  c2.line = printfText("modes: same machine with k = 300 N*m*s/rad: Floquet |mu| = %.3g (stable); simulated departure from "
                "the steady motion at most %.2e rad over %zu revolutions (< 1e-8; the unstable run grew to %.2e): %s",
                st.predicted_modulus, worst, st.deviation.size(), u.deviation.empty() ? NAN : u.deviation.back(),
                verdictWord(c2.pass));
  return c2;
}

// 5. Simulated runs at an unstable and a stable point.
void checkSimulatedRuns(const std::string& model_dir, const CheckRecorder& rec) {
  auto two_cart = [&](double c, double k) {
    return shippedScene(model_dir, "recuperative-2cart", {"coupling.type=elastic", "coupling.stiffness=" + std::to_string(c),
                                                          "coupling.damping=" + std::to_string(k)});
  };
  const GrowthMeasurement u = measureGrowth(two_cart(24000, 0), 30, 8);
  const ModesCheck c = unstablePointGrows(u);
  rec.add(c);
  const GrowthMeasurement st = measureGrowth(two_cart(24000, 300), 30, 8);
  double worst = 0;
  for (double d : st.deviation) worst = std::max(worst, d);
  const ModesCheck c2 = stablePointDoesNotGrow(st, worst, u);
  rec.add(c2);
  rec.result.json["simulated_runs"] = {
      {"unstable", {{"c", 24000}, {"k", 0}, {"predicted_modulus", u.predicted_modulus}, {"measured_growth", u.measured_growth},
                    {"revolutions_fitted", u.revolutions_fitted}, {"predicted_order", u.predicted_order},
                    {"peak_order", u.peak_order}, {"pass", c.pass}}},
      {"stable", {{"c", 24000}, {"k", 300}, {"predicted_modulus", st.predicted_modulus}, {"max_departure", worst},
                  {"pass", c2.pass}}}};
}

// 6. The papers' machine at the papers' coupling with damping k: the Floquet verdict and the band
// of frozen frequencies (a measurement, no claim); its row of the results.
nlohmann::json paperMachineAt(const std::string& model_dir, double k, const CheckRecorder& rec) {
  const Scene s = shippedScene(model_dir, "balanced-4cart", {"coupling.damping=" + std::to_string(k)});
  auto red = makeReducedDrive(s);
  SteadyMotionOptions so;
  so.samples = 72;
  const SteadyMotion m = steadyMotion(*red, s, so);
  std::vector<double> p;
  for (const DrivePoint& q : m.samples) p.push_back(frozenModes(*red, s, q).torsional_frequency());
  const Band b = bandOf(p);
  ModesCheck c;
  c.name = "paper_machine_k" + std::to_string(int(k));
  c.is_claim = false;
  c.pass = true;
  c.line = printfText("modes: Loveikin, Pochka, Romasevych (2018) machine, c = 200000 N*m/rad, k = %.0f N*m*s/rad: %s, "
               "largest |mu| %.3g per revolution; frozen p %.5g ... %.5g rad/s = %.3g ... %.3g times the crank "
               "speed %.4g rad/s (measurement)",
               k, m.found ? m.verdict.text.c_str() : "no steady motion", m.verdict.max_modulus, b.min, b.max,
               b.min / m.omega_mean, b.max / m.omega_mean, m.omega_mean);
  rec.add(c);
  return {{"k", k}, {"verdict", m.verdict.text}, {"max_modulus", m.verdict.max_modulus},
          {"p_min", b.min}, {"p_max", b.max}, {"omega_mean", m.omega_mean}};
}

}  // namespace

ModesValidationResult runModesValidation(const std::string& model_dir,
                                         const std::function<void(const std::string&)>& log) {
  const std::clock_t c0 = std::clock();
  ModesValidationResult res;
  const CheckRecorder rec{res, log};
  checkConstantInertia(model_dir, rec);
  checkMathieuCurves(rec);
  checkDampedOscillator(rec);
  checkModelsAgree(model_dir, rec);
  checkSimulatedRuns(model_dir, rec);
  // 7. The crankshaft as a torsional chain against Holzer's method.
  rec.add(chainAgainstHolzer(
      shippedScene(model_dir, "balanced-4cart",
                   {"simulation.formulation=constrained", "loads.guide_friction.normal_force=lagged",
                    "crankshaft.throw_positions=[0.2, 0.5, 0.8, 1.1]", "crankshaft.torsional_stiffness=7.85e5"}),
      res.json));
  // 6. The papers' machine at the papers' coupling.
  nlohmann::json rows = nlohmann::json::array();
  for (double k : {0.0, 2000.0, 8000.0}) rows.push_back(paperMachineAt(model_dir, k, rec));
  res.json["paper_machine"] = rows;
  res.cpu_seconds = double(std::clock() - c0) / CLOCKS_PER_SEC;
  res.json["cpu_seconds"] = res.cpu_seconds;
  res.json["failed"] = res.failed();
  return res;
}

std::string modesValidationMarkdown(const ModesValidationResult& r) {
  std::ostringstream os;
  os << "# Torsional modes and Floquet stability: validation\n\n"
     << "Written by `rollerdyn validate`. Each line is one check against an independent reference "
        "(closed forms, published expansions, a simulated run); \"measurement\" lines make no claim.\n\n";
  for (const ModesCheck& c : r.checks) {
    std::string text = c.line.substr(c.line.find(": ") + 2);  // without the "modes: " of the console
    for (const char* verdict : {": holds", ": FAILS"})  // the verdict leads the markdown line instead
      if (text.size() > 7 && text.compare(text.size() - 7, 7, verdict) == 0) text.resize(text.size() - 7);
    os << "- " << (c.is_claim ? (c.pass ? "**holds**: " : "**FAILS**: ") : "") << text << "\n";
  }
  os << "\nCPU " << r.cpu_seconds << " s. The stability charts of the shipped machines are in `modes/<scene>/` "
     << "(regenerate with validation/modes/run.sh).\n";
  return os.str();
}

}  // namespace rollerdyn::modes
