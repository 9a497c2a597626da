// The crankshaft chain's modes as modes.json's `crankshaft_chain` and as console lines: rendered
// from CrankshaftChainModes only.
#include <sstream>

#include "io/FieldFormat.h"
#include "modes/ChainModes.h"

namespace rollerdyn::modes {

namespace {

// The shaft segments between the throws: the carts they join, length and stiffness.
nlohmann::json segmentsJson(const CrankshaftChainModes& m) {
  nlohmann::json seg = nlohmann::json::array();
  for (const ChainSegment& s : m.segments)
    seg.push_back({{"between_carts", {s.cart_a, s.cart_b}}, {"length_m", s.length}, {"stiffness_Nm_per_rad", s.stiffness}});
  return seg;
}

// Each elastic mode's band of natural frequency over the revolution, and its shape.
nlohmann::json modeBandsJson(const CrankshaftChainModes& m) {
  nlohmann::json modes = nlohmann::json::array();
  for (size_t k = 0; k < m.modes.size(); ++k) {
    const ChainModeBand& b = m.modes[k];
    modes.push_back({{"mode", int(k) + 1},
                     {"p_min_rad_s", b.p_min},
                     {"p_max_rad_s", b.p_max},
                     {"f_min_Hz", b.f_min},
                     {"f_max_Hz", b.f_max},
                     {"shape", b.shape}});
  }
  return modes;
}

}  // namespace

nlohmann::json chainJson(const CrankshaftChainModes& m) {
  nlohmann::json j;
  j["applicable"] = m.applies;
  if (!m.applies) {
    j["reason"] = m.not_applicable;
    return j;
  }
  j["method"] = "natural frequencies p of the lumped torsional chain (motor side, coupling, one rotor per crank throw, "
                "shaft segments c = G*I_p/dz), frozen over one revolution; checked against Holzer's method";
  j["approximations"] = m.approximations;
  j["angles"] = m.angles;
  j["segments"] = segmentsJson(m);
  j["modes"] = modeBandsJson(m);
  return j;
}

std::string chainText(const CrankshaftChainModes& m) {
  if (!m.applies) return "";
  std::ostringstream os;
  os << "  crankshaft as a torsional chain (" << m.segments.size() << " shaft segments):\n";
  for (const ChainSegment& s : m.segments)
    os << "    segment between the throws of carts " << s.cart_a << " and " << s.cart_b << ": " << significant(s.length, 4)
       << " m, c = " << significant(s.stiffness, 4) << " N*m/rad\n";
  for (size_t k = 0; k < m.modes.size(); ++k) {
    const ChainModeBand& b = m.modes[k];
    os << "    mode " << k + 1 << ": p = " << significant(b.p_min, 4) << " .. " << significant(b.p_max, 4) << " rad/s ("
       << significant(b.f_min, 4) << " .. " << significant(b.f_max, 4) << " Hz), " << b.shape << "\n";
  }
  os << "    (" << m.approximations << ")\n";
  return os.str();
}

}  // namespace rollerdyn::modes
