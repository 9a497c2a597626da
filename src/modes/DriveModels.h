// The drive seen by the modal analysis: accelerations of the independent coordinates of either
// model as a function of their values and rates, and the mass matrix that multiplies them.
//
// Independent coordinates ν: the crank angle φ2 and, with an elastic coupling, the coupling
// twist ψ = φ1 - φ2 (the multibody model's minimal formulation, MinimalCoordinates.h, and the
// reduced model's state, ReducedModel.h, use the same pair). Kinetic energy T = ½·ν̇ᵀ·M(φ2)·ν̇:
//   reduced:   M = [[J_n1 + J_n2(φ2), J_n1], [J_n1, J_n1]]   (Loveikin, Pochka, Romasevych (2018)
//              eq. (1), (9); rigid coupling: the 1×1 matrix J_n1 + J_n2(φ2))
//   multibody: M = Nᵀ·M_tree·N, Simbody's tree mass matrix on the columns of N (the velocities of
//              every body per unit ν̇), formed with SimbodyMatterSubsystem::multiplyByM.
// The accelerations ν̈ = a(φ2, ψ, φ̇2, ψ̇) are each model's own equations of motion (the reduced
// model's right-hand side; the multibody model's projected equations, MinimalDynamics.h), so
// every force element the scene builds (motor, coupling spring and damper, roller loads, guide
// friction, gravity) enters the linearization exactly as it enters a simulation. The multibody
// model's friction normal-force lags (states of their own) are held at their values at the
// operating point.
#pragma once

#include <memory>
#include <string>

#include <Eigen/Core>

#include "scene/Scene.h"

namespace rollerdyn {
class ReducedModel;
class MultibodyModel;
}  // namespace rollerdyn

namespace rollerdyn::modes {

// Values and rates of the independent coordinates.
struct DrivePoint {
  double phi = 0;       // crank angle φ2 of cart 1 [rad]
  double omega = 0;     // crank speed φ̇2 [rad/s]
  double twist = 0;     // ψ = φ1 - φ2 [rad] (0: rigid coupling)
  double twist_rate = 0;  // ψ̇ [rad/s]
};

class DriveModel {
 public:
  virtual ~DriveModel() = default;
  virtual const char* name() const = 0;      // "multibody" | "reduced"
  virtual bool elastic() const = 0;          // two independent coordinates (φ2, ψ), else one (φ2)
  int dof() const { return elastic() ? 2 : 1; }
  // Holds the states that are not independent coordinates (the multibody model's friction
  // normal-force lags) at their values for this operating point; no-op for the reduced model.
  virtual void setOperatingPoint(const DrivePoint& p) {}
  // ν̈ = (φ̈2, ψ̈) [rad/s²] (rigid: (φ̈2, 0)).
  virtual Eigen::Vector2d accelerations(const DrivePoint& p) = 0;
  // M(φ2) in (φ2, ψ) coordinates [kg·m²] (rigid: 1×1).
  virtual Eigen::MatrixXd massMatrix(double phi) = 0;
  // The reduced model of the same scene, built once with the drive: the kinematics, inertias and
  // loads the analysis reads beside the drive's own equations (naming modes, the steady guess,
  // the excitation orders), whichever model the drive is.
  virtual const ReducedModel& reducedModel() const = 0;
};

// The coupling's twist under the motor's breakdown torque at the crank axis (at least 1 N·m):
// the scale of the twist in the tolerances and difference steps of the modal analysis.
double breakdownTwist(const Scene& scene);

std::unique_ptr<DriveModel> makeReducedDrive(const Scene& scene);
std::unique_ptr<DriveModel> makeMultibodyDrive(const Scene& scene);

}  // namespace rollerdyn::modes
