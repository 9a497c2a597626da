// Equivalent-circuit parameters from a motor's catalogue data by least squares, after Pedra
// (2008), "On the determination of induction motor parameters from manufacturer data for
// electromagnetic transient programs", IEEE Trans. Power Systems 23(4): the model's values at
// the catalogue's points (rated point, standstill, breakdown) are made equal to the catalogue's.
//
// Catalogue points, all of the equivalent star at the rated supply (U_ph = U_n/√3, f_n):
//   rated slip s_n = 1 − ω_n/ω0:  torque M_n = P_n/ω_n, current I_n, power factor cos φ_n,
//                                 efficiency η_n = M·ω_n/P_in;
//   standstill (s = 1):           torque M_s, current I_s;
//   breakdown:                    the largest torque over 0 < s ≤ 1, M_k.
// Residuals are relative errors model/catalogue − 1, weighted 10 for the three torques, 3 for
// the two currents, 1 for cos φ_n and η_n. Why not alike: a circuit without saturation of the
// leakage paths cannot in general meet a high starting current together with a moderate
// breakdown torque (a low standstill reactance lowers the breakdown leakage too), and with
// copper losses only it meets P_in and the losses only approximately; with equal weights the
// best fit of the 4A200M6U3 misses η_n by 3.2 % and M_k by 1.8 %, of the 4A160M6U3 I_s by 7.3 %
// and M_k by 5.8 %. The drive's dynamics depend on the torques first, its start-up current
// answers on I_s, and only the energy figures on cos φ_n and η_n: the weights say so, and every
// point's error is printed beside the catalogue value (`rollerdyn motor`). Unknowns (log-scaled,
// so they stay positive): double cage R_s, X_σs, X_m, R_r1, R_r2, X_σr2, with the running cage's
// leakage equal to the stator's, X_σr1 = X_σs (our assumption: seven parameters against six
// independent data, since η_n follows from P_n, I_n, cos φ_n when the catalogue is consistent,
// P_n = √3·U_n·I_n·cos φ_n·η_n; the equal split of the running leakage is IEEE Std 112's for
// design classes A and D). Single cage: R_s, X_σs = X_σr, X_m, R_r: four unknowns against seven
// points, so it cannot meet the starting torque (the point of the double cage).
// The circuit has copper losses only: matching P_in and the shaft power puts iron, friction and
// stray losses into the copper resistances (mostly R_s), and the torque at s_n is the shaft torque.
// Method: NLopt's BOBYQA from an initial guess built from the catalogue (Kloss's breakdown
// relations for the leakage and rotor resistance, the reactive current for X_m, the losses for
// R_s), restarted from deterministic perturbations of it until every residual is below 1e-9,
// or 15 starts in a row bring no improvement, or 60 starts are used; the best fit is kept.
#pragma once

#include <string>
#include <vector>

#include "motor/InductionMachine.h"

namespace rollerdyn {

struct MotorCatalogue;

// One catalogue point: the catalogue's value beside the model's.
struct CatalogueComparison {
  std::string quantity;  // what it is, e.g. "starting torque"
  std::string symbol;    // e.g. "M_s"
  std::string unit;      // e.g. "N·m", "-"
  double catalogue = 0;
  double model = 0;
  double relativeError() const { return (model - catalogue) / catalogue; }
};

// The rated supply and machine the catalogue speaks of.
struct CatalogueSupply {
  double line_voltage = 0;  // U_n [V]
  double frequency = 50;    // f_n [Hz]
  int pole_pairs = 1;       // p [-]
};

// The model `machine` at every catalogue point (7 rows, in the order listed above).
std::vector<CatalogueComparison> compareWithCatalogue(const InductionMachineParameters& machine,
                                                      const MotorCatalogue& catalogue);
// Slip of the largest torque over 0 < s ≤ 1 at the rated supply, and that torque.
double breakdownSlip(const InductionMachineParameters& machine, double* torque = nullptr);

// Where a fit came from: fitted in this process, or read from the fit cache (FitCache.h).
struct FitOrigin {
  bool from_cache = false;  // read from cache_file, fitted by an earlier process
  std::string cache_file;   // the file the fit is kept in; "" when it could not be kept
  std::string fitted_on;    // when the fit was computed, "2026-11-28 00:41 UTC"
  double fit_seconds = 0;   // wall time the fit took [s]
  // For engineers: "fitted now in 1.68 s, kept in PATH" or "from the cache PATH (fitted on DATE
  // in 1.68 s)": the one text of it (`rollerdyn motor`, motor.json, summary.json).
  std::string describe() const;
};

struct CatalogueFit {
  InductionMachineParameters machine;
  std::vector<CatalogueComparison> points;  // compareWithCatalogue(machine, catalogue)
  double max_relative_error = 0;            // over the points
  int starts = 0;                           // optimizer starts used
  int evaluations = 0;                      // model evaluations over all starts
  FitOrigin origin;
};

// Version of the fitting method, part of every fit's cache key: BUMP IT whenever a change of the
// code can change a fit's result (computeFit, initialGuess, the weights, bounds, tolerances or
// starts in CatalogueFit.cpp, compareWithCatalogue, breakdownSlip, solveCircuit, the machine's
// fields), so that no build ever uses a fit kept by an older one.
constexpr int kCatalogueFitVersion = 1;

// Exactly what fitCatalogue(catalogue, supply, cages) reads, as text (ExactKey.h), with
// kCatalogueFitVersion, a hash of the fitting code's source files (made by the build, so an edit
// that forgot the version still changes the key) and the optimizer library's version: the key of
// both fit caches. Every
// field of MotorCatalogue and CatalogueSupply is named here by a structured binding, so a field
// added to either fails to compile until it is put into the key (or said to be unread).
std::string catalogueFitKey(const MotorCatalogue& catalogue, const CatalogueSupply& supply, int cages);

// Fits a circuit with `cages` (1 or 2) rotor cages. Deterministic, so a fit is computed once per
// process and data (both drive models and every run of a sweep build the law from the scene) and
// kept on disk for later processes (FitCache.h: keyed by catalogueFitKey); use_cache false
// computes it afresh and keeps nothing. Throws std::invalid_argument for an incomplete catalogue
// or supply.
CatalogueFit fitCatalogue(const MotorCatalogue& catalogue, const CatalogueSupply& supply, int cages,
                          bool use_cache = true);
// The fit from the disk cache when it holds this key, else computed now and kept there; no
// in-process memory (fitCatalogue adds that).
CatalogueFit fitCatalogueThroughDiskCache(const MotorCatalogue& catalogue, const CatalogueSupply& supply,
                                          int cages);

}  // namespace rollerdyn
