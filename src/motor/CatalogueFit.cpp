#include "motor/CatalogueFit.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <ctime>
#include <map>
#include <mutex>
#include <stdexcept>

#include <nlopt.hpp>

#include "motor/ExactKey.h"
#include "motor/FitCache.h"
#include "motor/FitSourceHash.h"  // generated (CMakeLists.txt)
#include "process/ProcessShared.h"
#include "scene/Scene.h"

namespace rollerdyn {

namespace {

constexpr double kSqrt3 = 1.7320508075688772;
// Changing what a fit computes (weights, bounds, guess, tolerances, starts): bump
// kCatalogueFitVersion (CatalogueFit.h), so no kept fit of the old method is read.
// Weights of the relative errors, in the order of compareWithCatalogue (header: why).
constexpr double kCatalogueWeights[7] = {10, 3, 1, 1, 10, 3, 10};
// Bounds of the unknowns in per-unit of Z_b = U_ph/I_n, in the order R_s, X_σs (= X_σr1), X_m,
// R_r1, R_r2, X_σr2: a wide band around the values of squirrel-cage motors (leakage 0.05-0.2,
// magnetizing 1.5-5, resistances 0.005-0.1 per unit), so that a catalogue the circuit cannot meet
// gives a machine at a bound rather than a vanishing leakage inductance (an unphysical,
// infinitely stiff machine).
constexpr double kLowerPu[6] = {1e-4, 0.01, 0.5, 1e-4, 1e-4, 0.005};
constexpr double kUpperPu[6] = {0.3, 1.0, 50.0, 0.5, 2.0, 2.0};

// Torque at the rated supply and rotor speed ω_r.
double torqueAt(const InductionMachineParameters& m, double omega_rotor) {
  return solveCircuit(m, m.phase_voltage, m.supplyAngularFrequency(), omega_rotor).torque;
}
double speedOfSlip(const InductionMachineParameters& m, double s) { return m.synchronousSpeed() * (1.0 - s); }

// Unknowns ↔ circuit, in per-unit of Z_b = U_ph/I_n (reactances at f_n), log-scaled.
struct Layout {
  int cages;
  double z_base, w1;
  int size() const { return cages == 2 ? 6 : 4; }
  void toMachine(const double* x, InductionMachineParameters& m) const {
    auto pu = [&](int i) { return std::exp(x[i]) * z_base; };
    m.cages = cages;
    m.R_s = pu(0);
    m.L_sigma_s = pu(1) / w1;
    m.L_m = pu(2) / w1;
    m.R_r[0] = pu(3);
    m.L_sigma_r[0] = m.L_sigma_s;  // X_σr1 = X_σs (header)
    if (cages == 2) {
      m.R_r[1] = pu(4);
      m.L_sigma_r[1] = pu(5) / w1;
    } else {
      m.R_r[1] = m.L_sigma_r[1] = 0.0;
    }
  }
};

struct Problem {
  const MotorCatalogue* cat;
  InductionMachineParameters base;
  Layout layout;
  int evaluations = 0;
  double residuals(const double* x, std::array<double, 7>* r) {
    ++evaluations;
    InductionMachineParameters m = base;
    layout.toMachine(x, m);
    const std::vector<CatalogueComparison> pts = compareWithCatalogue(m, *cat);
    double cost = 0;
    for (size_t i = 0; i < pts.size(); ++i) {
      const double e = pts[i].relativeError();
      if (r) (*r)[i] = e;
      cost += std::isfinite(e) ? kCatalogueWeights[i] * kCatalogueWeights[i] * e * e : 1e30;
    }
    return cost;
  }
};

double objective(unsigned n, const double* x, double*, void* data) {
  return static_cast<Problem*>(data)->residuals(x, nullptr);
}

// Initial guess from the catalogue in per-unit of Z_b (header).
std::vector<double> initialGuess(const MotorCatalogue& c, const CatalogueSupply& s, int cages) {
  const double u = s.line_voltage / kSqrt3, i_n = c.current, z_b = u / i_n;
  const double w1 = 2.0 * M_PI * s.frequency, w0 = w1 / s.pole_pairs;
  const double m_n = c.nominalTorque(), m_k = c.breakdown_torque_ratio * m_n;
  const double lambda = c.breakdown_torque_ratio, s_n = 1.0 - c.omega_nominal / w0;
  // R_s = 0 circuit: M_k = 3p·U²/(2·ω1·X_σ), s_k = R_r/X_σ = s_n(λ + √(λ² − 1)).
  const double x_sigma = 3.0 * s.pole_pairs * u * u / (2.0 * w1 * m_k);
  const double s_k = std::min(0.9, s_n * (lambda + std::sqrt(lambda * lambda - 1.0)));
  const double r_r = s_k * x_sigma;
  const double sin_phi = std::sqrt(std::max(1e-4, 1.0 - c.power_factor * c.power_factor));
  const double x_m = u / (i_n * sin_phi);
  const double p_in = 3.0 * u * i_n * c.power_factor;
  const double stator_loss = std::max(0.01 * p_in, p_in - m_n * w0);
  const double r_s = stator_loss / (3.0 * i_n * i_n);
  std::vector<double> g = {r_s, 0.5 * x_sigma, x_m, r_r};
  if (cages == 2) {
    g[1] = 0.6 * x_sigma;  // running-cage leakage dominates at small slip
    g.push_back(4.0 * r_r);          // starting cage: several times the running resistance,
    g.push_back(0.15 * x_sigma);     // little leakage
  }
  for (double& v : g) v = std::log(v / z_b);
  return g;
}

}  // namespace

double breakdownSlip(const InductionMachineParameters& m, double* torque) {
  // Coarse log-spaced scan of 0 < s ≤ 1, then golden-section refinement around the best point.
  const int n = 40;
  const double s_lo = 1e-4;
  double best_s = 1.0, best_m = -1e300;
  for (int i = 0; i <= n; ++i) {
    const double s = s_lo * std::pow(1.0 / s_lo, double(i) / n);
    const double mt = torqueAt(m, speedOfSlip(m, s));
    if (mt > best_m) best_m = mt, best_s = s;
  }
  const double step = std::pow(1.0 / s_lo, 1.0 / n);
  double a = std::max(s_lo, best_s / step), b = std::min(1.0, best_s * step);
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int it = 0; it < 60 && b - a > 1e-13; ++it) {
    const double c = b - g * (b - a), d = a + g * (b - a);
    if (torqueAt(m, speedOfSlip(m, c)) > torqueAt(m, speedOfSlip(m, d))) b = d; else a = c;
  }
  double s = 0.5 * (a + b), mt = torqueAt(m, speedOfSlip(m, s));
  const double m1 = torqueAt(m, speedOfSlip(m, 1.0));
  if (m1 > mt) s = 1.0, mt = m1;  // maximum at standstill
  if (torque) *torque = mt;
  return s;
}

