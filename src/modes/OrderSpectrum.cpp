#include "modes/OrderSpectrum.h"

#include <algorithm>
#include <cmath>
#include <complex>

#include <unsupported/Eigen/FFT>

#include "analysis/SteadyState.h"

namespace rollerdyn::modes {

namespace {

// y(x) interpolated linearly at xq; i walks forward from the last call (xq rises call to call).
double interpolateForward(const std::vector<double>& x, const std::vector<double>& y, double xq, size_t& i) {
  while (i + 2 < x.size() && x[i + 1] < xq) ++i;
  const double w = (x[i + 1] - x[i]) != 0 ? (xq - x[i]) / (x[i + 1] - x[i]) : 0.0;
  return y[i] + w * (y[i + 1] - y[i]);
}

// Time at each of N equally spaced crank angles over the window's R revolutions (phi_w: crank
// angle from the window's start at the times t_w, rising).
std::vector<double> timesAtEqualCrankAngles(const std::vector<double>& phi_w, const std::vector<double>& t_w, int N,
                                            int R) {
  std::vector<double> tq(N);
  size_t ia = 0;
  for (int q = 0; q < N; ++q) {
    const double pq = 2 * M_PI * R * q / N;
    tq[q] = (pq <= phi_w.front()) ? t_w.front() : interpolateForward(phi_w, t_w, pq, ia);
  }
  return tq;
}

// The share of the whole orders (every R-th bin over R revolutions) in the power of the
// one-sided spectrum `spec` of N samples, the mean left out; 1 for a signal without variation.
double wholeOrderShare(const std::vector<std::complex<double>>& spec, int N, int R) {
  double total = 0, whole = 0;
  for (int b = 1; b < N / 2; ++b) {
    const double ab = 2.0 * std::abs(spec[b]) / N;
    total += ab * ab;
    if (b % R == 0) whole += ab * ab;
  }
  return total > 0 ? whole / total : 1.0;
}

// The n_peaks largest amplitudes `a` (the mean left out), largest first, with their orders.
std::vector<SpectrumPeak> strongestOrders(const std::vector<double>& a, const std::vector<double>& orders,
                                          int n_peaks) {
  std::vector<int> idx;
  for (int b = 1; b < int(a.size()); ++b) idx.push_back(b);
  std::sort(idx.begin(), idx.end(), [&](int p, int q) { return a[p] > a[q]; });
  std::vector<SpectrumPeak> peaks;
  for (int k = 0; k < n_peaks && k < int(idx.size()); ++k) peaks.push_back({orders[idx[k]], a[idx[k]]});
  return peaks;
}

// One signal y(tt) resampled at the times tq of equal crank angles and transformed: its amplitude
// per order, its n_peaks largest orders and the share of whole orders in its power.
void addSignalSpectrum(OrderSpectrum& s, const std::string& c, const std::vector<double>& y,
                       const std::vector<double>& tt, const std::vector<double>& tq, int R, int bins, int n_peaks,
                       Eigen::FFT<double>& fft) {
  const int N = int(tq.size());
  std::vector<double> yq(N);
  size_t ib = 0;
  for (int q = 0; q < N; ++q) yq[q] = interpolateForward(tt, y, tq[q], ib);
  std::vector<std::complex<double>> spec;
  fft.fwd(spec, yq);
  std::vector<double> a(bins);
  for (int b = 0; b < bins; ++b) a[b] = (b == 0 ? 1.0 : 2.0) * std::abs(spec[b]) / N;
  s.signals.push_back(c);
  s.amplitude.push_back(a);
  s.peaks.push_back(strongestOrders(a, s.orders, n_peaks));
  s.whole_order_share.push_back(wholeOrderShare(spec, N, R));
}

// The window: the last R whole revolutions of the steady window (R, t_begin, t_end of s, and the
// last revolution's mean speed for the direction of rotation). Why there is none, empty when found.
std::string placeWindow(const Table& ts, double window_revolutions, OrderSpectrum& s, double& omega_mean) {
  if (!ts.has("t") || !ts.has("phi_crank")) return "the timeseries has no t or phi_crank column";
  const SteadyState ss = detectSteadyState(ts, window_revolutions);
  if (ss.window_revolutions < 1 || ss.revolutions.empty()) return "no whole crank revolution in the steady window";
  const int R = ss.window_revolutions;
  const CrankRevolution& first = ss.revolutions[ss.revolutions.size() - R];
  const CrankRevolution& last = ss.revolutions.back();
  s.t_begin = first.t_begin;
  s.t_end = last.t_end;
  s.revolutions = R;
  omega_mean = last.omega_mean;
  return "";
}

// The rows of the window: their times and the crank angle from the window's start, turned to
// rise with the rotation.
struct WindowAngles {
  std::vector<double> phi, t;
};

WindowAngles windowAngles(const Table& ts, const OrderSpectrum& s, double omega_mean) {
  const std::vector<double> t = ts.column("t"), phi = ts.column("phi_crank");
  // Crank angle at the window's start (interpolated) and the direction of rotation.
  size_t i0 = 0;
  const double phi_start = interpolateForward(t, phi, s.t_begin, i0);
  const double sign = omega_mean >= 0 ? 1.0 : -1.0;
  // Rows of the window, monotonic in φ (the crank turns one way in steady running).
  WindowAngles w;
  for (size_t r = 0; r < t.size(); ++r)
    if (t[r] >= s.t_begin - 1e-12 && t[r] <= s.t_end + 1e-12) {
      w.phi.push_back(sign * (phi[r] - phi_start));
      w.t.push_back(t[r]);
    }
  return w;
}

// Why the window's rows cannot be resampled at equal crank angles, empty when they can.
std::string windowAnglesProblem(const WindowAngles& w) {
  if (w.phi.size() < 8) return "too few output rows in the steady window";
  for (size_t k = 1; k < w.phi.size(); ++k)
    if (!(w.phi[k] > w.phi[k - 1])) return "the crank does not turn steadily one way in the window";
  return "";
}

// The orders up to max_order and each signal of `columns` the table has, resampled at the times tq.
void addSpectra(OrderSpectrum& s, const Table& table, const std::vector<std::string>& columns,
                const std::vector<double>& tq, double max_order, int n_peaks) {
  const int R = s.revolutions, N = int(tq.size());
  const std::vector<double> tt = table.column("t");
  Eigen::FFT<double> fft;
  const int bins = std::min(N / 2, int(std::floor(max_order * R)) + 1);
  for (int b = 0; b < bins; ++b) s.orders.push_back(double(b) / R);
  for (const std::string& c : columns) {
    if (!table.has(c)) continue;
    addSignalSpectrum(s, c, table.column(c), tt, tq, R, bins, n_peaks, fft);
  }
}

}  // namespace

OrderSpectrum orderSpectrum(const Table& ts, const Table& table, const std::vector<std::string>& columns,
                            double window_revolutions, int M, double max_order, int n_peaks) {
  OrderSpectrum s;
  s.samples_per_revolution = M;
  double omega_mean = 0;
  s.note = placeWindow(ts, window_revolutions, s, omega_mean);
  if (!s.note.empty()) return s;
  const WindowAngles w = windowAngles(ts, s, omega_mean);
  s.note = windowAnglesProblem(w);
  if (!s.note.empty()) return s;
  // Time at each equally spaced crank angle; the signals are then interpolated in time (rows
  // of `table` may be a different table with the same time column).
  const std::vector<double> tq = timesAtEqualCrankAngles(w.phi, w.t, M * s.revolutions, s.revolutions);
  if (!table.has("t")) {
    s.note = "the table has no t column";
    return s;
  }
  addSpectra(s, table, columns, tq, max_order, n_peaks);
  s.ok = !s.signals.empty();
  if (!s.ok) s.note = "none of the signals is in the table";
  return s;
}

Table spectrumTable(const OrderSpectrum& s) {
  Table t;
  t.columns.push_back("order");
  for (const std::string& c : s.signals) t.columns.push_back(c);
  for (size_t b = 0; b < s.orders.size(); ++b) {
    std::vector<double> row{s.orders[b]};
    for (const auto& a : s.amplitude) row.push_back(a[b]);
    t.rows.push_back(row);
  }
  return t;
}

}  // namespace rollerdyn::modes
