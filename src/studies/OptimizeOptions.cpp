// The options of `rollerdyn optimize` checked before any run, and a --constraint's text read
// (Optimizer.h, OptimizeOptions.h).
#include "studies/OptimizeOptions.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "scene/DidYouMean.h"
#include "scene/SceneSchema.h"

namespace rollerdyn {

namespace {

std::string trim(const std::string& s) {
  const auto a = s.find_first_not_of(" \t");
  if (a == std::string::npos) return "";
  return s.substr(a, s.find_last_not_of(" \t") - a + 1);
}

bool knownMetric(const std::string& m) {
  const auto& names = sweepNumericMetrics();
  return std::find(names.begin(), names.end(), m) != names.end();
}

std::string metricList() {
  std::string list;
  for (const std::string& m : sweepNumericMetrics()) list += (list.empty() ? "" : ", ") + m;
  return list;
}

// Each --param a scene key, once, with a range a < b.
void validateParameters(const OptimizeOptions& o) {
  for (std::size_t k = 0; k < o.params.size(); ++k) {
    const SampleRange& p = o.params[k];
    if (!findSceneKey(p.key))
      throw std::invalid_argument("optimize: --param " + p.key + " is not a scene key (see docs/scene-reference.md)");
    if (!(p.lower < p.upper) || !std::isfinite(p.lower) || !std::isfinite(p.upper))
      throw std::invalid_argument("optimize: --range of " + p.key + ": expected a:b with a < b");
    for (std::size_t m = 0; m < k; ++m)
      if (o.params[m].key == p.key) throw std::invalid_argument("optimize: --param " + p.key + " given twice");
  }
}

// --minimize and --constraint name known metrics (or a --param key, or the caller's functions).
void validateObjectiveAndConstraints(const OptimizeOptions& o) {
  bool is_key = false;
  for (const SampleRange& p : o.params) is_key = is_key || p.key == o.minimize;
  if (!is_key && !o.objective && !knownMetric(o.minimize)) {
    std::vector<std::string> names = sweepNumericMetrics();
    for (const SampleRange& p : o.params) names.push_back(p.key);
    throw std::invalid_argument("optimize: --minimize: unknown metric '" + o.minimize + "'" + didYouMean(o.minimize, names) +
                                "; expected a metric (" + metricList() + ") or one of the --param keys");
  }
  for (const OptimizeConstraint& c : o.constraints)
    if (!c.value && !knownMetric(c.metric))
      throw std::invalid_argument("optimize: --constraint '" + c.text + "': unknown metric '" + c.metric + "'" +
                                  didYouMean(c.metric, sweepNumericMetrics()) + "; expected one of " + metricList());
}

// --method one NLopt knows here (bobyqa without constraints), threads, evaluations and tolerance.
void validateMethod(const OptimizeOptions& o) {
  const std::string& m = o.method;
  if (m != "auto" && m != "bobyqa" && m != "cobyla" && m != "direct-l" && m != "crs2" && m != "multistart")
    throw std::invalid_argument("optimize: --method: expected auto, bobyqa, cobyla, direct-l, crs2 or multistart, got '" +
                                m + "'");
  if (o.threads < 1) throw std::invalid_argument("optimize: --threads must be at least 1");
  if (m == "bobyqa" && !o.constraints.empty())
    throw std::invalid_argument("optimize: --method bobyqa handles no --constraint: use cobyla (or auto), or a "
                                "global method (direct-l, crs2: constraints by penalty)");
  if (o.max_evals < 1) throw std::invalid_argument("optimize: --max-evals must be at least 1");
  if (!(o.x_tolerance > 0 && o.x_tolerance < 1))
    throw std::invalid_argument("optimize: the parameter tolerance must be between 0 and 1 (fraction of each range)");
}

}  // namespace

void validateOptimizeOptions(const OptimizeOptions& o) {
  if (o.params.empty()) throw std::invalid_argument("optimize: give at least one --param KEY with --range a:b");
  if (o.model != "multibody" && o.model != "reduced")
    throw std::invalid_argument("optimize: --model must be multibody or reduced, got '" + o.model + "'");
  validateParameters(o);
  validateObjectiveAndConstraints(o);
  validateMethod(o);
}

namespace {

// A constraint's bound: the whole text one finite number.
bool readBound(const std::string& value, double* bound) {
  if (value.empty()) return false;
  std::size_t used = 0;
  try {
    *bound = std::stod(value, &used);
  } catch (const std::exception&) {
    return false;
  }
  return used == value.size() && std::isfinite(*bound);
}

}  // namespace

OptimizeConstraint parseConstraint(const std::string& text) {
  OptimizeConstraint c;
  c.text = text;
  std::size_t at = text.find("<=");
  c.upper = true;
  if (at == std::string::npos) {
    at = text.find(">=");
    c.upper = false;
  }
  if (at == std::string::npos)
    throw std::invalid_argument("--constraint '" + text + "': expected METRIC<=VALUE or METRIC>=VALUE, e.g. 'delta<=0.05'");
  c.metric = trim(text.substr(0, at));
  const std::string value = trim(text.substr(at + 2));
  if (c.metric.empty() || !readBound(value, &c.bound))
    throw std::invalid_argument("--constraint '" + text + "': expected METRIC<=VALUE or METRIC>=VALUE with a number, "
                                "e.g. 'delta<=0.05'");
  return c;
}

}  // namespace rollerdyn
