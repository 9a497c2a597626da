#include "physics/TorsionalChain.h"

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace rollerdyn {

TorsionalChainLayout torsionalChainLayout(const Scene& sc) {
  const CrankshaftLayout& c = sc.crankshaft;
  const int n = sc.carts.count;
  if (!c.torsionalChain() || int(c.throw_positions.size()) != n)
    throw std::logic_error("torsional chain: needs crankshaft.torsional_stiffness and one throw position per cart");
  TorsionalChainLayout L;
  L.cart_of_throw.resize(n);
  std::iota(L.cart_of_throw.begin(), L.cart_of_throw.end(), 0);
  std::stable_sort(L.cart_of_throw.begin(), L.cart_of_throw.end(),
                   [&](int a, int b) { return c.throw_positions[a] < c.throw_positions[b]; });
  L.throw_of_cart.resize(n);
  for (int k = 0; k < n; ++k) L.throw_of_cart[L.cart_of_throw[k]] = k;
  const double flywheel = sc.flywheel.location == FlywheelLocation::Crankshaft ? sc.flywheel.inertia : 0.0;
  for (int k = 0; k < n; ++k)
    L.inertia.push_back(sc.crank.inertia_per_crank + sc.crank.shaft_inertia / n + (k == 0 ? flywheel : 0.0));
  for (int k = 0; k + 1 < n; ++k) {
    const double dz = c.throw_positions[L.cart_of_throw[k + 1]] - c.throw_positions[L.cart_of_throw[k]];
    if (!(dz > 0)) throw std::logic_error("torsional chain: two throws in one plane");
    L.length.push_back(dz);
    L.stiffness.push_back(c.torsional_stiffness / dz);
    L.damping.push_back(c.torsional_damping / dz);
  }
  return L;
}

}  // namespace rollerdyn