std::vector<CatalogueComparison> compareWithCatalogue(const InductionMachineParameters& m, const MotorCatalogue& c) {
  const double u = m.phase_voltage, w1 = m.supplyAngularFrequency();
  const double m_n = c.nominalTorque();
  const CircuitSolution rated = solveCircuit(m, u, w1, c.omega_nominal);
  const CircuitSolution start = solveCircuit(m, u, w1, 0.0);
  double m_k = 0;
  breakdownSlip(m, &m_k);
  return {
      {"rated torque", "M_n", "N·m", m_n, rated.torque},
      {"rated current", "I_n", "A", c.current, rated.current},
      {"rated power factor", "cos φ_n", "-", c.power_factor, rated.power_factor},
      {"rated efficiency", "η_n", "-", c.efficiency, rated.torque * c.omega_nominal / rated.electrical_power},
      {"starting torque", "M_s", "N·m", c.starting_torque_ratio * m_n, start.torque},
      {"starting current", "I_s", "A", c.starting_current_ratio * c.current, start.current},
      {"breakdown torque", "M_k", "N·m", c.breakdown_torque_ratio * m_n, m_k},
  };
}

namespace {
// The linked NLopt's version, "major.minor.bugfix": another version may stop at another optimum.
std::string nloptVersion() {
  int major = 0, minor = 0, bugfix = 0;
  nlopt::version(major, minor, bugfix);
  return std::to_string(major) + "." + std::to_string(minor) + "." + std::to_string(bugfix);
}
}  // namespace

std::string catalogueFitKey(const MotorCatalogue& catalogue, const CatalogueSupply& supply, int cages) {
  // Every field by name: a new field fails to compile here until it is keyed (or said unread).
  const auto& [power, omega_nominal, current, power_factor, efficiency, starting_torque_ratio, breakdown_torque_ratio,
               starting_current_ratio, catalogue_cages] = catalogue;
  (void)catalogue_cages;  // not read by the fit: the argument `cages` says how many cages to fit
  const auto& [line_voltage, frequency, pole_pairs] = supply;
  return ExactKey()
      .add("catalogue_fit_version", kCatalogueFitVersion)
      .add("fit_sources", std::string(ROLLERDYN_FIT_SOURCE_HASH))  // any edit of the fitting code
      .add("nlopt", nloptVersion())
      .add("power", power)
      .add("omega_nominal", omega_nominal)
      .add("current", current)
      .add("power_factor", power_factor)
      .add("efficiency", efficiency)
      .add("starting_torque_ratio", starting_torque_ratio)
      .add("breakdown_torque_ratio", breakdown_torque_ratio)
      .add("starting_current_ratio", starting_current_ratio)
      .add("line_voltage", line_voltage)
      .add("frequency", frequency)
      .add("pole_pairs", pole_pairs)
      .add("cages", cages)
      .text();
}

