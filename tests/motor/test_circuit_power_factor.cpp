// The equivalent circuit's power factor and electrical power for the circuits fitted to the two
// catalogue motors of the papers' scenes, against the circuit's impedance written out here:
//   Z = R_s + jX_σs + (jX_m ∥ (R_r1/s + jX_σr1) ∥ (R_r2/s + jX_σr2)),  I_s = U_ph/Z,
//   cos φ = cos(arg U_ph − arg I_s) = Re Z/|Z| ≤ 1,  P_in = 3·U_ph·|I_s|·cos φ  (three phases of
// the equivalent star, U_ph = U_n/√3). A √3 for a 3 in the power factor puts cos φ_n at 1.419
// for the 4A200M6U3; the fit weights cos φ_n least and prints it, no other test reads it.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <string>

#include "motor/CatalogueFit.h"
#include "motor/CircuitLaw.h"
#include "motor/MotorLawFactory.h"
#include "scene/Scene.h"
#include "scene/SceneParser.h"

namespace rollerdyn {
namespace {

struct HandCircuit {
  double cos_phi;  // cos(arg U − arg I_s) [-]
  double current;  // |I_s| [A]
  double power;    // 3·U·|I_s|·cos φ [W]
};

// The T-circuit at rotor speed ω_r and the rated supply, from the parameters alone.
HandCircuit handCircuit(const InductionMachineParameters& m, double omega_rotor) {
  using C = std::complex<double>;
  const C j(0, 1);
  const double w1 = 2 * M_PI * m.frequency;                     // supply angular frequency
  const double s = 1 - omega_rotor * m.pole_pairs / w1;         // slip
  C Y_parallel = 1.0 / (j * w1 * m.L_m);                         // magnetizing branch
  for (int k = 0; k < m.cages; ++k) Y_parallel += 1.0 / (m.R_r[k] / s + j * w1 * m.L_sigma_r[k]);
  const C Z = m.R_s + j * w1 * m.L_sigma_s + 1.0 / Y_parallel;
  const C U = std::polar(m.phase_voltage, 0.3);                  // any phase angle: only the difference counts
  const C I = U / Z;
  const double cos_phi = std::cos(std::arg(U) - std::arg(I));
  return {cos_phi, std::abs(I), 3.0 * std::abs(U) * std::abs(I) * cos_phi};
}

TEST(CircuitPowerFactor, FittedCatalogueMotorsHaveCosPhiOfTheirImpedanceAndAtMostOne) {
  // The 4A200M6U3 (cos φ_n = 0.90) and the 4A160M6U3 (cos φ_n = 0.87), both 380 V delta, 50 Hz.
  for (const char* file : {"balanced-4cart.yaml", "energy-balanced-3cart.yaml"}) {
    const Scene scene =
        parseSceneFile(std::string(ROLLERDYN_SOURCE_DIR) + "/model/" + file, {"motor.model=circuit"});
    ASSERT_TRUE(scene.induction.catalogue.given()) << file;
    const InductionMachineParameters m = sceneMachine(scene);
    // U_ph of the equivalent star: U_n/√3.
    EXPECT_NEAR(m.phase_voltage, scene.induction.voltage / std::sqrt(3.0), 1e-9 * m.phase_voltage) << file;
    const CircuitLaw law(m);
    const double w0 = m.synchronousSpeed();
    const double w_n = scene.induction.catalogue.omega_nominal;
    for (double w : {w_n, w0 * (1 - 0.005), w0 * (1 - 0.1), w0 * (1 - 0.3), 0.0}) {
      const HandCircuit ref = handCircuit(m, w);
      const CircuitSolution sol = law.solve(SupplyState{}, w);
      const std::string at = std::string(file) + " at ω_r = " + std::to_string(w) + " rad/s";
      EXPECT_LE(sol.power_factor, 1.0) << at;
      EXPECT_GT(sol.power_factor, 0.0) << at;  // motoring: the machine takes active power
      EXPECT_NEAR(sol.power_factor, ref.cos_phi, 1e-10) << at;
      EXPECT_NEAR(sol.current, ref.current, 1e-10 * ref.current) << at;
      EXPECT_NEAR(sol.electrical_power, ref.power, 1e-10 * ref.power) << at;
      MotorEvaluation e;
      law.evaluate(SupplyState{}, w, nullptr, e, nullptr);
      EXPECT_NEAR(e.electrical_power, ref.power, 1e-10 * ref.power) << at;
    }
    // The fit prints the model's cos φ_n beside the catalogue's: the same law at the rated speed.
    const CatalogueFit fit = fitSceneCatalogue(scene, scene.induction.catalogue.cages);
    ASSERT_EQ(fit.points.size(), 7u);
    EXPECT_EQ(fit.points[2].symbol, "cos φ_n");
    EXPECT_NEAR(fit.points[2].model, handCircuit(fit.machine, w_n).cos_phi, 1e-10) << file;
    EXPECT_LE(fit.points[2].model, 1.0) << file;
  }
}

}  // namespace
}  // namespace rollerdyn
