// The identification's set-up and model runs (Identify.h); the numerics are in IdentifyFit.cpp,
// the files and the console text in IdentifyOutputs.cpp.
//
// Choices (docs/identify.md):
// - σ_s not given: first 1e-2 × the RMS of the signal's deviation from its own mean (a fit that
//   weighs each signal by its own swing), then, after that fit, the RMS residual of that signal,
//   and one refit from the first optimum: the weights of a maximum-likelihood fit with Gaussian
//   noise of unknown level per signal (the residuals estimate it).
// - Finite differences: relative step 1e-3 of each key's value (1e-3 of its range at 0), in the
//   scaled parameter. The integration's error at relative accuracy ε moves a signal by ~ε·|y|, and
//   with adaptive steps that error is not smooth in the parameter; the difference quotient then
//   errs by ~ε/1e-3 relative to the signal, against the key's relative sensitivity S. At
//   ε = 1e-8 (the default for identify: min(the scene's accuracy, 1e-8)) that is 1e-5/S, well
//   below 1 % for any key that moves a signal by more than 0.1 % per 1 % change.
// - The model's output every min(scene output step, median measured spacing), interpolated
//   linearly onto the measured times.
#include "studies/Identify.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <cmath>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <thread>

#include <nlopt.hpp>
#include <yaml-cpp/yaml.h>

#include "multibody/MultibodySimulation.h"
#include "reduced/ReducedModel.h"
#include "report/SceneTable.h"
#include "scene/DidYouMean.h"
#include "scene/SceneSchema.h"
#include "studies/IdentifyFit.h"