std::string FitOrigin::describe() const {
  char seconds[32];
  std::snprintf(seconds, sizeof seconds, "%.2f s", fit_seconds);
  if (from_cache) return "from the cache " + cache_file + " (fitted on " + fitted_on + " in " + seconds + ")";
  return std::string("fitted now in ") + seconds +
         (cache_file.empty() ? ", not kept (no writable cache folder)" : ", kept in " + cache_file);
}

namespace {

CatalogueFit computeFit(const MotorCatalogue& c, const CatalogueSupply& s, int cages);

// The fit of `machine`, computed or kept: its catalogue points are computed here in either case.
CatalogueFit completeFit(const InductionMachineParameters& machine, const MotorCatalogue& c, int starts,
                         int evaluations) {
  CatalogueFit fit;
  fit.machine = machine;
  fit.points = compareWithCatalogue(fit.machine, c);
  for (const auto& p : fit.points) fit.max_relative_error = std::max(fit.max_relative_error, std::abs(p.relativeError()));
  fit.starts = starts;
  fit.evaluations = evaluations;
  return fit;
}

// computeFit, timed and dated.
CatalogueFit timedFit(const MotorCatalogue& c, const CatalogueSupply& s, int cages) {
  const auto start = std::chrono::steady_clock::now();
  CatalogueFit fit = computeFit(c, s, cages);
  fit.origin.fit_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char date[40];
  std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", &utc);
  fit.origin.fitted_on = date;
  return fit;
}

}  // namespace

CatalogueFit fitCatalogueThroughDiskCache(const MotorCatalogue& c, const CatalogueSupply& s, int cages) {
  const std::string key = catalogueFitKey(c, s, cages);
  const std::string file = fitCacheFile(key);
  if (const std::optional<KeptFit> kept = readKeptFit(file, key)) {
    CatalogueFit fit = completeFit(kept->machine, c, kept->starts, kept->evaluations);
    fit.origin = {true, file, kept->fitted_on, kept->fit_seconds};
    return fit;
  }
  CatalogueFit fit = timedFit(c, s, cages);
  if (writeKeptFit(file, key, {fit.machine, fit.starts, fit.evaluations, fit.origin.fitted_on, fit.origin.fit_seconds}))
    fit.origin.cache_file = file;
  return fit;
}

CatalogueFit fitCatalogue(const MotorCatalogue& c, const CatalogueSupply& s, int cages, bool use_cache) {
  if (!use_cache) return timedFit(c, s, cages);
  struct Memory {
    std::mutex mutex;
    std::map<std::string, CatalogueFit> fits;
  };
  // One per process, also when the reduced model's library asks (ProcessShared.h). The name
  // carries the version: a type changed with it is never shared with an older one.
  static Memory& memory = processShared<Memory>("catalogue fits v1");
  const std::string key = catalogueFitKey(c, s, cages);
  {
    std::lock_guard<std::mutex> lock(memory.mutex);
    const auto it = memory.fits.find(key);
    if (it != memory.fits.end()) return it->second;
  }
  CatalogueFit fit = fitCatalogueThroughDiskCache(c, s, cages);  // outside the lock: other motors in parallel
  std::lock_guard<std::mutex> lock(memory.mutex);
  return memory.fits.emplace(key, std::move(fit)).first->second;
}

