// The designs (points) of a sweep: the Cartesian grid of --values, one design per line of a
// values file, or a Latin hypercube sample of N designs in given ranges (McKay, Beckman and
// Conover (1979): each range cut into N equal strata, one value per stratum, the strata of
// the parameters paired by independent random permutations). Every design is a list of texts,
// one per parameter, applied as --set KEY=TEXT; its numbers are those texts read back, so the
// value a run used and the value written to sweep.csv are the same.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "studies/Sweep.h"

namespace rollerdyn {

struct SweepDesigns {
  std::vector<std::vector<std::string>> texts;  // per design, per parameter
  std::vector<std::vector<double>> values;      // the same read as numbers (NaN for words)
};

// The designs of a sweep: options.designs when given, else the grid of options.params (last
// parameter fastest).
SweepDesigns sweepDesigns(const SweepOptions& options);

// A values file: one design per line, one value per key, separated by commas or blanks; '#'
// starts a comment; blank lines are skipped; an optional first line naming the keys (in order)
// is a header. Throws std::invalid_argument naming FILE:LINE and what was expected.
std::vector<std::vector<std::string>> readValuesFile(const std::string& path,
                                                     const std::vector<std::string>& keys);

// Range of one parameter for sampling: lower and upper bound in the key's unit.
struct SampleRange {
  std::string key;     // scene key path
  double lower = 0;    // lower bound (scene unit of the key)
  double upper = 0;    // upper bound (scene unit of the key), > lower
};

// "a:b" with a < b, both finite. Throws std::invalid_argument naming the key.
SampleRange parseSampleRange(const std::string& key, const std::string& spec);

// n designs of a Latin hypercube over ranges, reproducible from seed on every platform (own
// 64-bit generator, no std:: distributions whose output is implementation-defined); each value
// rounded to 12 significant digits (the text given to --set).
std::vector<std::vector<std::string>> latinHypercube(const std::vector<SampleRange>& ranges, std::size_t n,
                                                     std::uint64_t seed);

// Sweep parameters for explicit designs: each key with the column of its design values (what
// sweep.json lists under "parameters").
std::vector<SweepParameter> designParameters(const std::vector<std::string>& keys,
                                             const std::vector<std::vector<std::string>>& designs);

}  // namespace rollerdyn