namespace rollerdyn {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kRelativeStep = 1e-3;  // finite-difference step, relative to the key's value (header)
constexpr double kDefaultAccuracy = 1e-8;

// One free key and its map to the scaled parameter u in [0, 1].
struct KeyMap {
  IdentifiedKey info;
  double toValue(double u) const {
    u = std::clamp(u, 0.0, 1.0);
    return info.log_scale ? info.lower * std::pow(info.upper / info.lower, u) : info.lower + u * (info.upper - info.lower);
  }
  double toScaled(double x) const {
    const double u = info.log_scale ? std::log(x / info.lower) / std::log(info.upper / info.lower)
                                    : (x - info.lower) / (info.upper - info.lower);
    return std::clamp(u, 0.0, 1.0);
  }
  // dx/du at x
  double slope(double x) const {
    return info.log_scale ? x * std::log(info.upper / info.lower) : info.upper - info.lower;
  }
};

// The scene's value of a key (or of one element "key[i]"), NaN when the scene leaves it to the parser.
double startValue(const std::vector<SceneParameterRow>& rows, const std::string& key) {
  int element = -1;
  findSceneKeyOrElement(key, &element);
  const std::string leaf = element < 0 ? key : key.substr(0, key.find('['));
  for (const SceneParameterRow& r : rows) {
    if (r.key != leaf) continue;
    try {
      const YAML::Node n = YAML::Load(r.value);
      if (n.IsSequence()) return element >= 0 && element < static_cast<int>(n.size()) ? n[element].as<double>() : kNaN;
      return n.as<double>();
    } catch (const std::exception&) {
      return kNaN;
    }
  }
  return kNaN;
}

std::vector<KeyMap> resolveKeys(const IdentifyOptions& o, const std::vector<SceneParameterRow>& rows) {
  if (o.free_keys.empty()) throw std::invalid_argument("identify: expected at least one --free key, got none");
  std::vector<KeyMap> keys;
  for (const std::string& key : o.free_keys) {
    for (const KeyMap& k : keys)
      if (k.info.key == key) throw std::invalid_argument("identify: --free " + key + " is given twice");
    const KeySpec* spec = findSceneKeyOrElement(key);
    if (!spec) {
      requireSceneKey("identify: --free " + key, key);  // throws with the did-you-mean hint
      throw std::invalid_argument("identify: --free " + key + ": expected a key of the scene schema");
    }
    if (spec->kind != KeyKind::Number && spec->kind != KeyKind::NumberList)
      throw std::invalid_argument("identify: --free " + key + ": expected a key whose value is a number, got " +
                                  describeExpected(*spec));
    KeyMap k;
    k.info.key = key;
    k.info.unit = spec->unit;
    const auto given = o.bounds.find(key);
    if (given != o.bounds.end()) {
      k.info.lower = given->second.first;
      k.info.upper = given->second.second;
      k.info.bounds_from = "--bounds";
    } else {
      const Range& r = spec->range;
      if (!std::isfinite(r.lo) || !std::isfinite(r.hi))
        throw std::invalid_argument("identify: --free " + key + ": the scene schema allows " + describeAllowed(*spec) +
                                    ", no finite range; give bounds with --bounds " + key + "=LOWER:UPPER [" +
                                    spec->unit + "]");
      // An open end of the schema's range is no value a run may take: bounds just inside it.
      const double inset = 1e-9 * (r.hi - r.lo);
      k.info.lower = r.lo_inclusive ? r.lo : r.lo + inset;
      k.info.upper = r.hi_inclusive ? r.hi : r.hi - inset;
      k.info.bounds_from = "schema";
    }
    if (!(std::isfinite(k.info.lower) && std::isfinite(k.info.upper) && k.info.lower < k.info.upper))
      throw std::invalid_argument("identify: bounds of " + key + ": expected LOWER < UPPER, both finite, got " +
                                  formatNumber(k.info.lower) + ":" + formatNumber(k.info.upper));
    k.info.log_scale = k.info.lower > 0 && k.info.upper / k.info.lower >= 100.0;
    const double scene_value = startValue(rows, key);
    if (std::isfinite(scene_value) && scene_value >= k.info.lower && scene_value <= k.info.upper) {
      k.info.start = scene_value;
    } else if (std::isfinite(scene_value)) {
      throw std::invalid_argument("identify: " + key + ": the scene's value " + formatNumber(scene_value) +
                                  " lies outside the bounds " + formatNumber(k.info.lower) + ":" +
                                  formatNumber(k.info.upper) + "; widen them or --set a starting value inside");
    } else {
      k.info.start = k.toValue(0.5);
    }
    keys.push_back(k);
  }
  for (const auto& [key, b] : o.bounds)
    if (std::find(o.free_keys.begin(), o.free_keys.end(), key) == o.free_keys.end())
      throw std::invalid_argument("identify: --bounds " + key + ": expected one of the --free keys" +
                                  didYouMean(key, o.free_keys) + ", got a key that is not free");
  return keys;
}

// Linear interpolation of column `c` of `table` (rows by increasing t in column 0) at `t`.
double interpolate(const Table& table, int tc, int c, double t, std::size_t* hint) {
  const auto& rows = table.rows;
  std::size_t i = *hint;
  while (i + 1 < rows.size() && rows[i + 1][tc] < t) ++i;
  *hint = i;
  if (i + 1 >= rows.size()) return rows[i][c];
  const double t0 = rows[i][tc], t1 = rows[i + 1][tc];
  const double w = t1 > t0 ? std::clamp((t - t0) / (t1 - t0), 0.0, 1.0) : 0.0;
  return rows[i][c] + w * (rows[i + 1][c] - rows[i][c]);
}

double median(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

std::string joinList(const std::vector<std::string>& v) {
  std::string s;
  for (const std::string& x : v) s += (s.empty() ? "" : ", ") + x;
  return s;
}

// The model runs of one identification: the scene with the free keys applied, over a span, on the
// measured times.
class ModelRuns {
 public:
  ModelRuns(const IdentifyOptions& o, const MeasuredData& data, const SceneInput& input,
            const std::vector<KeyMap>& keys, double accuracy, double output_step)
      : o_(o), data_(data), input_(input), keys_(keys), accuracy_(accuracy), output_step_(output_step) {}

  struct Trial {
    bool ok = false;
    std::string reason;
    std::vector<std::vector<double>> model;  // per signal, at the first n measured times
  };

  // The model at scaled point u on the first n measured times (at `accuracy`, 0: the runs' own).
  Trial run(const std::vector<double>& u, std::size_t n, double accuracy = 0) {
    Trial trial;
    if (o_.interrupt && o_.interrupt->load()) {
      trial.reason = "interrupted";
      return trial;
    }
    runs_.fetch_add(1);
    std::vector<std::string> overrides = o_.base_overrides;
    overrides.push_back("simulation.t_end=" + formatNumber(data_.t[n - 1]));
    overrides.push_back("simulation.accuracy=" + formatNumber(accuracy > 0 ? accuracy : accuracy_));
    overrides.push_back("simulation.output_step=" + formatNumber(output_step_));
    for (std::size_t k = 0; k < keys_.size(); ++k)
      overrides.push_back(keys_[k].info.key + "=" + formatNumber(keys_[k].toValue(u[k])));
    try {
      const Scene scene = parseSceneInput(input_, overrides);
      RunResult result;
      if (o_.model == "multibody") {
        RunControl control;
        control.interrupt = o_.interrupt;
        result = runMultibodyModel(scene, control);
      } else {
        result = runReducedModel(scene);
      }
      if (!result.stats.complete) {
        failed_.fetch_add(1);
        trial.reason = result.stats.status;
        return trial;
      }
      trial.model.resize(data_.signals.size());
      for (std::size_t s = 0; s < data_.signals.size(); ++s) {
        const std::string& name = data_.signals[s].name;
        const Table* table = result.timeseries.has(name) ? &result.timeseries
                             : result.reactions.has(name) ? &result.reactions
                                                          : nullptr;
        if (!table) {
          std::vector<std::string> columns = result.timeseries.columns;
          columns.insert(columns.end(), result.reactions.columns.begin(), result.reactions.columns.end());
          throw MissingColumn(data_.file + ": column '" + name + "': the " + o_.model +
                              " model's run writes no such column" + didYouMean(name, columns) +
                              "; it writes " + joinList(columns));
        }
        const int tc = table->index("t"), c = table->index(name);
        std::size_t hint = 0;
        for (std::size_t i = 0; i < n; ++i) trial.model[s].push_back(interpolate(*table, tc, c, data_.t[i], &hint));
      }
      trial.ok = true;
    } catch (const MissingColumn&) {
      throw;
    } catch (const std::exception& e) {
      failed_.fetch_add(1);
      trial.reason = e.what();
    }
    return trial;
  }

  // Several points side by side on up to o.threads threads.
  std::vector<Trial> runAll(const std::vector<std::vector<double>>& points, std::size_t n) {
    std::vector<Trial> out(points.size());
    const std::size_t workers = std::min<std::size_t>(std::max(1, o_.threads), points.size());
    if (workers <= 1) {
      for (std::size_t i = 0; i < points.size(); ++i) out[i] = run(points[i], n);
      return out;
    }
    std::atomic<std::size_t> next{0};
    std::mutex mu;
    std::exception_ptr error;  // a measured column the model does not write: raised once all have stopped
    std::vector<std::thread> pool;
    for (std::size_t w = 0; w < workers; ++w)
      pool.emplace_back([&] {
        for (std::size_t i = next.fetch_add(1); i < points.size(); i = next.fetch_add(1)) {
          try {
            out[i] = run(points[i], n);
          } catch (...) {
            std::lock_guard<std::mutex> lock(mu);
            if (!error) error = std::current_exception();
          }
        }
      });
    for (std::thread& t : pool) t.join();
    if (error) std::rethrow_exception(error);
    return out;
  }

  int runs() const { return runs_.load(); }
  int failed() const { return failed_.load(); }

  struct MissingColumn : std::invalid_argument {
    using std::invalid_argument::invalid_argument;
  };

 private:
  const IdentifyOptions& o_;
  const MeasuredData& data_;
  const SceneInput& input_;
  const std::vector<KeyMap>& keys_;
  double accuracy_, output_step_;
  std::atomic<int> runs_{0}, failed_{0};
};

// Weighted residuals (model − data)/σ_s over the first n samples, signal after signal.
std::vector<double> weightedResiduals(const MeasuredData& d, const std::vector<std::vector<double>>& model,
                                      const std::vector<double>& sigma, std::size_t n) {
  std::vector<double> r;
  r.reserve(d.signals.size() * n);
  for (std::size_t s = 0; s < d.signals.size(); ++s)
    for (std::size_t i = 0; i < n; ++i) r.push_back((model[s][i] - d.signals[s].values[i]) / sigma[s]);
  return r;
}

double rmsOf(const std::vector<double>& v, std::size_t from, std::size_t to) {
  if (to <= from) return kNaN;
  double s = 0;
  for (std::size_t i = from; i < to; ++i) s += v[i] * v[i];
  return std::sqrt(s / static_cast<double>(to - from));
}

// The global stage: DIRECT-L (Gablonsky and Kelley 2001) over the scaled box, 30 runs per key;
// its best point (or u0 when nothing beats it) starts Levenberg–Marquardt.
struct GlobalSearch {
  const ResidualBatch* evaluate;
  std::vector<double> best;
  double best_cost = std::numeric_limits<double>::infinity();
  const std::atomic<bool>* interrupt = nullptr;
};

double globalObjective(const std::vector<double>& u, std::vector<double>&, void* data) {
  GlobalSearch& g = *static_cast<GlobalSearch*>(data);
  if (g.interrupt && g.interrupt->load()) throw nlopt::forced_stop();
  const ResidualEvaluation e = (*g.evaluate)({u})[0];
  if (!e.ok) return 1e300;
  double cost = 0;
  for (double v : e.r) cost += v * v;
  if (cost < g.best_cost) {
    g.best_cost = cost;
    g.best = u;
  }
  return cost;
}

std::vector<double> globalStart(const ResidualBatch& evaluate, const std::vector<double>& u0,
                                const std::atomic<bool>* interrupt) {
  const unsigned p = static_cast<unsigned>(u0.size());
  GlobalSearch g{&evaluate, u0, std::numeric_limits<double>::infinity(), interrupt};
  std::vector<double> scratch;
  globalObjective(u0, scratch, &g);
  nlopt::opt opt(nlopt::GN_DIRECT_L, p);
  opt.set_lower_bounds(std::vector<double>(p, 0.0));
  opt.set_upper_bounds(std::vector<double>(p, 1.0));
  opt.set_maxeval(30 * static_cast<int>(p));
  opt.set_min_objective(globalObjective, &g);
  std::vector<double> u = u0;
  double f = 0;
  try {
    opt.optimize(u, f);
  } catch (const std::exception&) {
    // stopped (interrupt, a failure inside NLopt): the best point seen so far is kept
  }
  return g.best;
}

// The data with only the chosen signals (all when none are chosen).
MeasuredData selectSignals(const MeasuredData& data, const std::vector<std::string>& chosen) {
  if (chosen.empty()) return data;
  MeasuredData d = data;
  d.signals.clear();
  std::vector<std::string> names;
  for (const MeasuredSignal& s : data.signals) names.push_back(s.name);
  for (const std::string& c : chosen) {
    const MeasuredSignal* s = data.find(c);
    if (!s)
      throw std::invalid_argument("identify: --signals " + c + ": expected a column of " + data.file +
                                  didYouMean(c, names) + " (" + joinList(names) + "), got one it does not have");
    d.signals.push_back(*s);
  }
  return d;
}

std::string percent(double v) { return formatNumber(std::round(v * 1000.0) / 10.0) + " %"; }

// Correlated pairs, keys the data do not determine, estimates on a bound, and the combination the
// data determine worst when JᵀJ is (near) singular (docs/identify.md, "Warnings").
void addWarnings(IdentifyResult& res, const std::vector<bool>& no_effect, bool singular) {
  const std::size_t p = res.keys.size();
  for (std::size_t a = 0; a < p; ++a)
    for (std::size_t b = a + 1; b < p; ++b) {
      const double rho = res.correlation[a][b];
      if (std::isfinite(rho) && std::abs(rho) > 0.95)
        res.warnings.push_back({"correlated", {res.keys[a].key, res.keys[b].key}, rho,
                                res.keys[a].key + " and " + res.keys[b].key +
                                    " cannot be told apart by these data (correlation " + formatNumber(std::round(rho * 1000) / 1000) +
                                    "): the fit trades one for the other; fix one with --set or measure a signal "
                                    "that separates them"});
    }
  bool undetermined = false;
  for (std::size_t k = 0; k < p; ++k) {
    const IdentifiedKey& key = res.keys[k];
    if (no_effect[k]) {
      undetermined = true;
      res.warnings.push_back({"undetermined", {key.key}, kNaN,
                              "the measured signals do not change with " + key.key +
                                  ": these data cannot determine it (fix it with --set, or measure a signal it moves)"});
    } else if (!(key.relative_std <= 0.5)) {
      undetermined = true;
      res.warnings.push_back({"undetermined", {key.key}, key.relative_std,
                              "these data do not determine " + key.key + ": its relative standard uncertainty is " +
                                  (std::isfinite(key.relative_std) ? percent(key.relative_std) : std::string("unbounded")) +
                                  " (above 50 %)"});
    }
    if (key.at_bound)
      res.warnings.push_back({"at_bound", {key.key}, key.value,
                              key.key + " = " + key.text + " lies on a bound of the search (" + formatNumber(key.lower) +
                                  ":" + formatNumber(key.upper) + "): the best value may lie beyond it and its "
                                  "uncertainty means little; widen --bounds"});
  }
  if (undetermined || singular || res.condition > 1e3) {
    std::string combo;
    for (std::size_t k = 0; k < p; ++k) {
      const double v = res.weakest_direction[k];
      if (std::abs(v) < 0.01) continue;
      combo += std::string(combo.empty() ? (v < 0 ? "-" : "") : (v < 0 ? " - " : " + ")) +
               formatNumber(std::round(std::abs(v) * 100) / 100) + "·Δ" + res.keys[k].key + "/" + res.keys[k].key;
    }
    res.warnings.push_back({"weak_direction", {}, res.condition,
                            std::string(singular ? "JᵀJ is singular" : "JᵀJ is near singular") + " (condition " +
                                formatNumber(std::round(res.condition * 10) / 10) +
                                "): the data determine worst the relative change " + combo});
  }
}

}  // namespace

IdentifyResult runIdentify(const IdentifyOptions& o) {
  const auto wall0 = std::chrono::steady_clock::now();
  if (o.model != "multibody" && o.model != "reduced")
    throw std::invalid_argument("identify: --model: expected multibody or reduced, got '" + o.model + "'");
  if (!(o.holdout >= 0.0 && o.holdout <= 0.9))
    throw std::invalid_argument("identify: --holdout: expected a fraction in [0, 0.9], got " + formatNumber(o.holdout));
  const MeasuredData d = selectSignals(o.data, o.signals);
  if (d.t.size() < 3 || d.signals.empty())
    throw std::invalid_argument("identify: expected measured data with t and at least one signal");
  for (const auto& [name, sigma] : o.noise) {
    if (!d.find(name)) {
      std::vector<std::string> names;
      for (const auto& s : d.signals) names.push_back(s.name);
      throw std::invalid_argument("identify: --noise " + name + ": expected a measured column" + didYouMean(name, names) +
                                  " (" + joinList(names) + "), got one the data do not have");
    }
    if (!(sigma > 0 && std::isfinite(sigma)))
      throw std::invalid_argument("identify: --noise " + name + ": expected σ > 0, got " + formatNumber(sigma));
  }
  const SceneInput input = o.scene_input ? *o.scene_input : readSceneInput(o.scene_path);
  const Scene base = parseSceneInput(input, o.base_overrides);
  const std::vector<KeyMap> keys = resolveKeys(o, sceneParameterRows(input, o.base_overrides));
  const std::size_t p = keys.size();

  IdentifyResult res;
  res.scene = o.scene_path.empty() ? base.name : o.scene_path;
  res.model = o.model;
  res.data_file = d.file;
  res.accuracy = o.accuracy > 0 ? o.accuracy : std::min(base.simulation.accuracy, kDefaultAccuracy);
  std::vector<double> spacing;
  for (std::size_t i = 1; i < d.t.size(); ++i) spacing.push_back(d.t[i] - d.t[i - 1]);
  res.output_step = std::min(base.simulation.output_step, median(spacing));
  res.t_end = d.t.back();
  res.t_fit_end = d.t.front() + (1.0 - o.holdout) * (d.t.back() - d.t.front());
  std::size_t n_fit = 0;
  while (n_fit < d.t.size() && d.t[n_fit] <= res.t_fit_end * (1 + 1e-12)) ++n_fit;
  const std::size_t n_all = d.t.size();
  if (n_fit * d.signals.size() <= p + 1)
    throw std::invalid_argument("identify: the fitted part of the data (" + std::to_string(n_fit) +
                                " samples) is too short for " + std::to_string(p) + " keys; lower --holdout");

  ModelRuns runs(o, d, input, keys, res.accuracy, res.output_step);
  // σ_s: given, or first 1e-2 × the signal's RMS deviation from its mean (header).
  std::vector<double> sigma(d.signals.size());
  std::vector<bool> given(d.signals.size(), false);
  for (std::size_t s = 0; s < d.signals.size(); ++s) {
    const auto& v = d.signals[s].values;
    double mean = 0;
    for (double x : v) mean += x;
    mean /= static_cast<double>(v.size());
    double dev = 0, top = 0;
    for (double x : v) {
      dev += (x - mean) * (x - mean);
      top = std::max(top, std::abs(x));
    }
    SignalFit f;
    f.name = d.signals[s].name;
    f.unit = d.signals[s].unit;
    f.data_rms = std::sqrt(dev / static_cast<double>(v.size()));
    res.signals.push_back(f);
    const auto g = o.noise.find(f.name);
    given[s] = g != o.noise.end();
    sigma[s] = given[s] ? g->second : std::max({1e-2 * f.data_rms, 1e-9 * top, 1e-300});
  }

  const ResidualBatch evaluate = [&](const std::vector<std::vector<double>>& points) {
    std::vector<ResidualEvaluation> out;
    for (ModelRuns::Trial& t : runs.runAll(points, n_fit)) {
      ResidualEvaluation e;
      e.ok = t.ok;
      e.reason = t.reason;
      if (t.ok) e.r = weightedResiduals(d, t.model, sigma, n_fit);
      out.push_back(std::move(e));
    }
    return out;
  };

  std::vector<double> u0(p);
  for (std::size_t k = 0; k < p; ++k) u0[k] = keys[k].toScaled(keys[k].info.start);
  // The data's columns are checked by the first run, before any search (a missing column throws).
  LmSettings lm;
  lm.max_iterations = o.max_iterations;
  lm.interrupt = o.interrupt;
  for (std::size_t k = 0; k < p; ++k) {
    const KeyMap& km = keys[k];
    const double x = km.info.start;
    const double size = std::abs(x) > 0 ? std::abs(x) : km.info.upper - km.info.lower;
    lm.fd_step.push_back(std::clamp(kRelativeStep * size / km.slope(std::max(x, km.info.lower)), 1e-9, 0.1));
  }
  int fit_number = 1;
  lm.on_iteration = [&](int it, double cost, const std::vector<double>& u) {
    if (!o.on_progress) return;
    std::string line = "fit " + std::to_string(fit_number) + ", iteration " + std::to_string(it) + ": cost " +
                       formatNumber(cost) + " at";
    for (std::size_t k = 0; k < p; ++k) line += " " + keys[k].info.key + "=" + formatNumber(keys[k].toValue(u[k]));
    o.on_progress(line);
  };
  if (o.global) u0 = globalStart(evaluate, u0, o.interrupt);
  LmOutcome fit = levenbergMarquardt(evaluate, u0, lm);
  res.iterations = fit.iterations;
  const bool any_estimated = std::find(given.begin(), given.end(), false) != given.end();
  if (fit.converged && any_estimated) {
    // σ_s = the RMS residual of each estimated signal at the first optimum, then one refit.
    for (std::size_t s = 0; s < d.signals.size(); ++s) {
      if (given[s]) continue;
      const double rms = rmsOf(std::vector<double>(fit.r.begin() + static_cast<long>(s * n_fit),
                                                   fit.r.begin() + static_cast<long>((s + 1) * n_fit)),
                               0, n_fit) * sigma[s];
      sigma[s] = std::max(rms, 1e-9 * sigma[s]);
    }
    fit_number = 2;
    fit = levenbergMarquardt(evaluate, fit.u, lm);
    res.iterations += fit.iterations;
  }
  res.converged = fit.converged;
  res.convergence = fit.reason;
  for (std::size_t s = 0; s < d.signals.size(); ++s) {
    res.signals[s].sigma = sigma[s];
    res.signals[s].sigma_from = given[s] ? "given" : "estimated";
    res.signals[s].samples_fit = n_fit;
    res.signals[s].samples_holdout = n_all - n_fit;
  }
  res.residuals = fit.r.size();
  res.rss = fit.cost;

  // The estimate and its covariance: central differences in the keys' own units.
  std::vector<double> x(p), scale(p);
  for (std::size_t k = 0; k < p; ++k) {
    IdentifiedKey info = keys[k].info;
    info.text = formatNumber(keys[k].toValue(fit.u[k]));
    info.value = std::stod(info.text);
    info.at_bound = fit.u[k] <= 1e-6 || fit.u[k] >= 1 - 1e-6;
    x[k] = info.value;
    scale[k] = std::abs(info.value) > 0 ? std::abs(info.value) : info.upper - info.lower;
    res.keys.push_back(info);
  }
  if (!fit.r.empty()) {
    std::vector<std::vector<double>> points;
    std::vector<double> h(p);
    for (std::size_t k = 0; k < p; ++k) {
      h[k] = lm.fd_step[k];
      std::vector<double> a = fit.u, b = fit.u;
      a[k] = std::min(1.0, fit.u[k] + h[k]);
      b[k] = std::max(0.0, fit.u[k] - h[k]);
      points.push_back(a);
      points.push_back(b);
    }
    const std::vector<ResidualEvaluation> e = evaluate(points);
    std::vector<std::vector<double>> J(fit.r.size(), std::vector<double>(p, 0.0));
    bool ok = true;
    for (std::size_t k = 0; k < p && ok; ++k) {
      const ResidualEvaluation& up = e[2 * k];
      const ResidualEvaluation& down = e[2 * k + 1];
      const double xa = keys[k].toValue(points[2 * k][k]), xb = keys[k].toValue(points[2 * k + 1][k]);
      const ResidualEvaluation* hi = up.ok ? &up : nullptr;
      const ResidualEvaluation* lo = down.ok ? &down : nullptr;
      const double x_hi = hi ? xa : x[k], x_lo = lo ? xb : x[k];
      if (!hi && !lo) {
        ok = false;
        res.converged = false;
        res.convergence = "the runs beside the estimate failed (" + up.reason + "): no uncertainty";
        break;
      }
      for (std::size_t i = 0; i < fit.r.size(); ++i)
        J[i][k] = ((hi ? hi->r[i] : fit.r[i]) - (lo ? lo->r[i] : fit.r[i])) / (x_hi - x_lo);
    }
    if (ok) {
      const CovarianceEstimate c = estimateCovariance(J, fit.cost, scale);
      res.sigma_hat2 = c.sigma_hat2;
      res.correlation = c.correlation;
      res.condition = c.condition;
      res.weakest_direction = c.weakest_direction;
      for (std::size_t k = 0; k < p; ++k) {
        res.keys[k].std = c.std[k];
        res.keys[k].relative_std = res.keys[k].value != 0 ? c.std[k] / std::abs(res.keys[k].value) : kNaN;
      }
      addWarnings(res, c.no_effect, c.singular);
      if (c.singular && res.converged) {
        res.converged = false;
        res.convergence = "the data do not determine every free key (JᵀJ is singular; see the warnings)";
      }
    }
  }

  // The run at the estimate over the whole span: the fit's and the held-out part's errors.
  if (!fit.r.empty()) {
    const ModelRuns::Trial all = runs.run(fit.u, n_all);
    res.t = d.t;
    for (const MeasuredSignal& m : d.signals) res.data_values.push_back(m.values);
    if (all.ok) {
      res.model_values = all.model;
      for (std::size_t s = 0; s < d.signals.size(); ++s) {
        std::vector<double> diff(n_all);
        for (std::size_t i = 0; i < n_all; ++i) diff[i] = all.model[s][i] - d.signals[s].values[i];
        res.signals[s].rms_fit = rmsOf(diff, 0, n_fit);
        res.signals[s].rms_holdout = rmsOf(diff, n_fit, n_all);
      }
      // The integration's own error: the same run at 1/100 of the accuracy. Far below σ_s it is
      // no part of the residuals; near σ_s the cost is flat within it and the fit cannot settle.
      const ModelRuns::Trial fine = runs.run(fit.u, n_all, res.accuracy / 100);
      for (std::size_t s = 0; s < d.signals.size() && fine.ok; ++s) {
        std::vector<double> diff(n_all);
        for (std::size_t i = 0; i < n_all; ++i) diff[i] = all.model[s][i] - fine.model[s][i];
        SignalFit& f = res.signals[s];
        f.integration_error = rmsOf(diff, 0, n_all);
        if (f.integration_error > 0.1 * f.sigma)
          res.warnings.push_back({"integration", {}, f.integration_error,
                                  "the integration's own error in " + f.name + " (RMS " +
                                      formatNumber(std::round(f.integration_error / f.sigma * 100) / 100) +
                                      " of its σ) is not far below the measurement noise: tighten --accuracy "
                                      "(now " + formatNumber(res.accuracy) + ")"});
      }
    } else {
      for (SignalFit& f : res.signals) f.rms_fit = f.rms_holdout = kNaN;
      res.warnings.push_back({"holdout", {}, kNaN, "the run at the estimate over the whole span failed (" + all.reason +
                                                       "): no prediction of the held-out part"});
    }
  }
  res.runs = runs.runs();
  res.failed_runs = runs.failed();
  res.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  return res;
}

}  // namespace rollerdyn
