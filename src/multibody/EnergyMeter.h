// Integrates the energy flows of the built system alongside the equations of motion (as
// auxiliary z states), so the energy audit measures integration error rather than output-grid
// quadrature error: z = [motor work, damper dissipation, friction dissipation, load work] [J].
// It applies no force. Elements absent from the scene contribute nothing.
#pragma once

#include "Simbody.h"

namespace rollerdyn {

class MotorForce;
class ElasticCoupling;
class RollerLoadForce;
class GuideFriction;

class EnergyMeter : public SimTK::Force::Custom::Implementation {
 public:
  struct Sources {
    const MotorForce* motor = nullptr;
    const ElasticCoupling* coupling = nullptr;
    const RollerLoadForce* loads = nullptr;
    const GuideFriction* friction = nullptr;
  };
  EnergyMeter(const SimTK::GeneralForceSubsystem& forces, Sources sources)
      : forces_(forces), sources_(sources) {}

  double motorWork(const SimTK::State& s) const { return z(s, 0); }
  double dampingDissipation(const SimTK::State& s) const { return z(s, 1); }
  double frictionDissipation(const SimTK::State& s) const { return z(s, 2); }
  double loadWork(const SimTK::State& s) const { return z(s, 3); }

  void calcForce(const SimTK::State&, SimTK::Vector_<SimTK::SpatialVec>&, SimTK::Vector_<SimTK::Vec3>&,
                 SimTK::Vector&) const override {}
  SimTK::Real calcPotentialEnergy(const SimTK::State&) const override { return 0; }
  void realizeTopology(SimTK::State& s) const override;
  void realizeAcceleration(const SimTK::State& s) const override;
  // Writes the four work rates into zdot (indexed like the force subsystem's z); state realized
  // to Velocity.
  void calcRates(const SimTK::State& s, SimTK::Vector& zdot) const;

 private:
  double z(const SimTK::State& s, int i) const { return forces_.getZ(s)[z_start_ + i]; }
  const SimTK::GeneralForceSubsystem& forces_;
  Sources sources_;
  mutable SimTK::ZIndex z_start_;
};

}  // namespace rollerdyn
