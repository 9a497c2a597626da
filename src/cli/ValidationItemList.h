// The validation items `rollerdyn validate` runs after its sections (1)-(4), in report order
// (src/compare/ValidationItems.h says how to write one). Kept in the command layer because items
// come from several layers (compare, studies).
#pragma once

#include <vector>

#include "compare/ValidationItems.h"

namespace rollerdyn::cli {

std::vector<validation::NamedItem> validationItems();

}  // namespace rollerdyn::cli
