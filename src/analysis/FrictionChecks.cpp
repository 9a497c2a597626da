#include "analysis/FrictionChecks.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "physics/SelfLocking.h"
#include "io/FieldFormat.h"

namespace rollerdyn {
namespace {

constexpr double kRadToDeg = 180.0 / M_PI;

// The guide friction's self-locking, or its nearness ("" when the index is below the warning's).
std::string guideLockingWarning(const Scene& scene, const LockingMargins& m) {
  const double lam = scene.crank.radius / scene.rods.length;
  if (m.self_locking_index >= 1.0)
    return printfText("guide friction self-locks the carts: self-locking index f·max(tan β_max, (|p|·tan β_max + d/2)/b) = "
                      "%.3g >= 1 (f = %.3g, r/l = %.4g, β_max = %.1f°): near the largest rod angle the friction a rod "
                      "force causes exceeds that force's push, so the mechanism jams there",
                      m.self_locking_index, scene.loads.guide_friction, lam, m.beta_max * kRadToDeg);
  if (m.self_locking_index > kLockingIndexWarning)
    return printfText("guide friction near self-locking: index f·max(tan β_max, (|p|·tan β_max + d/2)/b) = %.3g (locks at "
                      "1); at the largest rod angle the friction is amplified up to %.3gx its open-loop value "
                      "f·(|N_front| + |N_rear|) (f = %.3g, r/l = %.4g)",
                      m.self_locking_index, m.friction_amplification, scene.loads.guide_friction, lam);
  return "";
}

// A crank-slider whose smallest transmission angle is below design practice's ("" when it is not).
std::string deadCentreWarning(const Scene& scene, const LockingMargins& m) {
  const double lam = scene.crank.radius / scene.rods.length;
  const double mu = m.transmission_angle_min * kRadToDeg;
  if (!(mu < kTransmissionAngleWarning)) return "";
  return printfText("crank-slider close to dead centre: r/l = %.4g gives a largest rod angle β_max = %.1f°, a smallest "
                    "transmission angle of %.1f° (below the %.0f° of mechanism-design practice) and rod forces up to "
                    "1/cos β_max = %.3g times the cart's horizontal load; at r/l -> 1 the rod stands across the guide "
                    "and the mechanism jams or folds over",
                    lam, m.beta_max * kRadToDeg, mu, kTransmissionAngleWarning, m.rod_force_factor);
}

}  // namespace

std::string guideNormalsDescription(const Scene& scene, bool reduced_model) {
  if (reduced_model)
    return scene.reduced.guide_normals == ReducedGuideNormals::Kinetostatic
               ? "kinetostatic: guide reactions with the carts' and rods' inertial forces, solved with the motion "
                 "(the multibody model's algebraic law)"
               : "quasi-static: the papers' cart statics without inertial forces (Loveikin, Pochka, Romasevych "
                 "(2018) eq. (14)-(25))";
  if (!scene.hasGuideFriction()) return "";
  if (scene.loads.guide_normal_force == GuideNormalForce::Algebraic)
    return "algebraic: the friction uses the guide reactions of the same instant, solved with the motion";
  return printfText("lagged: the friction uses the guide reactions followed with a time constant tau_N = %.3g s",
             scene.loads.guide_friction_lag);
}

std::vector<std::string> lockingWarnings(const Scene& scene) {
  std::vector<std::string> w;
  const LockingMargins m = lockingMargins(scene);
  if (!m.applicable) return w;
  const std::string locking = guideLockingWarning(scene, m);
  if (!locking.empty()) w.push_back(locking);
  const std::string dead_centre = deadCentreWarning(scene, m);
  if (!dead_centre.empty()) w.push_back(dead_centre);
  return w;
}

double frictionWorkDeviation(const RunResult& run) {
  const double qs = run.energy.friction_dissipation, kin = run.friction_work_kinetostatic;
  if (!std::isfinite(kin) || !(std::abs(kin) > 0.0)) return std::nan("");
  return std::abs(qs / kin - 1.0);
}

namespace {

// The papers' statics leave out each cart's d'Alembert force, whose amplitude at the crank
// speed ω is m_B·r·ω²·(1 + r/l) (the slider-crank's acceleration at the dead centre).
std::string quasiStaticJointLoadsWarning(const Scene& scene) {
  const double omega = scene.motor.enabled && scene.reducer.ratio > 0 ? scene.motor.omega_sync / scene.reducer.ratio
                                                                      : std::abs(scene.initial.crank_speed);
  const double r = scene.crank.radius, lambda = r / scene.rods.length;
  double m_B = scene.lightestCartMassWithRodShare();
  for (int j = 0; j < scene.carts.count; ++j) m_B = std::max(m_B, scene.cartMassWithRodShare(j));
  const double inertial = m_B * r * omega * omega * (1.0 + lambda);
  return printfText("the reduced model's joint loads (guide reactions, rod forces, bearing loads) are the papers' "
             "quasi-static ones: they leave out the carts' and rods' inertial forces, up to m_B·r·ω²·(1 + r/l) "
             "= %.3g kN per cart at ω = %.4g rad/s, so rod-end and guide loads can be several times too low; "
             "size joints with reduced.guide_normals: kinetostatic or with the multibody model",
             inertial / 1000.0, omega);
}

// summary.json guide_friction: the coefficient, the normal-force law, the locking margins and the friction work.
nlohmann::json guideFrictionJson(const Scene& scene, const RunResult& run, const LockingMargins& m, double deviation) {
  return {{"coefficient", scene.loads.guide_friction},
          {"normal_forces", run.guide_normals.empty() ? nlohmann::json(nullptr) : nlohmann::json(run.guide_normals)},
          {"self_locking_index", m.applicable ? jsonNumber(m.self_locking_index) : nlohmann::json(nullptr)},
          {"transmission_angle_min_deg", m.applicable ? jsonNumber(m.transmission_angle_min * kRadToDeg) : nlohmann::json(nullptr)},
          {"rod_force_factor", m.applicable ? jsonNumber(m.rod_force_factor) : nlohmann::json(nullptr)},
          {"friction_work", jsonNumber(run.energy.friction_dissipation)},
          {"friction_work_kinetostatic", jsonNumber(run.friction_work_kinetostatic)},
          {"friction_work_deviation", jsonNumber(deviation)},
          {"friction_work_threshold", kFrictionWorkWarning}};
}

}  // namespace

std::vector<std::string> addFrictionWarnings(const Scene& scene, const RunResult& run, nlohmann::json& summary) {
  if (!summary.contains("warnings") || !summary["warnings"].is_array()) summary["warnings"] = nlohmann::json::array();
  std::vector<std::string> w = lockingWarnings(scene);
  const LockingMargins m = lockingMargins(scene);
  const double deviation = frictionWorkDeviation(run);
  if (std::isfinite(deviation) && deviation > kFrictionWorkWarning)
    w.push_back(printfText("the reduced model's guide friction uses the papers' quasi-static normal forces (no inertial "
                    "forces): its friction work %.4g J differs by %.3g %% from the %.4g J the kinetostatic normal "
                    "forces give on the same motion; the drive torques are biased accordingly (set "
                    "reduced.guide_normals: kinetostatic)",
                    run.energy.friction_dissipation, 100.0 * deviation, run.friction_work_kinetostatic));
  if (run.model == "reduced" && scene.reduced.guide_normals == ReducedGuideNormals::QuasiStatic &&
      scene.simulation.reactions && !scene.hasCamDrive())
    w.push_back(quasiStaticJointLoadsWarning(scene));
  summary["guide_friction"] = guideFrictionJson(scene, run, m, deviation);
  for (const std::string& s : w) summary["warnings"].push_back(s);
  return w;
}

std::string lockingReport(const Scene& scene) {
  const LockingMargins m = lockingMargins(scene);
  std::ostringstream o;
  if (!m.applicable) {
    o << "self-locking: not applicable (cam drive: the cam pushes along the guide)\n";
    return o.str();
  }
  o << printfText("rod angle: largest β_max = %.2f° (r/l = %.4g), smallest transmission angle %.2f°, rod force up to "
           "%.3g x the cart's horizontal load\n",
           m.beta_max * kRadToDeg, scene.crank.radius / scene.rods.length, m.transmission_angle_min * kRadToDeg,
           m.rod_force_factor);
  if (scene.hasGuideFriction())
    o << printfText("self-locking index f·max(tan β_max, (|p|·tan β_max + d/2)/b) = %.3g (the cart locks at 1; friction amplified "
             "up to %.3gx)\n",
             m.self_locking_index, m.friction_amplification);
  else
    o << "self-locking index: 0 (no guide friction)\n";
  return o.str();
}

}  // namespace rollerdyn