namespace {

// The catalogue data and supply a fit needs (std::invalid_argument saying what is missing).
void checkFitInputs(const MotorCatalogue& c, const CatalogueSupply& s, int cages) {
  if (!c.given() || !(c.omega_nominal > 0 && c.current > 0 && c.power_factor > 0 && c.efficiency > 0 &&
                      c.starting_torque_ratio > 0 && c.breakdown_torque_ratio > 1 && c.starting_current_ratio > 1))
    throw std::invalid_argument("catalogue fit: incomplete catalogue data");
  if (!(s.line_voltage > 0 && s.frequency > 0 && s.pole_pairs >= 1))
    throw std::invalid_argument("catalogue fit: rated voltage, frequency and pole pairs needed");
  if (cages != 1 && cages != 2) throw std::invalid_argument("catalogue fit: 1 or 2 cages");
  if (!(c.omega_nominal < 2.0 * M_PI * s.frequency / s.pole_pairs))
    throw std::invalid_argument("catalogue fit: rated speed must be below the synchronous speed");
}

// One local fit (BOBYQA) from x, within the per-unit bounds; x ends where it got to. Its cost.
double localFit(Problem& prob, std::vector<double>& x) {
  const int n = prob.layout.size();
  nlopt::opt opt(nlopt::LN_BOBYQA, n);
  std::vector<double> lo(n), hi(n);
  for (int i = 0; i < n; ++i) {
    lo[i] = std::log(kLowerPu[i]), hi[i] = std::log(kUpperPu[i]);
    x[i] = std::clamp(x[i], lo[i] + 1e-9, hi[i] - 1e-9);
  }
  opt.set_lower_bounds(lo);
  opt.set_upper_bounds(hi);
  opt.set_min_objective(objective, &prob);
  opt.set_ftol_rel(1e-14);
  opt.set_xtol_rel(1e-10);
  opt.set_maxeval(2000);
  opt.set_initial_step(0.3);
  double cost = 0;
  try {
    opt.optimize(x, cost);
  } catch (const std::exception&) {
    cost = prob.residuals(x.data(), nullptr);  // roundoff-limited: keep where it got to
  }
  return cost;
}

// Every residual at x below 1e-9: the catalogue met.
bool meetsCatalogue(Problem& prob, const std::vector<double>& x) {
  std::array<double, 7> r{};
  prob.residuals(x.data(), &r);
  double worst = 0;
  for (double e : r) worst = std::max(worst, std::abs(e));
  return worst < 1e-9;
}

// The best of the local fits from x0 and from random points around it, and how many starts ran.
struct BestStart {
  std::vector<double> x;
  int starts = 0;
};

// Random start points around the guess, from a fixed seed: the fit is reproducible.
class RandomStarts {
 public:
  // x0 with every (logarithmic) parameter moved by a factor up to e^±1.5.
  std::vector<double> around(const std::vector<double>& x0) {
    std::vector<double> x = x0;
    for (double& v : x) v += 1.5 * (2.0 * uniform() - 1.0);
    return x;
  }

 private:
  // The next number of a linear congruential generator, uniform in [0, 1).
  double uniform() {
    lcg_ = lcg_ * 6364136223846793005ULL + 1442695040888963407ULL;
    return double(lcg_ >> 11) / double(1ULL << 53);
  }
  unsigned long long lcg_ = 0x2545F4914F6CDD1DULL;
};

BestStart multiStart(Problem& prob, const std::vector<double>& x0) {
  BestStart best{x0, 0};
  double best_cost = prob.residuals(x0.data(), nullptr);
  RandomStarts random;
  // Starts until every residual is below 1e-9 (the catalogue met), or the best cost has not
  // improved by 1e-9 relative over kPatience starts, or kMaxStarts are used.
  constexpr int kMaxStarts = 60, kPatience = 15;
  int since_better = 0;
  for (; best.starts < kMaxStarts && since_better < kPatience; ++best.starts) {
    std::vector<double> x = best.starts > 0 ? random.around(x0) : x0;
    const double cost = localFit(prob, x);
    if (cost < best_cost * (1.0 - 1e-9)) {
      best_cost = cost, best.x = x, since_better = 0;
    } else {
      ++since_better;
    }
    if (meetsCatalogue(prob, best.x)) {
      ++best.starts;
      break;
    }
  }
  return best;
}

CatalogueFit computeFit(const MotorCatalogue& c, const CatalogueSupply& s, int cages) {
  checkFitInputs(c, s, cages);
  Problem prob;
  prob.cat = &c;
  prob.base.pole_pairs = s.pole_pairs;
  prob.base.phase_voltage = s.line_voltage / kSqrt3;
  prob.base.frequency = s.frequency;
  prob.layout = {cages, prob.base.phase_voltage / c.current, 2.0 * M_PI * s.frequency};
  const int n = prob.layout.size();
  std::vector<double> x0 = initialGuess(c, s, cages);
  for (int i = 0; i < n; ++i) x0[i] = std::clamp(x0[i], std::log(kLowerPu[i]) + 1e-9, std::log(kUpperPu[i]) - 1e-9);

  const BestStart best = multiStart(prob, x0);
  InductionMachineParameters machine = prob.base;
  prob.layout.toMachine(best.x.data(), machine);
  machine.validate();
  return completeFit(machine, c, best.starts, prob.evaluations);
}

}  // namespace

}  // namespace rollerdyn
