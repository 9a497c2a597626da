// Order spectrum of a run's signals over its steady window: each signal resampled at equal steps
// of the crank angle over the window's whole revolutions, and its discrete Fourier transform
// (Eigen's FFT). Against the crank angle, a harmonic of the crank speed is a whole order k
// whatever small speed ripple the run has; a component at a fraction of an order (k/2 for a
// parametric resonance of order k, whose response oscillates at half the exciting order) or at the
// torsional frequency p/ω shows as a peak between whole orders. The resolution is 1/R of an order
// for R revolutions in the window.
#pragma once

#include <string>
#include <vector>

#include "io/Table.h"

namespace rollerdyn::modes {

struct SpectrumPeak {
  double order = 0;       // k (fractions when the window holds several revolutions)
  double amplitude = 0;   // one-sided amplitude [signal's unit]
};

struct OrderSpectrum {
  bool ok = false;
  std::string note;                  // why not ok (too short a window, missing columns)
  int revolutions = 0;               // R, whole revolutions analysed
  int samples_per_revolution = 0;
  double t_begin = 0, t_end = 0;     // window [s]
  std::vector<double> orders;        // 0, 1/R, 2/R, ... up to max_order
  std::vector<std::string> signals;  // column names
  std::vector<std::vector<double>> amplitude;  // [signal][bin]; bin 0: the mean
  // The largest peaks of each signal (mean excluded), strongest first.
  std::vector<std::vector<SpectrumPeak>> peaks;
  // Amplitude share of whole orders: Σ amplitude² at k·R bins / Σ amplitude² (mean excluded).
  std::vector<double> whole_order_share;
};

// Signals `columns` of `table` (rows matching `timeseries`' times; the same table is fine) over the
// steady window of the timeseries (analysis/SteadyState.h, `window_revolutions`).
OrderSpectrum orderSpectrum(const Table& timeseries, const Table& table, const std::vector<std::string>& columns,
                            double window_revolutions, int samples_per_revolution = 64, double max_order = 24,
                            int peaks = 6);

// One table: order, then one amplitude column per signal.
Table spectrumTable(const OrderSpectrum& s);

}  // namespace rollerdyn::modes
