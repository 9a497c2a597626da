// What `rollerdyn modes` writes and prints from a ModesReport (ModalAnalysis.h): the files
// (modes.json, rendered by modesJson in ModesJson.cpp; frozen.csv, campbell.csv, stability.csv)
// and the console's lines.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "modes/ModalAnalysis.h"

#include <stdexcept>

#include "io/AtomicFile.h"

namespace rollerdyn::modes {
namespace {

// The mode overdamped at every crank angle: its damping ratio, and where the drive's oscillation
// is instead.
void overdampedModeText(std::ostringstream& os, const ModelFrozenModes& m) {
  char b[512];
  std::snprintf(b, sizeof b, "damping ratio %.3g ... %.3g (>= 1: overdamped at every crank angle, it does not "
                "oscillate and has no damped frequency)", m.torsional_damping.min, m.torsional_damping.max);
  os << b;
  if (m.other_oscillating_angles > 0) {
    // With a heavy, non-proportional damping the oscillation is the pair continued from the other
    // (rigid-body) mode: say where it is, with its own triple.
    std::snprintf(b, sizeof b,
                  "; the drive's oscillation is the other mode's (without damping the whole drive turning together), "
                  "with the damping natural frequency %.4g rad/s, damping ratio %.3g, damped frequency %.4g rad/s "
                  "(means over the crank angle)",
                  m.other_natural.mean, m.other_damping.mean, m.oscillation_damped.mean);
    os << b;
  }
}

// The damped pair's natural frequency, damping ratio and damped frequency over the crank angle,
// and at how many angles it is overdamped.
void dampedPairText(std::ostringstream& os, const ModelFrozenModes& m, int angles) {
  char b[512];
  std::snprintf(b, sizeof b,
                "natural frequency %.4g ... %.4g rad/s, damping ratio %.3g ... %.3g, damped frequency %.4g ... %.4g "
                "rad/s over the crank angle (at each angle the three of one damped pair)",
                m.torsional_natural.min, m.torsional_natural.max, m.torsional_damping.min, m.torsional_damping.max,
                m.torsional_damped.min, m.torsional_damped.max);
  os << b;
  if (m.torsional_overdamped_angles > 0)
    os << "; overdamped (no oscillation, damped frequency counted as 0) at " << m.torsional_overdamped_angles << " of "
       << angles << " crank angles";
}

// The frozen-angle coupling mode of one model in one line: its frequency without damping, then the
// natural frequency, damping ratio and damped frequency of its own damped pair (FrozenModes.h).
std::string frozenTorsionalText(const ModelFrozenModes& m, bool floquet) {
  std::ostringstream os;
  char b[512];
  std::snprintf(b, sizeof b,
                "  frozen-angle torsional mode, %-9s without damping p = %.6g rad/s mean, %.6g ... %.6g over the "
                "crank angle; with the damping, the same mode: ",
                (m.model + ":").c_str(), m.torsional.mean, m.torsional.min, m.torsional.max);
  os << b;
  const int angles = int(m.angles.size());
  if (m.torsional_overdamped_angles >= angles && angles > 0)
    overdampedModeText(os, m);
  else
    dampedPairText(os, m, angles);
  // A negative damping ratio is a mode that grows: never printed as if it were a damping.
  if (m.torsional_damping.min < 0)
    os << (m.torsional_damping.max < 0 ? " (negative: the mode grows at every crank angle, unstable while frozen"
                                       : " (negative at some crank angles: the mode grows there while frozen")
       << (floquet ? "; the Floquet verdict decides over the whole revolution)" : "; no Floquet verdict)");
  os << "\n";
  return os.str();
}

// One model's columns of frozen.csv at one angle: p, ζ, ω_n, ω_d of the torsional mode (ω_d
// empty where it is overdamped) and λ of the rigid-body mode.
std::vector<double> frozenColumns(const FrozenAngle& angle) {
  double pt = NAN, zt = NAN, wn = NAN, wd = NAN, lr = NAN;
  for (const FrozenMode& mode : angle.modes)
    if (mode.torsional) {
      pt = mode.frequency;
      zt = mode.damping_ratio;
      wn = mode.natural_frequency;
      wd = mode.oscillates ? mode.damped_frequency : NAN;  // overdamped: none (empty)
    } else {
      lr = mode.lambda;
    }
  return {pt, zt, wn, wd, lr};
}

}  // namespace

Table frozenTable(const ModesReport& r) {
  Table t;
  t.columns = {"phi_crank", "omega_crank", "twist", "twist_rate"};
  for (const ModelFrozenModes& m : r.frozen) {
    if (!m.ok) continue;
    t.columns.push_back("p_torsional_" + m.model + "[rad/s]");
    t.columns.push_back("zeta_torsional_" + m.model);
    t.columns.push_back("omega_n_torsional_" + m.model + "[rad/s]");
    t.columns.push_back("omega_d_torsional_" + m.model + "[rad/s]");
    t.columns.push_back("lambda_rigid_" + m.model + "[1/s^2]");
  }
  if (r.frozen.empty()) return t;
  for (size_t i = 0; i < r.frozen[0].angles.size(); ++i) {
    const DrivePoint& p = r.frozen[0].angles[i].point;
    std::vector<double> row{p.phi, p.omega, p.twist, p.twist_rate};
    for (const ModelFrozenModes& m : r.frozen) {
      if (!m.ok) continue;
      const std::vector<double> columns = frozenColumns(m.angles[i]);
      row.insert(row.end(), columns.begin(), columns.end());
    }
    t.rows.push_back(row);
  }
  return t;
}

Table campbellTable(const ModesReport& r) {
  Table t;
  t.columns = {"omega_set[rad/s]", "omega_crank_mean[rad/s]", "p_mean[rad/s]", "p_min[rad/s]", "p_max[rad/s]",
               "p_floquet[rad/s]", "zeta_floquet", "max_multiplier_modulus", "zeta_frozen_mean", "oscillates"};
  for (const CampbellPoint& p : r.campbell.points)
    t.rows.push_back({p.omega_target, p.found ? p.omega_mean : NAN, p.frozen.mean, p.frozen.min, p.frozen.max,
                      p.floquet_frequency, p.floquet_damping_ratio, p.max_modulus, p.frozen_damping.mean,
                      p.found ? (p.oscillates ? 1.0 : 0.0) : NAN});
  return t;
}

Table stabilityTable(const ModesReport& r) {
  Table t;
  t.columns = {"chart", "c[N*m/rad]", "k[N*m*s/rad]", "omega_set[rad/s]", "omega_crank_mean[rad/s]",
               "max_multiplier_modulus", "zeta_torsional", "p_torsional[rad/s]", "stable"};
  for (size_t n = 0; n < r.charts.size(); ++n) {
    const StabilityChart& c = r.charts[n];
    for (const auto& row : c.grid)
      for (const StabilityPoint& p : row) {
        const double k = c.y_key == "damping" ? p.y : c.fixed_damping;
        const double w = c.y_key == "omega" ? p.y : NAN;
        t.rows.push_back({double(n + 1), p.c, k, w, p.omega_mean, p.max_modulus, p.torsional_damping_ratio,
                          p.torsional_frequency, p.found ? (p.stable ? 1.0 : 0.0) : NAN});
      }
  }
  return t;
}

namespace {

// Title, the two-mass first estimate and the steady motion the modes are taken along.
std::string modesHeadText(const ModesReport& r) {
  std::ostringstream os;
  char b[512];
  os << "torsional modes of " << r.scene << " (" << (r.elastic ? "elastic" : "rigid") << " coupling)\n";
  if (r.two_mass.applicable) {
    std::snprintf(b, sizeof b,
                  "  first estimate, two constant inertias (Dyomin (two rotors) eq. (10)): J1 = %.4g, J2 mean = %.4g "
                  "kg*m^2, p0 = %.5g rad/s\n",
                  r.two_mass.J1, r.two_mass.J2_mean, r.two_mass.p0);
    os << b;
  }
  if (r.steady.found) {
    std::snprintf(b, sizeof b, "  steady motion (reduced model): mean crank speed %.5g rad/s, revolution %.4g s\n",
                  r.steady.omega_mean, r.steady.period);
    os << b;
  } else {
    os << "  steady motion: not found (" << r.steady.failure << ")\n";
  }
  return os.str();
}

// The frozen-angle modes of each model, the mode shape and how far the two models agree.
std::string frozenModesText(const ModesReport& r) {
  std::ostringstream os;
  char b[512];
  for (const ModelFrozenModes& m : r.frozen) {
    if (!m.ok) {
      os << "  frozen-angle modes, " << m.model << " model: failed (" << m.failure << ")\n";
      continue;
    }
    if (r.elastic) os << frozenTorsionalText(m, r.steady.found);
  }
  if (r.elastic && !r.frozen.empty() && r.frozen[0].ok) {
    const ModelFrozenModes& m = r.frozen[0];
    std::snprintf(b, sizeof b, "  mode shape: %s (kinetic energy: motor side %.0f %%, crankshaft and rods %.0f %%, carts %.0f %%)\n",
                  m.torsional_name.c_str(), 100 * m.energy_motor_side, 100 * m.energy_shaft_rods, 100 * m.energy_carts);
    os << b;
  }
  if (std::isfinite(r.model_difference)) {
    std::snprintf(b, sizeof b, "  multibody against reduced: largest relative difference of p %.2e\n", r.model_difference);
    os << b;
  }
  return os.str();
}

// One model's Floquet line: the verdict on its steady motion over one revolution.
std::string floquetText(const SteadyMotion& m, const char* model, const std::string& run_stability_na) {
  std::ostringstream os;
  char b[512];
  if (!run_stability_na.empty()) {  // the run has no steady motion: no verdict on one
    os << "  Floquet (" << model << "): stability of the steady motion n/a: " << run_stability_na << "\n";
    return os.str();
  }
  if (!m.found) {
    os << "  Floquet (" << model << "): no steady motion (" << m.failure << ")\n";
    return os.str();
  }
  const FloquetVerdict& v = m.verdict;
  std::snprintf(b, sizeof b, "  Floquet (%s): %s, largest |multiplier| %.4g per revolution (margin %.4g)", model,
                v.text.c_str(), v.max_modulus, v.margin);
  os << b;
  if (v.has_torsional && v.torsional_resolved) {
    std::snprintf(b, sizeof b, "; torsional mode %.5g rad/s, damping ratio %.3g", v.torsional_frequency,
                  v.torsional_damping_ratio);
    os << b;
  } else if (v.has_torsional) {
    os << "; torsional mode decays more than a million-fold per revolution (its frequency is not resolved)";
  }
  os << "\n";
  return os.str();
}

// The orders the layout excites and those whose torque harmonics drive the coupling.
std::string excitationOrdersText(const ModesReport& r) {
  std::ostringstream os;
  char b[512];
  os << "  excitation orders (layout): ";
  for (size_t i = 0; i < r.orders.layout.size() && i < 12; ++i) os << (i ? ", " : "") << r.orders.layout[i];
  if (r.orders.layout.size() > 12) os << ", ...";
  std::snprintf(b, sizeof b, "; inertia swing %.3g %% of its mean\n", 100 * r.orders.inertia_relative_swing);
  os << b;
  os << "  orders that drive the coupling (load and inertia torque harmonics >= 1 % of the largest, at omega = ";
  std::snprintf(b, sizeof b, "%.4g rad/s): ", r.orders.omega);
  os << b;
  for (size_t i = 0; i < r.orders.forced.size(); ++i) os << (i ? ", " : "") << r.orders.forced[i];
  if (r.orders.forced.empty()) os << "none";
  os << "\n";
  return os.str();
}

// The crossings in the order that matters: the orders the carts' layout excites first (the
// others are harmonics of the loads' shape, often a thousandth of the layout's), each group
// nearest the speed the drive runs at first.
std::vector<CampbellCrossing> crossingsByRelevance(const ModesReport& r) {
  std::vector<CampbellCrossing> sorted = r.campbell.crossings;
  const auto& layout = r.orders.layout;
  auto rank = [&](const CampbellCrossing& c) {
    const bool of_layout = std::find(layout.begin(), layout.end(), c.order) != layout.end();
    const double distance = std::isfinite(r.steady.omega_mean) ? std::abs(c.omega - r.steady.omega_mean) : c.omega;
    return std::make_pair(of_layout ? 0 : 1, distance);
  };
  std::stable_sort(sorted.begin(), sorted.end(),
                   [&](const CampbellCrossing& a, const CampbellCrossing& b) { return rank(a) < rank(b); });
  return sorted;
}

// Where a mode meets an order (p = k*omega or 2p = k*omega) on the way to the running speed.
std::string campbellCrossingsText(const ModesReport& r) {
  std::ostringstream os;
  char b[512];
  if (r.campbell.applicable) {
    os << "  Campbell crossings (" << r.campbell.crossings.size()
       << "; the layout's orders first, each group nearest the running speed first):";
    int shown = 0;
    for (const CampbellCrossing& c : crossingsByRelevance(r)) {
      if (shown++ == 8) {
        os << " ...";
        break;
      }
      std::snprintf(b, sizeof b, " %s%d at %.4g rad/s;", c.parametric ? "2p=" : "p=", c.order, c.omega);
      os << b;
    }
    os << "\n";
  }
  return os.str();
}

// One line per stability chart: how many of its points are unstable and in how many zones.
std::string stabilityChartsText(const ModesReport& r) {
  std::ostringstream os;
  char b[512];
  for (const StabilityChart& c : r.charts) {
    if (c.y_key == "omega")
      std::snprintf(b, sizeof b, "  stability chart c x omega at k = %.4g N*m*s/rad: %d of %zu points unstable, %zu zone(s)",
                    c.fixed_damping, c.unstable_points, c.c.size() * c.y.size(), c.zones.size());
    else
      std::snprintf(b, sizeof b, "  stability chart c x k at omega = %.4g rad/s: %d of %zu points unstable, %zu zone(s)",
                    c.fixed_speed, c.unstable_points, c.c.size() * c.y.size(), c.zones.size());
    os << b;
    if (c.failed_points) os << ", " << c.failed_points << " without steady running";
    os << "\n";
  }
  return os.str();
}

}  // namespace

std::string modesText(const ModesReport& r, const std::string& run_stability_na) {
  std::ostringstream os;
  char b[512];
  os << modesHeadText(r);
  os << frozenModesText(r);
  os << floquetText(r.steady, "reduced", run_stability_na);
  if (r.has_multibody_steady) os << floquetText(r.steady_multibody, "multibody", run_stability_na);
  os << excitationOrdersText(r);
  os << campbellCrossingsText(r);
  os << separationText(r.separation);
  os << chainText(r.chain);
  os << stabilityChartsText(r);
  for (const std::string& n : r.notes) os << "  note: " << n << "\n";
  for (const auto& [name, meaning] : r.approximations) os << "  approximation, " << name << ": " << meaning << "\n";
  std::snprintf(b, sizeof b, "  analysis CPU %.2f s\n", r.cpu_seconds);
  os << b;
  return os.str();
}

void writeModesFiles(const std::string& out_dir, const ModesReport& r) {
  writeFileAtomic(out_dir + "/modes.json", modesJson(r).dump(2) + "\n");
  writeCsvAtomic(out_dir + "/frozen.csv", frozenTable(r));
  writeCsvAtomic(out_dir + "/campbell.csv", campbellTable(r));
  writeCsvAtomic(out_dir + "/stability.csv", stabilityTable(r));
}

void setChartStiffness(ModesOptions& o, const Scene& scene, double lo, double hi, const std::string& what) {
  if (!(lo > 0) || !(hi > lo))
    throw std::invalid_argument(what + ": expected LO:HI in N·m/rad with 0 < LO < HI");
  const double c_ref = scene.coupling.type == CouplingType::Elastic ? scene.coupling.stiffness : 0.0;
  if (!(c_ref > 0))
    throw std::invalid_argument(what + ": the scene's coupling is rigid; set coupling.type=elastic and "
                                "coupling.stiffness to give a range");
  o.c_low = lo / c_ref;
  o.c_high = hi / c_ref;
}

}  // namespace rollerdyn::modes
