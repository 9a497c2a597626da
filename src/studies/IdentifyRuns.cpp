#include "studies/IdentifyRuns.h"

#include <exception>
#include <limits>
#include <mutex>
#include <thread>

#include <yaml-cpp/yaml.h>

#include "multibody/MultibodySimulation.h"
#include "reduced/ReducedModel.h"
#include "scene/DidYouMean.h"
#include "scene/SceneSchema.h"
#include "compare/RunModel.h"

namespace rollerdyn::identify {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

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

}  // namespace

double KeyMap::toValue(double u) const {
  u = std::clamp(u, 0.0, 1.0);
  return info.log_scale ? info.lower * std::pow(info.upper / info.lower, u) : info.lower + u * (info.upper - info.lower);
}

double KeyMap::toScaled(double x) const {
  const double u = info.log_scale ? std::log(x / info.lower) / std::log(info.upper / info.lower)
                                  : (x - info.lower) / (info.upper - info.lower);
  return std::clamp(u, 0.0, 1.0);
}

double KeyMap::slope(double x) const {
  return info.log_scale ? x * std::log(info.upper / info.lower) : info.upper - info.lower;
}

namespace {

// The schema's entry of a --free key: a number or a list element of numbers.
const KeySpec& numericKeySpec(const std::string& key) {
  const KeySpec* spec = findSceneKeyOrElement(key);
  if (!spec) {
    requireSceneKey("identify: --free " + key, key);  // throws with the did-you-mean hint
    throw std::invalid_argument("identify: --free " + key + ": expected a key of the scene schema");
  }
  if (spec->kind != KeyKind::Number && spec->kind != KeyKind::NumberList)
    throw std::invalid_argument("identify: --free " + key + ": expected a key whose value is a number, got " +
                                describeExpected(*spec));
  return *spec;
}

// The search bounds: --bounds, else the schema's finite range; the search runs in log scale over
// two decades or more.
void searchBounds(const IdentifyOptions& o, const KeySpec& spec, IdentifiedKey& info) {
  const std::string& key = info.key;
  const auto given = o.bounds.find(key);
  if (given != o.bounds.end()) {
    info.lower = given->second.first;
    info.upper = given->second.second;
    info.bounds_from = "--bounds";
  } else {
    const Range& r = spec.range;
    if (!std::isfinite(r.lo) || !std::isfinite(r.hi))
      throw std::invalid_argument("identify: --free " + key + ": the scene schema allows " + describeAllowed(spec) +
                                  ", no finite range; give bounds with --bounds " + key + "=LOWER:UPPER [" +
                                  spec.unit + "]");
    // An open end of the schema's range is no value a run may take: bounds just inside it.
    const double inset = 1e-9 * (r.hi - r.lo);
    info.lower = r.lo_inclusive ? r.lo : r.lo + inset;
    info.upper = r.hi_inclusive ? r.hi : r.hi - inset;
    info.bounds_from = "schema";
  }
  if (!(std::isfinite(info.lower) && std::isfinite(info.upper) && info.lower < info.upper))
    throw std::invalid_argument("identify: bounds of " + key + ": expected LOWER < UPPER, both finite, got " +
                                formatNumber(info.lower) + ":" + formatNumber(info.upper));
  info.log_scale = info.lower > 0 && info.upper / info.lower >= 100.0;
}

// The search starts from the scene's value (inside the bounds), else from the middle of the bounds.
double searchStart(const std::vector<SceneParameterRow>& rows, const KeyMap& k) {
  const double scene_value = startValue(rows, k.info.key);
  if (std::isfinite(scene_value) && scene_value >= k.info.lower && scene_value <= k.info.upper) return scene_value;
  if (std::isfinite(scene_value))
    throw std::invalid_argument("identify: " + k.info.key + ": the scene's value " + formatNumber(scene_value) +
                                " lies outside the bounds " + formatNumber(k.info.lower) + ":" +
                                formatNumber(k.info.upper) + "; widen them or --set a starting value inside");
  return k.toValue(0.5);
}

}  // namespace

