// The validation items `rollerdyn validate` runs after its sections (1)-(5), in report order
// (src/compare/ValidationItems.h says how to write one). Kept in the command layer because items
// come from several layers (compare, studies, modes).
#pragma once

#include <string>
#include <vector>

#include "compare/ValidationItems.h"
#include "modes/ModesValidation.h"

namespace rollerdyn::cli {

// `out_dir`: the report's folder; the torsional-modes item writes its own page under out_dir/modes/.
std::vector<validation::NamedItem> validationItems(const std::string& out_dir);

// The torsional-modes checks as a report section: each check that makes a claim is a claim (counted
// in the summary, deciding the exit status), each measurement a line of text.
validation::ValidationSection modesSection(const modes::ModesValidationResult& m, const std::string& page);

// Writes the modes page and its numbers: out_dir/modes/validation.md and validation.json.
void writeModesPage(const std::string& out_dir, const modes::ModesValidationResult& m);

}  // namespace rollerdyn::cli
