#include "studies/SweepDesigns.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <numeric>
#include <sstream>
#include <stdexcept>

#include "scene/SceneSchema.h"

namespace rollerdyn {

namespace {

// The number a text stands for, NaN when it is not entirely one finite number (a word such as
// `rigid`); the same reading as parseSweepValues.
double numberOf(const std::string& text) {
  std::size_t used = 0;
  double v = std::numeric_limits<double>::quiet_NaN();
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    return std::numeric_limits<double>::quiet_NaN();
  }
  return (used == text.size() && std::isfinite(v)) ? v : std::numeric_limits<double>::quiet_NaN();
}

std::vector<std::string> fields(const std::string& line) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : line) {
    if (c == ',' || c == ' ' || c == '\t' || c == '\r') {
      if (!cur.empty()) out.push_back(cur);
      cur.clear();
      if (c == ',' && out.empty()) out.push_back("");  // a leading comma is an empty value
    } else {
      cur += c;
    }
  }
  if (!cur.empty()) out.push_back(cur);
  return out;
}

// SplitMix64 (Steele, Lea and Flood (2014)): a small generator whose output is fixed by its
// definition, so a seed gives the same sample with any compiler and standard library.
struct SplitMix64 {
  std::uint64_t state;
  std::uint64_t next() {
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  double uniform() { return double(next() >> 11) * 0x1.0p-53; }  // [0, 1)
  std::size_t below(std::size_t n) { return std::size_t(uniform() * double(n)); }
};

// The designs of --designs as written, each value also as a number (NaN for text).
SweepDesigns listedDesigns(const SweepOptions& o) {
  SweepDesigns d;
  d.texts = o.designs;
  for (const auto& design : d.texts) {
    std::vector<double> v;
    for (const std::string& t : design) v.push_back(numberOf(t));
    d.values.push_back(v);
  }
  return d;
}

// Every combination of the parameters' values (the full grid), the last parameter varying fastest.
SweepDesigns gridDesigns(const SweepOptions& o) {
  SweepDesigns d;
  std::size_t total = 1;
  for (const SweepParameter& p : o.params) total *= p.values.size();
  d.texts.assign(total, std::vector<std::string>(o.params.size()));
  d.values.assign(total, std::vector<double>(o.params.size()));
  for (std::size_t i = 0; i < total; ++i) {
    std::size_t rest = i;
    for (std::size_t k = o.params.size(); k-- > 0;) {
      const std::size_t j = rest % o.params[k].values.size();
      rest /= o.params[k].values.size();
      d.texts[i][k] = o.params[k].texts[j];
      d.values[i][k] = o.params[k].values[j];
    }
  }
  return d;
}

}  // namespace

SweepDesigns sweepDesigns(const SweepOptions& o) { return o.designs.empty() ? gridDesigns(o) : listedDesigns(o); }

namespace {

// A design line: one value per --param, none empty.
void checkDesignLine(const std::string& path, std::size_t line_no, const std::vector<std::string>& f,
                     std::size_t keys, const std::string& key_list) {
  if (f.size() != keys)
    throw std::invalid_argument(path + ":" + std::to_string(line_no) + ": expected " + std::to_string(keys) +
                                " value(s), one per --param (" + key_list + "), got " + std::to_string(f.size()));
  for (const std::string& v : f)
    if (v.empty())
      throw std::invalid_argument(path + ":" + std::to_string(line_no) + ": empty value (expected " +
                                  std::to_string(keys) + " value(s): " + key_list + ")");
}

}  // namespace

std::vector<std::vector<std::string>> readValuesFile(const std::string& path,
                                                     const std::vector<std::string>& keys) {
  std::ifstream in(path);
  if (!in) throw std::invalid_argument("--values-file " + path + ": cannot open it");
  std::vector<std::vector<std::string>> designs;
  std::string line;
  std::size_t line_no = 0;
  bool first = true;
  std::string key_list;
  for (const std::string& k : keys) key_list += (key_list.empty() ? "" : ", ") + k;
  while (std::getline(in, line)) {
    ++line_no;
    const auto hash = line.find('#');
    if (hash != std::string::npos) line.erase(hash);
    const std::vector<std::string> f = fields(line);
    if (f.empty()) continue;
    const bool header = first && f == keys;  // a first line naming the keys
    first = false;
    if (header) continue;
    checkDesignLine(path, line_no, f, keys.size(), key_list);
    designs.push_back(f);
  }
  if (designs.empty()) throw std::invalid_argument("--values-file " + path + ": no designs (one per line: " + key_list + ")");
  return designs;
}

SampleRange parseSampleRange(const std::string& key, const std::string& spec) {
  const auto colon = spec.find(':');
  SampleRange r;
  r.key = key;
  if (colon == std::string::npos || spec.find(':', colon + 1) != std::string::npos)
    throw std::invalid_argument("--range for " + key + ": expected a:b (lower:upper), got '" + spec + "'");
  r.lower = numberOf(spec.substr(0, colon));
  r.upper = numberOf(spec.substr(colon + 1));
  if (!std::isfinite(r.lower) || !std::isfinite(r.upper))
    throw std::invalid_argument("--range for " + key + ": a:b needs two numbers, got '" + spec + "'");
  if (!(r.lower < r.upper))
    throw std::invalid_argument("--range for " + key + ": the lower bound must be below the upper, got '" + spec + "'");
  return r;
}

std::vector<std::vector<std::string>> latinHypercube(const std::vector<SampleRange>& ranges, std::size_t n,
                                                     std::uint64_t seed) {
  if (n == 0) throw std::invalid_argument("--lhs: the number of designs must be at least 1");
  SplitMix64 rng{seed};
  std::vector<std::vector<std::string>> designs(n, std::vector<std::string>(ranges.size()));
  for (std::size_t k = 0; k < ranges.size(); ++k) {
    std::vector<std::size_t> strata(n);
    std::iota(strata.begin(), strata.end(), 0);
    for (std::size_t i = n; i-- > 1;) std::swap(strata[i], strata[rng.below(i + 1)]);  // Fisher-Yates
    const double width = (ranges[k].upper - ranges[k].lower) / double(n);
    for (std::size_t i = 0; i < n; ++i) {
      const double v = ranges[k].lower + width * (double(strata[i]) + rng.uniform());
      designs[i][k] = formatNumber(v);
    }
  }
  return designs;
}

std::vector<SweepParameter> designParameters(const std::vector<std::string>& keys,
                                             const std::vector<std::vector<std::string>>& designs) {
  std::vector<SweepParameter> params(keys.size());
  for (std::size_t k = 0; k < keys.size(); ++k) {
    params[k].key = keys[k];
    for (const auto& d : designs) {
      params[k].texts.push_back(d[k]);
      params[k].values.push_back(numberOf(d[k]));
    }
  }
  return params;
}

}  // namespace rollerdyn
