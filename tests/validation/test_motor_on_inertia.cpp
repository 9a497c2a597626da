// The motor-on-an-inertia bench of the motor validation, on its own: a static Kloss motor
// accelerating an inertia has a closed-form run-up time, and its mechanical energy balance
// closes; the space-phasor machine's start closes the electrical balance too.
#include <gtest/gtest.h>

#include <cmath>

#include "compare/MotorOnInertia.h"
#include "compare/ReferenceMachines.h"
#include "motor/KlossLaw.h"
#include "motor/ParkLaw.h"

namespace rollerdyn {
namespace {

TEST(MotorOnInertia, KlossRunUpMatchesTheClosedForm) {
  // J·dω/dt = M(s), M = 2M_k·s·s_k/(s² + s_k²), dω = −ω0·ds:
  // t(s) = J·ω0/(2·M_k·s_k)·[(1 − s²)/2 + s_k²·ln(1/s)] from rest.
  const KlossMotor m{true, 104.72, 517.14, 0.1145, 0.4};
  const KlossLaw law(m);
  InertiaRunOptions o;
  o.inertia = 5.0;
  o.t_end = 1.5;
  o.output_step = 1e-3;
  o.rtol = 1e-10;
  const InertiaRun run = runMotorOnInertia(law, o);
  ASSERT_TRUE(run.complete) << run.error;
  const double c = o.inertia * m.omega_sync / (2 * m.breakdown_torque * m.critical_slip);
  int checked = 0;
  for (const auto& r : run.rows) {
    const double s = 1 - r.omega / m.omega_sync;
    if (s < 0.05 || r.t == 0) continue;
    const double t = c * ((1 - s * s) / 2 + m.critical_slip * m.critical_slip * std::log(1 / s));
    EXPECT_NEAR(r.t, t, 1e-6) << "s = " << s;
    ++checked;
  }
  EXPECT_GT(checked, 100);
  EXPECT_NEAR(run.mechanical_residual(), 0.0, 1e-6 * run.motor_work);
  EXPECT_EQ(run.electrical_energy, 0.0);  // Kloss has no electrical outputs: integrals stay 0
}

TEST(MotorOnInertia, ParkStartClosesTheEnergyBalance) {
  const ParkLaw law(reference::mslSquirrelCage());
  InertiaRunOptions o;
  o.inertia = reference::kMslRotorInertia;
  o.load_torque = [](double w) { return 50.0 * w / 150.0; };
  o.t_end = 0.5;
  o.output_step = 1e-3;
  o.rtol = 1e-9;
  const InertiaRun run = runMotorOnInertia(law, o);
  ASSERT_TRUE(run.complete) << run.error;
  EXPECT_GT(run.electrical_energy, 0);
  EXPECT_NEAR(run.electrical_residual(), 0.0, 1e-6 * run.electrical_energy);
  EXPECT_NEAR(run.mechanical_residual(), 0.0, 1e-6 * run.motor_work);
  EXPECT_GT(run.rows.back().omega, 0.9 * law.synchronousSpeed());
}

}  // namespace
}  // namespace rollerdyn
