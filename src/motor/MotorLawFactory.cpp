#include "motor/MotorLawFactory.h"

#include <stdexcept>
#include <string>

#include "motor/CircuitLaw.h"
#include "motor/ExactKey.h"
#include "motor/KlossDynamicLaw.h"
#include "motor/KlossLaw.h"
#include "motor/ParkLaw.h"
#include "scene/MotorModels.h"

namespace rollerdyn {

std::unique_ptr<MotorLaw> makeMotorLaw(const Scene& scene) { return makeMotorLaw(scene, scene.induction.model); }

std::unique_ptr<MotorLaw> makeMotorLaw(const Scene& scene, MotorModel model) {
  switch (model) {
    case MotorModel::Kloss:
      return std::make_unique<KlossLaw>(scene.motor);
    case MotorModel::KlossDynamic: {
      const double te = scene.induction.torque_time_constant > 0
                            ? scene.induction.torque_time_constant
                            : KlossDynamicLaw::defaultTimeConstant(scene.motor, scene.induction.frequency);
      return std::make_unique<KlossDynamicLaw>(scene.motor, te);
    }
    case MotorModel::Circuit:
      return std::make_unique<CircuitLaw>(sceneMachine(scene));
    case MotorModel::Park:
      return std::make_unique<ParkLaw>(sceneMachine(scene));
  }
  throw std::logic_error("makeMotorLaw: unknown motor.model");
}

namespace {
CatalogueSupply sceneSupply(const InductionMotor& im) { return {im.voltage, im.frequency, im.pole_pairs}; }
bool lawIsFitted(const InductionMotor& im) {
  return isMachineLaw(im.model) && !im.circuit.given() &&
         im.catalogue.given();
}
}  // namespace

CatalogueFit fitSceneCatalogue(const Scene& scene, int cages) {
  return fitCatalogue(scene.induction.catalogue, sceneSupply(scene.induction), cages);
}

std::string sceneCatalogueFitKey(const Scene& scene, int cages) {
  return catalogueFitKey(scene.induction.catalogue, sceneSupply(scene.induction), cages);
}

std::optional<FitOrigin> sceneFitOrigin(const Scene& scene) {
  if (!lawIsFitted(scene.induction)) return std::nullopt;
  return fitSceneCatalogue(scene, scene.induction.catalogue.cages).origin;
}

namespace {
// Each field by a structured binding, so a field added to the struct and left off here does not
// compile (the key must hold the whole motor description).
void addCircuit(ExactKey& key, const MotorCircuit& circuit) {
  const auto& [R_s, L_sigma_s, L_m, R_r, L_sigma_r, R_r2, L_sigma_r2] = circuit;
  key.add("circuit.R_s", R_s)
      .add("circuit.L_sigma_s", L_sigma_s)
      .add("circuit.L_m", L_m)
      .add("circuit.R_r", R_r)
      .add("circuit.L_sigma_r", L_sigma_r)
      .add("circuit.R_r2", R_r2)
      .add("circuit.L_sigma_r2", L_sigma_r2);
}

void addCatalogue(ExactKey& key, const MotorCatalogue& catalogue) {
  const auto& [power, omega_nominal, current, power_factor, efficiency, starting_torque_ratio, breakdown_torque_ratio,
               starting_current_ratio, cages] = catalogue;
  key.add("catalogue.power", power)
      .add("catalogue.omega_nominal", omega_nominal)
      .add("catalogue.current", current)
      .add("catalogue.power_factor", power_factor)
      .add("catalogue.efficiency", efficiency)
      .add("catalogue.starting_torque_ratio", starting_torque_ratio)
      .add("catalogue.breakdown_torque_ratio", breakdown_torque_ratio)
      .add("catalogue.starting_current_ratio", starting_current_ratio)
      .add("catalogue.cages", cages);
}
}  // namespace

std::string motorLawKey(const Scene& scene) {
  const auto& [enabled, omega_sync, breakdown_torque, critical_slip, rotor_inertia] = scene.motor;
  const auto& [model, torque_time_constant, voltage, frequency, connection, pole_pairs, circuit, catalogue] =
      scene.induction;
  ExactKey key;
  key.add("enabled", enabled)
      .add("omega_sync", omega_sync)
      .add("breakdown_torque", breakdown_torque)
      .add("critical_slip", critical_slip)
      .add("rotor_inertia", rotor_inertia)
      .add("model", model)
      .add("torque_time_constant", torque_time_constant)
      .add("voltage", voltage)
      .add("frequency", frequency)
      .add("connection", connection)
      .add("pole_pairs", pole_pairs);
  addCircuit(key, circuit);
  addCatalogue(key, catalogue);
  return key.text();
}

InductionMachineParameters sceneMachine(const Scene& scene) {
  const InductionMotor& im = scene.induction;
  if (im.circuit.given()) return InductionMachineParameters::fromScene(im);
  if (im.catalogue.given()) return fitSceneCatalogue(scene, im.catalogue.cages).machine;
  throw std::invalid_argument("the motor has neither an equivalent circuit (motor.circuit.*) nor catalogue data "
                              "(motor.catalogue.*)");
}

}  // namespace rollerdyn
