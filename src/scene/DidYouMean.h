// "Did you mean ...?" hints for mistyped names: scene keys and --set paths (SceneDocument), and
// on the command line the commands, options and `sweep --param` keys. One edit distance for all,
// so every hint follows the same rule.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace rollerdyn {

// Levenshtein distance: insertions, deletions and substitutions turning `a` into `b`.
std::size_t editDistance(const std::string& a, const std::string& b);

// The candidate fewest edits away from `word` if that is at most `max_edits` and fewer than
// half the length of `word` (ties: the first in order), else "". Two edits catch a swapped pair
// or a missing letter; the half-length rule keeps "-x" from suggesting "-h".
std::string closestMatch(const std::string& word, const std::vector<std::string>& candidates,
                         std::size_t max_edits = 2);

// " (did you mean 'X'?)" for the closest match, or "" when none is close enough.
std::string didYouMean(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace rollerdyn
