#include "modes/DriveModels.h"

#include <algorithm>
#include <cmath>

#include "motor/BreakdownTorque.h"
#include "multibody/MinimalCoordinates.h"
#include "multibody/MinimalDynamics.h"
#include "multibody/MotorForce.h"
#include "multibody/MultibodyModel.h"
#include "reduced/ReducedModel.h"

namespace rollerdyn::modes {
namespace {

class ReducedDrive : public DriveModel {
 public:
  explicit ReducedDrive(const Scene& scene) : model_(scene), y_(model_.stateSize()), dy_(model_.stateSize()) {}
  const char* name() const override { return "reduced"; }
  bool elastic() const override { return !model_.rigid(); }
  Eigen::Vector2d accelerations(const DrivePoint& p) override {
    y_.setZero();
    y_(model_.iPhi()) = p.phi;
    y_(model_.iOmega()) = p.omega;
    if (!model_.rigid()) {
      y_(model_.iTwist()) = p.twist;
      y_(model_.iTwistRate()) = p.twist_rate;
    }
    // A motor law with states of its own (the space-phasor machine's flux linkages, the dynamic
    // Kloss torque) gets them at their steady values for this rotor speed under the running
    // supply, i.e. its static torque-speed curve. Left at zero (a de-energised machine) they gave
    // no torque at all, and Newton's method on the period map found no steady running.
    if (model_.motorStateCount() > 0) {
      const double w_r = (p.omega + (model_.rigid() ? 0.0 : p.twist_rate)) * model_.scene().reducer.ratio;
      model_.motorLaw()->initialState(model_.supply().state(running_, 0.0, w_r), w_r, true,
                                      y_.data() + model_.iMotorStates());
    }
    model_.derivatives(0.0, running_, y_.data(), dy_.data());
    return {dy_(model_.iOmega()), model_.rigid() ? 0.0 : dy_(model_.iTwistRate())};
  }
  const ReducedModel& reducedModel() const override { return model_; }
  Eigen::MatrixXd massMatrix(double phi) override {
    const double J1 = model_.motorSideInertia(), J2 = model_.crankSideInertia(phi);
    if (model_.rigid()) return Eigen::MatrixXd::Constant(1, 1, J1 + J2);
    Eigen::MatrixXd M(2, 2);
    M << J1 + J2, J1, J1, J1;
    return M;
  }

 private:
  ReducedModel model_;
  Eigen::VectorXd y_, dy_;
  // The supply of steady running: the rated stage, after any star-delta changeover or ramp (the
  // phase at t = 0 would be a star connection or a waiting stage for some starting methods).
  const SupplyPhase running_{SupplyPhase::Stage::Rated, 0.0};
};

class MultibodyDrive : public DriveModel {
 public:
  explicit MultibodyDrive(const Scene& scene)
      : model_(scene), s_(model_.initialState()), coords_(model_, s_), dyn_(model_, s_) {}
  const char* name() const override { return "multibody"; }
  bool elastic() const override { return coords_.twistFree(); }
  const ReducedModel& reducedModel() const override {
    if (!reduced_) reduced_ = std::make_unique<ReducedModel>(model_.scene());  // on first use only
    return *reduced_;
  }

  Eigen::Vector2d accelerations(const DrivePoint& p) override {
    place(p);
    // The motor law's own states at their steady values for this rotor speed under the running
    // supply (its static torque-speed curve), as the reduced drive does.
    if (const MotorForce* motor = model_.motorForce(); motor && model_.motorStateCount() > 0) {
      motor->setPhase(s_, SupplyPhase{SupplyPhase::Stage::Rated, 0.0});
      model_.system().realize(s_, SimTK::Stage::Velocity);
      motor->initialize(s_, true);
    }
    dyn_.evaluate(s_, coords_);
    const Eigen::Vector2d& a = dyn_.independentAccelerations();
    return {a(0), elastic() ? a(1) : 0.0};
  }

  Eigen::MatrixXd massMatrix(double phi) override {
    DrivePoint p;
    p.phi = phi;
    place(p);
    model_.system().realize(s_, SimTK::Stage::Position);
    const int k = coords_.freeSpeeds();
    Eigen::MatrixXd M(k, k);
    SimTK::Vector mn;
    for (int j = 0; j < k; ++j) {
      model_.matter().multiplyByM(s_, coords_.column(j), mn);
      for (int i = 0; i < k; ++i) M(i, j) = ~coords_.column(i) * mn;
    }
    return M;
  }

  // The friction normal-force lags N̂ set to the guide normal forces N of this state: the fixed
  // point of N̂ = N(state, f·|N̂|) (the friction forces change the normals by a factor of order
  // f = 0.008, so each pass gains about two digits; three passes reach round-off). Each pass is
  // one evaluation plus the inverse-dynamics normals; the rate (N - N̂)/τ_N times τ_N moves N̂ to N.
  void setOperatingPoint(const DrivePoint& p) override {
    if (!model_.hasGuideFriction()) return;
    place(p);
    const double tau = model_.scene().loads.guide_friction_lag;
    for (int pass = 0; pass < 3; ++pass) {
      dyn_.evaluate(s_, coords_);
      model_.auxiliaryRates(s_, dyn_.guideNormals(s_), zdot_);
      SimTK::Vector& z = model_.forces().updZ(s_);
      z += tau * zdot_;  // lags: N̂ + τ·(N - N̂)/τ = N; the energy integrals move, but no force reads them
    }
  }

 private:
  // q, u of every body from the independent coordinates (closed-form loops); z unchanged.
  void place(const DrivePoint& p) {
    IndependentState x;
    x.crank_angle = p.phi;
    x.crank_speed = p.omega;
    x.twist = p.twist;
    x.twist_rate = p.twist_rate;
    coords_.apply(0.0, x, s_);
  }

  MultibodyModel model_;
  mutable std::unique_ptr<ReducedModel> reduced_;
  SimTK::State s_;
  MinimalCoordinates coords_;
  MinimalDynamics dyn_;
  SimTK::Vector zdot_;
};

}  // namespace

std::unique_ptr<DriveModel> makeReducedDrive(const Scene& scene) { return std::make_unique<ReducedDrive>(scene); }
std::unique_ptr<DriveModel> makeMultibodyDrive(const Scene& scene) {
  Scene s = scene;
  s.simulation.formulation = Formulation::Minimal;
  return std::make_unique<MultibodyDrive>(s);
}

double breakdownTwist(const Scene& scene) {
  return std::max(motorBreakdownTorque(scene) * scene.reducer.ratio * scene.reducer.efficiency, 1.0) /
         scene.coupling.stiffness;
}

}  // namespace rollerdyn::modes
