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
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "report/SceneTable.h"
#include "scene/DidYouMean.h"
#include "scene/SceneSchema.h"
#include "studies/IdentifyFit.h"
#include "studies/IdentifyRuns.h"

namespace rollerdyn {

namespace {

using identify::joinList;
using identify::KeyMap;
using identify::median;
using identify::ModelRuns;
using identify::rmsOf;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kRelativeStep = 1e-3;  // finite-difference step, relative to the key's value (header)
constexpr double kDefaultAccuracy = 1e-8;

std::string percent(double v) { return formatNumber(std::round(v * 1000.0) / 10.0) + " %"; }

void addCorrelationWarnings(IdentifyResult& res) {
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
}

// A key the signals do not change with, or known to worse than 50 %, and one on a bound of the
// search. Returns whether the key is undetermined.
bool addKeyWarnings(IdentifyResult& res, const IdentifiedKey& key, bool no_effect) {
  bool undetermined = false;
  if (no_effect) {
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
  return undetermined;
}

// The combination of relative changes the data determine worst (the weakest direction).
std::string weakestCombination(const IdentifyResult& res) {
  std::string combo;
  for (std::size_t k = 0; k < res.keys.size(); ++k) {
    const double v = res.weakest_direction[k];
    if (std::abs(v) < 0.01) continue;
    combo += std::string(combo.empty() ? (v < 0 ? "-" : "") : (v < 0 ? " - " : " + ")) +
             formatNumber(std::round(std::abs(v) * 100) / 100) + "·Δ" + res.keys[k].key + "/" + res.keys[k].key;
  }
  return combo;
}

// Correlated pairs, keys the data do not determine, estimates on a bound, and the combination the
// data determine worst when JᵀJ is (near) singular (docs/identify.md, "Warnings").
void addWarnings(IdentifyResult& res, const std::vector<bool>& no_effect, bool singular) {
  addCorrelationWarnings(res);
  bool undetermined = false;
  for (std::size_t k = 0; k < res.keys.size(); ++k)
    undetermined = addKeyWarnings(res, res.keys[k], no_effect[k]) || undetermined;
  if (undetermined || singular || res.condition > 1e3)
    res.warnings.push_back({"weak_direction", {}, res.condition,
                            std::string(singular ? "JᵀJ is singular" : "JᵀJ is near singular") + " (condition " +
                                formatNumber(std::round(res.condition * 10) / 10) +
                                "): the data determine worst the relative change " + weakestCombination(res)});
}

void checkOptions(const IdentifyOptions& o, const MeasuredData& d) {
  if (o.model != "multibody" && o.model != "reduced")
    throw std::invalid_argument("identify: --model: expected multibody or reduced, got '" + o.model + "'");
  if (!(o.holdout >= 0.0 && o.holdout <= 0.9))
    throw std::invalid_argument("identify: --holdout: expected a fraction in [0, 0.9], got " + formatNumber(o.holdout));
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
}

// res.signals with each signal's name, unit and RMS deviation; σ_s given, or first 1e-2 × that
// RMS deviation (file comment). `given` receives which σ_s are given.
std::vector<double> startingSigmas(const IdentifyOptions& o, const MeasuredData& d, IdentifyResult& res,
                                   std::vector<bool>& given) {
  std::vector<double> sigma(d.signals.size());
  given.assign(d.signals.size(), false);
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
  return sigma;
}

// Forward-difference steps in u: kRelativeStep of each key's starting value (of its range at 0).
std::vector<double> differenceSteps(const std::vector<KeyMap>& keys) {
  std::vector<double> steps;
  for (const KeyMap& km : keys) {
    const double x = km.info.start;
    const double size = std::abs(x) > 0 ? std::abs(x) : km.info.upper - km.info.lower;
    steps.push_back(std::clamp(kRelativeStep * size / km.slope(std::max(x, km.info.lower)), 1e-9, 0.1));
  }
  return steps;
}

// The estimate into res.keys: each key's value as written, and whether it sits on a bound.
void recordEstimates(IdentifyResult& res, const std::vector<KeyMap>& keys, const LmOutcome& fit) {
  for (std::size_t k = 0; k < keys.size(); ++k) {
    IdentifiedKey info = keys[k].info;
    info.text = formatNumber(keys[k].toValue(fit.u[k]));
    info.value = std::stod(info.text);
    info.at_bound = fit.u[k] <= 1e-6 || fit.u[k] >= 1 - 1e-6;
    res.keys.push_back(info);
  }
}

// The designs beside the estimate, one step up and one down in each scaled key (within [0, 1]).
std::vector<std::vector<double>> centralDifferencePoints(const std::vector<double>& u, const std::vector<double>& step) {
  std::vector<std::vector<double>> points;
  for (std::size_t k = 0; k < u.size(); ++k) {
    std::vector<double> a = u, b = u;
    a[k] = std::min(1.0, u[k] + step[k]);
    b[k] = std::max(0.0, u[k] - step[k]);
    points.push_back(a);
    points.push_back(b);
  }
  return points;
}

// The central-difference Jacobian at the estimate in the keys' own units, at the fit's difference
// steps (a failed side: the estimate itself). Empty, with `failure` why, when both runs beside a
// key failed.
std::vector<std::vector<double>> jacobianAtEstimate(const IdentifyResult& res, const std::vector<KeyMap>& keys,
                                                    const LmOutcome& fit, const ResidualBatch& evaluate,
                                                    std::string* failure) {
  const std::vector<std::vector<double>> points = centralDifferencePoints(fit.u, differenceSteps(keys));
  const std::vector<ResidualEvaluation> e = evaluate(points);
  std::vector<std::vector<double>> J(fit.r.size(), std::vector<double>(keys.size(), 0.0));
  for (std::size_t k = 0; k < keys.size(); ++k) {
    const ResidualEvaluation* hi = e[2 * k].ok ? &e[2 * k] : nullptr;
    const ResidualEvaluation* lo = e[2 * k + 1].ok ? &e[2 * k + 1] : nullptr;
    if (!hi && !lo) {
      *failure = e[2 * k].reason;
      return {};
    }
    const double x_hi = hi ? keys[k].toValue(points[2 * k][k]) : res.keys[k].value;
    const double x_lo = lo ? keys[k].toValue(points[2 * k + 1][k]) : res.keys[k].value;
    for (std::size_t i = 0; i < fit.r.size(); ++i)
      J[i][k] = ((hi ? hi->r[i] : fit.r[i]) - (lo ? lo->r[i] : fit.r[i])) / (x_hi - x_lo);
  }
  return J;
}

// Each key's scale for the covariance: its value, or its range at 0.
std::vector<double> keyScales(const std::vector<IdentifiedKey>& keys) {
  std::vector<double> scale;
  for (const IdentifiedKey& k : keys) scale.push_back(std::abs(k.value) > 0 ? std::abs(k.value) : k.upper - k.lower);
  return scale;
}

void recordUncertainty(IdentifyResult& res, const CovarianceEstimate& c) {
  res.sigma_hat2 = c.sigma_hat2;
  res.correlation = c.correlation;
  res.condition = c.condition;
  res.weakest_direction = c.weakest_direction;
  for (std::size_t k = 0; k < res.keys.size(); ++k) {
    res.keys[k].std = c.std[k];
    res.keys[k].relative_std = res.keys[k].value != 0 ? c.std[k] / std::abs(res.keys[k].value) : kNaN;
  }
}

// A key the signals do not change with at all leaves no estimate: not converged. Keys the data
// determine poorly (a near-singular JᵀJ, however near) are warnings: how near depends on the
// integration's noise in the finite differences, not on the data alone.
void failOnKeysWithoutEffect(IdentifyResult& res, const std::vector<bool>& no_effect) {
  std::string without_effect;
  for (std::size_t k = 0; k < res.keys.size(); ++k)
    if (no_effect[k]) without_effect += (without_effect.empty() ? "" : ", ") + res.keys[k].key;
  if (!without_effect.empty() && res.converged) {
    res.converged = false;
    res.convergence = "the data do not determine " + without_effect +
                      ": the measured signals do not change with it (JᵀJ is singular; see the warnings)";
  }
}

// The estimate into res.keys, and at it the central-difference Jacobian in the keys' own units,
// the covariance, correlations and warnings (a failure beside the estimate leaves no uncertainty).
void estimateWithUncertainty(IdentifyResult& res, const std::vector<KeyMap>& keys, const LmOutcome& fit,
                             const ResidualBatch& evaluate) {
  recordEstimates(res, keys, fit);
  if (fit.r.empty()) return;
  std::string failure;
  const std::vector<std::vector<double>> J = jacobianAtEstimate(res, keys, fit, evaluate, &failure);
  if (J.empty()) {
    res.converged = false;
    res.convergence = "the runs beside the estimate failed (" + failure + "): no uncertainty";
    return;
  }
  const CovarianceEstimate c = estimateCovariance(J, fit.cost, keyScales(res.keys));
  recordUncertainty(res, c);
  addWarnings(res, c.no_effect, c.singular);
  failOnKeysWithoutEffect(res, c.no_effect);
}

// Each signal's RMS error of the model at the estimate over the fitted and the held-out part.
void fitAndHoldoutErrors(IdentifyResult& res, const ModelRuns::Trial& all, const MeasuredData& d, std::size_t n_fit) {
  const std::size_t n_all = d.t.size();
  for (std::size_t s = 0; s < d.signals.size(); ++s) {
    std::vector<double> diff(n_all);
    for (std::size_t i = 0; i < n_all; ++i) diff[i] = all.model[s][i] - d.signals[s].values[i];
    res.signals[s].rms_fit = rmsOf(diff, 0, n_fit);
    res.signals[s].rms_holdout = rmsOf(diff, n_fit, n_all);
  }
}

// Each signal's integration error: the run at the estimate against the same run at 1/100 of the
// accuracy; a warning where it is not far below the signal's noise.
void integrationErrors(IdentifyResult& res, const ModelRuns::Trial& all, const ModelRuns::Trial& fine) {
  const std::size_t n_all = res.t.size();
  for (std::size_t s = 0; s < res.signals.size() && fine.ok; ++s) {
    std::vector<double> diff(n_all);
    for (std::size_t i = 0; i < n_all; ++i) diff[i] = all.model[s][i] - fine.model[s][i];
    SignalFit& f = res.signals[s];
    f.integration_error = rmsOf(diff, 0, n_all);
    if (f.integration_error > 0.1 * f.sigma)
      res.warnings.push_back({"integration", {}, f.integration_error,
                              "the integration's own error in " + f.name + " (RMS " +
                                  formatNumber(std::round(f.integration_error / f.sigma * 100) / 100) +
                                  " of its σ) is not far below the measurement noise: tighten --accuracy (now " +
                                  formatNumber(res.accuracy) + ")"});
  }
}

// The run at the estimate over the whole span: the RMS errors of the fitted and the held-out part,
// and the integration's own error (the same run at 1/100 of the accuracy: far below σ_s it is no
// part of the residuals; near σ_s the cost is flat within it and the fit cannot settle).
void holdoutCheck(IdentifyResult& res, ModelRuns& runs, const MeasuredData& d, const std::vector<double>& u,
                  std::size_t n_fit) {
  const std::size_t n_all = d.t.size();
  const ModelRuns::Trial all = runs.run(u, n_all);
  res.t = d.t;
  for (const MeasuredSignal& m : d.signals) res.data_values.push_back(m.values);
  if (!all.ok) {
    for (SignalFit& f : res.signals) f.rms_fit = f.rms_holdout = kNaN;
    res.warnings.push_back({"holdout", {}, kNaN, "the run at the estimate over the whole span failed (" + all.reason +
                                                     "): no prediction of the held-out part"});
    return;
  }
  res.model_values = all.model;
  fitAndHoldoutErrors(res, all, d, n_fit);
  integrationErrors(res, all, runs.run(u, n_all, res.accuracy / 100));
}

// The runs' accuracy and output step (the data's own spacing at most), and the fitted span: the
// data before the held-out end. Returns the number of fitted samples per signal.
std::size_t runGridAndFittedSpan(const IdentifyOptions& o, const MeasuredData& d, const Scene& base, std::size_t p,
                                 IdentifyResult& res) {
  res.accuracy = o.accuracy > 0 ? o.accuracy : std::min(base.simulation.accuracy, kDefaultAccuracy);
  std::vector<double> spacing;
  for (std::size_t i = 1; i < d.t.size(); ++i) spacing.push_back(d.t[i] - d.t[i - 1]);
  res.output_step = std::min(base.simulation.output_step, median(spacing));
  res.t_end = d.t.back();
  res.t_fit_end = d.t.front() + (1.0 - o.holdout) * (d.t.back() - d.t.front());
  std::size_t n_fit = 0;
  while (n_fit < d.t.size() && d.t[n_fit] <= res.t_fit_end * (1 + 1e-12)) ++n_fit;
  if (n_fit * d.signals.size() <= p + 1)
    throw std::invalid_argument("identify: the fitted part of the data (" + std::to_string(n_fit) +
                                " samples) is too short for " + std::to_string(p) + " keys; lower --holdout");
  return n_fit;
}

// The residuals of a batch of designs, each signal weighted by its noise σ_s (read when the batch
// runs: the estimated ones change between the two fits).
ResidualBatch weightedResidualBatch(ModelRuns& runs, const MeasuredData& d, const std::vector<double>& sigma,
                                    std::size_t n_fit) {
  return [&runs, &d, &sigma, n_fit](const std::vector<std::vector<double>>& points) {
    std::vector<ResidualEvaluation> out;
    for (ModelRuns::Trial& t : runs.runAll(points, n_fit)) {
      ResidualEvaluation e;
      e.ok = t.ok;
      e.reason = t.reason;
      if (t.ok) e.r = identify::weightedResiduals(d, t.model, sigma, n_fit);
      out.push_back(std::move(e));
    }
    return out;
  };
}

// The search's settings; each iteration reported to o.on_progress as "fit N, iteration I: cost C at
// KEY=VALUE ..." (*fit_number: 1, then 2 for the refit).
LmSettings lmSettings(const IdentifyOptions& o, const std::vector<KeyMap>& keys, const int* fit_number) {
  LmSettings lm;
  lm.max_iterations = o.max_iterations;
  lm.interrupt = o.interrupt;
  lm.fd_step = differenceSteps(keys);
  lm.on_iteration = [&o, &keys, fit_number](int it, double cost, const std::vector<double>& u) {
    if (!o.on_progress) return;
    std::string line = "fit " + std::to_string(*fit_number) + ", iteration " + std::to_string(it) + ": cost " +
                       formatNumber(cost) + " at";
    for (std::size_t k = 0; k < keys.size(); ++k)
      line += " " + keys[k].info.key + "=" + formatNumber(keys[k].toValue(u[k]));
    o.on_progress(line);
  };
  return lm;
}

// Where the local fit starts: the keys' starting values, or with --global the best design of a
// global search from them.
std::vector<double> searchStart(const IdentifyOptions& o, const std::vector<KeyMap>& keys,
                                const ResidualBatch& evaluate) {
  std::vector<double> u0(keys.size());
  for (std::size_t k = 0; k < keys.size(); ++k) u0[k] = keys[k].toScaled(keys[k].info.start);
  // The data's columns are checked by the first run, before any search (a missing column throws).
  if (o.global) u0 = globalStart(evaluate, u0, o.interrupt);
  return u0;
}

IdentifyResult resultHeading(const IdentifyOptions& o, const Scene& base, const MeasuredData& d) {
  IdentifyResult res;
  res.scene = o.scene_path.empty() ? base.name : o.scene_path;
  res.model = o.model;
  res.data_file = d.file;
  return res;
}

// σ_s = the RMS residual of each estimated signal at the first optimum (before the refit).
void reestimateSigmas(const LmOutcome& fit, const std::vector<bool>& given, std::size_t n_fit,
                      std::vector<double>& sigma) {
  for (std::size_t s = 0; s < sigma.size(); ++s)
    if (!given[s]) sigma[s] = std::max(sigma[s] * rmsOf(fit.r, s * n_fit, (s + 1) * n_fit), 1e-9 * sigma[s]);
}

// The local fit from the search's start; when it converges and some σ_s are estimated, one refit
// from its optimum at the σ_s its residuals give (file comment). res.iterations counts both.
LmOutcome fitWithNoiseRefit(const IdentifyOptions& o, const std::vector<KeyMap>& keys, const ResidualBatch& evaluate,
                            const std::vector<bool>& given, std::size_t n_fit, std::vector<double>& sigma,
                            IdentifyResult& res) {
  int fit_number = 1;
  const LmSettings lm = lmSettings(o, keys, &fit_number);
  LmOutcome fit = levenbergMarquardt(evaluate, searchStart(o, keys, evaluate), lm);
  res.iterations = fit.iterations;
  if (fit.converged && std::find(given.begin(), given.end(), false) != given.end()) {
    reestimateSigmas(fit, given, n_fit, sigma);
    fit_number = 2;
    fit = levenbergMarquardt(evaluate, fit.u, lm);
    res.iterations += fit.iterations;
  }
  return fit;
}

// The fit's outcome into the result: convergence, residuals, and each signal's noise and samples.
void recordFit(IdentifyResult& res, const LmOutcome& fit, const std::vector<double>& sigma,
               const std::vector<bool>& given, std::size_t n_fit, std::size_t n_samples) {
  res.converged = fit.converged;
  res.convergence = fit.reason;
  for (std::size_t s = 0; s < sigma.size(); ++s) {
    res.signals[s].sigma = sigma[s];
    res.signals[s].sigma_from = given[s] ? "given" : "estimated";
    res.signals[s].samples_fit = n_fit;
    res.signals[s].samples_holdout = n_samples - n_fit;
  }
  res.residuals = fit.r.size();
  res.rss = fit.cost;
}

}  // namespace

IdentifyResult runIdentify(const IdentifyOptions& o) {
  const auto wall0 = std::chrono::steady_clock::now();
  const MeasuredData d = identify::selectSignals(o.data, o.signals);
  checkOptions(o, d);
  const SceneInput input = o.scene_input ? *o.scene_input : readSceneInput(o.scene_path);
  const Scene base = parseSceneInput(input, o.base_overrides);
  const std::vector<KeyMap> keys = identify::resolveKeys(o, sceneParameterRows(input, o.base_overrides));

  IdentifyResult res = resultHeading(o, base, d);
  const std::size_t n_fit = runGridAndFittedSpan(o, d, base, keys.size(), res);

  ModelRuns runs(o, d, input, keys, res.accuracy, res.output_step);
  std::vector<bool> given;
  std::vector<double> sigma = startingSigmas(o, d, res, given);
  const ResidualBatch evaluate = weightedResidualBatch(runs, d, sigma, n_fit);
  const LmOutcome fit = fitWithNoiseRefit(o, keys, evaluate, given, n_fit, sigma, res);
  recordFit(res, fit, sigma, given, n_fit, d.t.size());
  estimateWithUncertainty(res, keys, fit, evaluate);
  if (!fit.r.empty()) holdoutCheck(res, runs, d, fit.u, n_fit);
  res.runs = runs.runs();
  res.failed_runs = runs.failed();
  res.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  return res;
}

}  // namespace rollerdyn
