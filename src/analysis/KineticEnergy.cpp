// The machine's kinetic energy at each timeseries row (DriveSizing.h, kineticEnergy).
#include <limits>
#include <string>

#include "analysis/DriveSizing.h"

namespace rollerdyn {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The carts' speed columns the timeseries holds and, per column, the mass that moves with the cart
// [kg]: its own and the rod's half m_rod_half at its end.
struct CartSpeedColumns {
  std::vector<int> index;
  std::vector<double> mass;
};

CartSpeedColumns cartSpeedColumns(const Scene& sc, const Table& ts, double m_rod_half) {
  CartSpeedColumns c;
  for (int j = 1; j <= sc.carts.count; ++j)
    if (ts.has("v_cart_" + std::to_string(j))) {
      c.index.push_back(ts.index("v_cart_" + std::to_string(j)));
      c.mass.push_back(sc.cartMass(j - 1) + m_rod_half);
    }
  return c;
}

}  // namespace

std::vector<double> kineticEnergy(const Scene& sc, const Table& ts) {
  const std::size_t n = ts.rows.size();
  std::vector<double> T(n, 0.0);
  const double J1 = sc.motorSideInertia();
  const double m_rod_half = sc.rods.model == RodModel::Massless ? 0.0 : 0.5 * sc.rods.mass;
  const double r = sc.hasCamDrive() ? 0.0 : sc.crank.radius;
  const double Jc = sc.crankSideInertia() + sc.carts.count * m_rod_half * r * r;
  const int iw1 = ts.has("omega_motor") ? ts.index("omega_motor") : -1;
  const int iw2 = ts.has("omega_crank") ? ts.index("omega_crank") : -1;
  const CartSpeedColumns carts = cartSpeedColumns(sc, ts, m_rod_half);
  const std::vector<int>& iv = carts.index;
  const std::vector<double>& m_cart = carts.mass;
  for (std::size_t i = 0; i < n; ++i) {
    const auto& row = ts.rows[i];
    const double w2 = iw2 >= 0 ? row[iw2] : kNaN;
    // Rigid coupling: the motor turns with the crank (omega_motor may be absent).
    const double w1 = iw1 >= 0 ? row[iw1] : w2;
    double t = 0.5 * J1 * w1 * w1 + 0.5 * Jc * w2 * w2;
    for (std::size_t c = 0; c < iv.size(); ++c) t += 0.5 * m_cart[c] * row[iv[c]] * row[iv[c]];
    T[i] = t;
  }
  return T;
}

}  // namespace rollerdyn