std::vector<KeyMap> resolveKeys(const IdentifyOptions& o, const std::vector<SceneParameterRow>& rows) {
  if (o.free_keys.empty()) throw std::invalid_argument("identify: expected at least one --free key, got none");
  std::vector<KeyMap> keys;
  for (const std::string& key : o.free_keys) {
    for (const KeyMap& k : keys)
      if (k.info.key == key) throw std::invalid_argument("identify: --free " + key + " is given twice");
    const KeySpec& spec = numericKeySpec(key);
    KeyMap k;
    k.info.key = key;
    k.info.unit = spec.unit;
    searchBounds(o, spec, k.info);
    k.info.start = searchStart(rows, k);
    keys.push_back(k);
  }
  for (const auto& [key, b] : o.bounds)
    if (std::find(o.free_keys.begin(), o.free_keys.end(), key) == o.free_keys.end())
      throw std::invalid_argument("identify: --bounds " + key + ": expected one of the --free keys" +
                                  didYouMean(key, o.free_keys) + ", got a key that is not free");
  return keys;
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


double median(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

std::string joinList(const std::vector<std::string>& v) {
  std::string s;
  for (const std::string& x : v) s += (s.empty() ? "" : ", ") + x;
  return s;
}

std::vector<std::string> ModelRuns::overridesAt(const std::vector<double>& u, std::size_t n, double accuracy) const {
  std::vector<std::string> overrides = o_.base_overrides;
  overrides.push_back("simulation.t_end=" + formatNumber(data_.t[n - 1]));
  overrides.push_back("simulation.accuracy=" + formatNumber(accuracy > 0 ? accuracy : accuracy_));
  overrides.push_back("simulation.output_step=" + formatNumber(output_step_));
  for (std::size_t k = 0; k < keys_.size(); ++k)
    overrides.push_back(keys_[k].info.key + "=" + formatNumber(keys_[k].toValue(u[k])));
  return overrides;
}

std::vector<std::vector<double>> ModelRuns::signalsOf(const RunResult& result, std::size_t n) const {
  std::vector<std::vector<double>> model(data_.signals.size());
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
    for (std::size_t i = 0; i < n; ++i) model[s].push_back(interpolate(*table, tc, c, data_.t[i], &hint));
  }
  return model;
}

ModelRuns::Trial ModelRuns::runScene(const std::vector<std::string>& overrides, std::size_t n) {
  Trial trial;
  const Scene scene = parseSceneInput(input_, overrides);
  RunControl control;
  control.interrupt = o_.interrupt;
  const RunResult result = runModel(scene, o_.model, control);
  if (!result.stats.complete) {
    failed_.fetch_add(1);
    trial.reason = result.stats.status;
    return trial;
  }
  trial.model = signalsOf(result, n);
  trial.ok = true;
  return trial;
}

ModelRuns::Trial ModelRuns::run(const std::vector<double>& u, std::size_t n, double accuracy) {
  Trial trial;
  if (o_.interrupt && o_.interrupt->load()) {
    trial.reason = "interrupted";
    return trial;
  }
  runs_.fetch_add(1);
  const std::vector<std::string> overrides = overridesAt(u, n, accuracy);
  try {
    return runScene(overrides, n);
  } catch (const MissingColumn&) {
    throw;
  } catch (const std::exception& e) {
    failed_.fetch_add(1);
    trial.reason = e.what();
  }
  return trial;
}

std::vector<ModelRuns::Trial> ModelRuns::runAll(const std::vector<std::vector<double>>& points, std::size_t n) {
  std::vector<Trial> out(points.size());
  const std::size_t workers = std::min<std::size_t>(std::max(1, o_.threads), points.size());
  if (workers <= 1) {
    for (std::size_t i = 0; i < points.size(); ++i) out[i] = run(points[i], n);
    return out;
  }
  runOnThreads(points, n, workers, out);
  return out;
}

void ModelRuns::runOnThreads(const std::vector<std::vector<double>>& points, std::size_t n, std::size_t workers,
                             std::vector<Trial>& out) {
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
}

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

}  // namespace rollerdyn::identify
