// The crankshaft's figures in summary.json (sizing.crankshaft) and their console lines: the JSON
// is written once from CrankshaftSizing (CrankshaftBearings.h); the text only renders it.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "analysis/CrankshaftBearings.h"

namespace rollerdyn {

nlohmann::json crankshaftJson(const CrankshaftSizing& c);
// "" when `c` is not an object (the scene places no throws and bearings).
std::string crankshaftText(const nlohmann::json& c);

}  // namespace rollerdyn
