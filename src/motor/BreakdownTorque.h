// The breakdown torque of the motor a run simulates: the largest torque of its steady
// torque-speed curve. The Kloss laws are written in it (M_kr, Loveikin, Pochka, Romasevych (2018)
// eq. (37)); a catalogue law (equivalent circuit, space-phasor machine) has its own breakdown point,
// found on its curve, and the Kloss keys motor.breakdown_torque and the critical slip do not
// describe it. Every scale that reads "the motor's breakdown torque" (the integrators' torque
// scale, the reducer's power-flow band, the sizing's M_kr) reads it here, so a Kloss key given to
// a circuit motor changes none of them.
#pragma once

#include "motor/MotorLaw.h"
#include "scene/Scene.h"

namespace rollerdyn {

// The largest steady torque of a law under `supply` over rotor speeds 0 ... ω0·f [N·m at the
// rotor]: a scan of 400 speeds refined by golden-section search, with the speed where it lies.
struct SteadyTorquePeak {
  double speed = 0;   // rotor speed [rad/s]
  double torque = 0;  // steady torque there [N·m at the rotor]
};
SteadyTorquePeak largestSteadyTorquePoint(const MotorLaw& law, const SupplyState& supply);
double largestSteadyTorque(const MotorLaw& law, const SupplyState& supply);

// M_kr [N·m at the rotor] of the law the scene's run uses: motor.breakdown_torque for the Kloss
// laws (exactly the key, so their runs do not move by a rounding), else the peak of `law`'s
// steady curve at rated supply. Without a law (motor off, or none given) the key.
double motorBreakdownTorque(const Scene& scene, const MotorLaw* law);
// The same for the scene's own law (motor.model, built once per process: SharedMotorLaw.h); the
// key where the scene has no motor or its law cannot be built.
double motorBreakdownTorque(const Scene& scene);

}  // namespace rollerdyn
