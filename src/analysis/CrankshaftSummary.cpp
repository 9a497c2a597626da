#include "analysis/CrankshaftSummary.h"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "io/FieldFormat.h"

namespace rollerdyn {

using nlohmann::json;

namespace {


}  // namespace

// The shaft's figures (CrankshaftBearings.h): per throw along z its peak bending moment, per
// segment (coupling to the first throw, then between throws) its peak torque.
json crankshaftJson(const CrankshaftSizing& c) {
  json throws = json::array(), segments = json::array();
  for (std::size_t q = 0; q < c.throw_carts.size() && c.available; ++q) {
    throws.push_back({{"cart", c.throw_carts[q]}, {"position", jsonNumber(c.throw_positions[q])},
                      {"bending_moment_peak", jsonNumber(c.bending_moment_peak[q])}});
    segments.push_back({{"from_cart", q == 0 ? json(nullptr) : json(c.throw_carts[q - 1])},
                        {"to_cart", c.throw_carts[q]},
                        {"torque_peak", jsonNumber(c.segment_torque_peak[q])}});
  }
  return {{"bearing_positions", c.bearing_positions},
          {"throws", throws},
          {"segments", segments},
          {"segment_torque_method",
           c.chain_torques ? "between throws the torsional chain's simulated spring torques; from the coupling to the "
                             "first throw the quasi-static sum of the crank-pin forces' torques"
                           : "quasi-static: the sum of the crank-pin forces' torques about the axis beyond the "
                             "segment (the throws' own inertia left out)"},
          {"reason", c.available ? json(nullptr) : json(c.reason)}};
}

// The crankshaft's figures (sizing.crankshaft), when the scene places throws and bearings.
std::string crankshaftText(const json& c) {
  if (!c.is_object()) return "";
  std::ostringstream o;
  if (!jsonMember(c, "reason").is_null()) {
    o << "  crankshaft bending and torsion     n/a: " << jsonText(jsonMember(c, "reason"), "n/a") << "\n";
    return o.str();
  }
  o << "  crankshaft, per throw along z (from the coupling end): peak bending moment |M| and the peak torque "
       "|T| of the shaft segment leading to it (|T|: " << jsonText(jsonMember(c, "segment_torque_method"), "n/a") << "):\n";
  const json& seg = jsonMember(c, "segments");
  std::size_t q = 0;
  for (const json& t : jsonMember(c, "throws")) {
    const json& sg = q < seg.size() ? seg[q] : json();
    o << "    throw of cart " << jsonMember(t, "cart").dump() << " at z " << jsonNumberText(jsonMember(t, "position"), "%.4g")
      << " m: |M| " << jsonNumberText(jsonMember(t, "bending_moment_peak"), "%.4g") << " N·m; segment from "
      << (jsonMember(sg, "from_cart").is_number() ? "cart " + jsonMember(sg, "from_cart").dump() + "'s throw"
                                                  : std::string("the coupling"))
      << ": |T| " << jsonNumberText(jsonMember(sg, "torque_peak"), "%.4g") << " N·m\n";
    ++q;
  }
  return o.str();
}

}  // namespace rollerdyn
