// Integrates the energy flows of the built system alongside the equations of motion (as
// auxiliary z states), so the energy audit measures integration error rather than output-grid
// quadrature error: z = [motor work, damper dissipation, friction dissipation, load work] [J],
// then, with reducer.losses = power_flow only, the reducer's losses [J] (under the papers'
// constant η they are (1/η − 1)·motor work exactly and need no state: the papers' runs keep
// their states and steps). It applies no force. Elements absent from the scene contribute nothing.
#pragma once

#include "Simbody.h"

namespace rollerdyn {

class MotorForce;
class ElasticCoupling;
class RollerLoadForce;
class GuideFriction;
class CrankshaftTorsion;

class EnergyMeter : public SimTK::Force::Custom::Implementation {
 public:
  struct Sources {
    const MotorForce* motor = nullptr;
    const ElasticCoupling* coupling = nullptr;
    const RollerLoadForce* loads = nullptr;
    const GuideFriction* friction = nullptr;
    const CrankshaftTorsion* torsion = nullptr;  // the crankshaft's dampers, with the coupling's
  };
  EnergyMeter(const SimTK::GeneralForceSubsystem& forces, Sources sources);

  // z entries: 4, or 5 with the reducer's losses integrated.
  int stateCount() const { return reducer_state_ ? 5 : 4; }
  bool integratesReducerLosses() const { return reducer_state_; }

  double motorWork(const SimTK::State& s) const { return z(s, 0); }
  double dampingDissipation(const SimTK::State& s) const { return z(s, 1); }
  double frictionDissipation(const SimTK::State& s) const { return z(s, 2); }
  double loadWork(const SimTK::State& s) const { return z(s, 3); }
  // The reducer's losses on the motor's torque since t = 0 [J] (physics/ReducerLosses.h).
  double reducerLosses(const SimTK::State& s) const;

  void calcForce(const SimTK::State&, SimTK::Vector_<SimTK::SpatialVec>&, SimTK::Vector_<SimTK::Vec3>&,
                 SimTK::Vector&) const override {}
  SimTK::Real calcPotentialEnergy(const SimTK::State&) const override { return 0; }
  void realizeTopology(SimTK::State& s) const override;
  void realizeAcceleration(const SimTK::State& s) const override;
  // Writes the work rates into zdot (indexed like the force subsystem's z); state realized
  // to Velocity.
  void calcRates(const SimTK::State& s, SimTK::Vector& zdot) const;

 private:
  double z(const SimTK::State& s, int i) const { return forces_.getZ(s)[z_start_ + i]; }
  const SimTK::GeneralForceSubsystem& forces_;
  Sources sources_;
  bool reducer_state_ = false;
  mutable SimTK::ZIndex z_start_;
};

}  // namespace rollerdyn
