#include "analysis/CrankOrders.h"

#include <cmath>
#include <stdexcept>

namespace rollerdyn {

namespace {

// The signal over the last R revolutions of a forward-turning crank: crank angle and value from
// the window's start (interpolated between the rows either side of it) to the last row.
struct OrderWindow {
  std::vector<double> phi, y;
  double t_begin = 0;
};

// False when the crank does not turn forward over the window or the run does not reach back R revolutions.
bool lastRevolutions(const std::vector<double>& t, const std::vector<double>& phi, const std::vector<double>& y,
                     int revolutions, OrderWindow& w) {
  const std::size_t n = phi.size();
  const double phi_end = phi.back(), phi_begin = phi_end - 2.0 * M_PI * revolutions;
  // First row inside the window, walking back while φ decreases (a forward-turning crank).
  std::size_t i0 = n - 1;
  while (i0 > 0 && phi[i0 - 1] > phi_begin) {
    if (!(phi[i0 - 1] < phi[i0])) return false;  // not turning forward within the window
    --i0;
  }
  if (i0 == 0 || !(phi[i0 - 1] < phi[i0])) return false;  // the run does not reach back R revolutions
  // Window start interpolated between rows i0 - 1 and i0.
  const double f = (phi_begin - phi[i0 - 1]) / (phi[i0] - phi[i0 - 1]);
  w.phi = {phi_begin};
  w.y = {y[i0 - 1] + f * (y[i0] - y[i0 - 1])};
  for (std::size_t i = i0; i < n; ++i) {
    w.phi.push_back(phi[i]);
    w.y.push_back(y[i]);
  }
  w.t_begin = t[i0 - 1] + f * (t[i0] - t[i0 - 1]);
  return true;
}

// Order k's Fourier coefficients over the window by the trapezoidal rule in φ: A_0 is the mean
// (1/span); A_k the amplitude (2/span).
double orderAmplitude(const OrderWindow& w, int k, double span) {
  const std::vector<double>&p = w.phi, &v = w.y;
  double a = 0, b = 0;
  for (std::size_t i = 1; i < p.size(); ++i) {
    const double h = p[i] - p[i - 1];
    a += 0.5 * h * (v[i] * std::cos(k * p[i]) + v[i - 1] * std::cos(k * p[i - 1]));
    b += 0.5 * h * (v[i] * std::sin(k * p[i]) + v[i - 1] * std::sin(k * p[i - 1]));
  }
  return k == 0 ? a / span : 2.0 / span * std::hypot(a, b);
}

}  // namespace

CrankOrderAmplitudes crankOrderAmplitudes(const Table& ts, const std::string& column, int revolutions,
                                          int max_order) {
  if (revolutions < 1 || max_order < 0)
    throw std::invalid_argument("crankOrderAmplitudes: needs revolutions >= 1 and max_order >= 0");
  CrankOrderAmplitudes out;
  out.revolutions = revolutions;
  const std::vector<double> t = ts.column("t"), phi = ts.column("phi_crank"), y = ts.column(column);
  if (phi.size() < 3) return out;
  OrderWindow w;
  if (!lastRevolutions(t, phi, y, revolutions, w)) return out;
  out.t_begin = w.t_begin;
  out.t_end = t.back();
  const double span = 2.0 * M_PI * revolutions;
  for (int k = 0; k <= max_order; ++k) out.amplitude.push_back(orderAmplitude(w, k, span));
  out.valid = true;
  return out;
}

}  // namespace rollerdyn
