// The static and dynamic Kloss laws on their own: numbers unchanged at the rated supply, how
// they follow the supply (U², f), the dynamic characteristic's lag, switching, and the factory.
#include <gtest/gtest.h>

#include <cmath>

#include "motor/KlossDynamicLaw.h"
#include "motor/KlossLaw.h"
#include "motor/MotorLawFactory.h"
#include "physics/KlossMotor.h"
#include "scene/SceneParser.h"

namespace rollerdyn {
namespace {

// The 4A200M6U3 of Loveikin, Pochka, Romasevych (2018): ω0 = 104.72, M_kr = 517.14, s_kr = 0.1145.
KlossMotor paperMotor() {
  KlossMotor m;
  m.enabled = true;
  m.omega_sync = 104.72;
  m.breakdown_torque = 517.14;
  m.critical_slip = 0.1145;
  m.rotor_inertia = 0.4;
  return m;
}

double maxTorqueSpeed(const MotorLaw& law, const SupplyState& s, double w_lo, double w_hi, double* m_max) {
  // Golden-section search of the torque maximum on [w_lo, w_hi].
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double a = w_lo, b = w_hi;
  for (int i = 0; i < 200; ++i) {
    const double c = b - g * (b - a), d = a + g * (b - a);
    if (law.steadyTorque(s, c) > law.steadyTorque(s, d)) b = d; else a = c;
  }
  *m_max = law.steadyTorque(s, 0.5 * (a + b));
  return 0.5 * (a + b);
}

TEST(KlossLaw, RatedSupplyGivesThePapersNumbersExactly) {
  const KlossMotor m = paperMotor();
  const KlossLaw law(m);
  const SupplyState rated;
  for (double w = -50; w <= 150; w += 0.37) {
    EXPECT_EQ(law.steadyTorque(rated, w), klossRotorTorque(m, w)) << w;
    MotorEvaluation e;
    law.evaluate(rated, w, nullptr, e, nullptr);
    EXPECT_EQ(e.torque, klossRotorTorque(m, w));
    EXPECT_TRUE(std::isnan(e.stator_current));  // Kloss has no current
  }
  EXPECT_EQ(law.stateCount(), 0);
  EXPECT_TRUE(std::isinf(law.fastestTimeConstant()));
  EXPECT_DOUBLE_EQ(law.synchronousSpeed(), 104.72);
}

TEST(KlossLaw, BreakdownTorqueScalesWithVoltageSquared) {
  const KlossLaw law(paperMotor());
  SupplyState s;
  s.voltage = 1.0 / std::sqrt(3.0);  // star start of a delta motor
  for (double w : {0.0, 50.0, 92.73, 102.1})
    EXPECT_NEAR(law.steadyTorque(s, w), law.steadyTorque(SupplyState{}, w) / 3.0, 1e-12 * 517.14);
}

TEST(KlossLaw, FrequencyMovesTheCurveAndKeepsTheBreakdownSlipSpeed) {
  const KlossMotor m = paperMotor();
  const KlossLaw law(m);
  for (double phi : {0.2, 0.5, 1.0, 1.2}) {
    SupplyState s;
    s.frequency = phi;
    s.voltage = phi;  // V/f = const: same breakdown torque
    EXPECT_NEAR(law.steadyTorque(s, m.omega_sync * phi), 0.0, 1e-9);  // synchronous speed ∝ f
    double m_max = 0;
    const double w_max = maxTorqueSpeed(law, s, 0.0, m.omega_sync * phi, &m_max);
    EXPECT_NEAR(m_max, m.breakdown_torque, 1e-6 * m.breakdown_torque) << phi;
    // breakdown at the same slip speed ω0·s_kr below the synchronous speed
    EXPECT_NEAR(m.omega_sync * phi - w_max, m.omega_sync * m.critical_slip, 1e-4) << phi;
  }
}

TEST(KlossLaw, DisconnectedGivesNoTorqueAndBadSupplyIsRefused) {
  const KlossLaw law(paperMotor());
  SupplyState off;
  off.connected = false;
  EXPECT_EQ(law.steadyTorque(off, 50.0), 0.0);
  SupplyState zero_f;
  zero_f.frequency = 0.0;
  EXPECT_THROW(law.steadyTorque(zero_f, 50.0), std::invalid_argument);
  KlossMotor bad = paperMotor();
  bad.critical_slip = 0;
  EXPECT_THROW(KlossLaw{bad}, std::invalid_argument);
}

TEST(KlossDynamicLaw, DefaultTimeConstantIsOneOverSupplyFrequencyTimesCriticalSlip) {
  // 1/(2π·50·0.1145) = 27.8 ms for the papers' six-pole 4A200M6U3.
  EXPECT_NEAR(KlossDynamicLaw::defaultTimeConstant(paperMotor(), 50.0), 1.0 / (2 * M_PI * 50 * 0.1145), 1e-15);
  EXPECT_NEAR(KlossDynamicLaw::defaultTimeConstant(paperMotor(), 50.0), 0.0278, 1e-4);
}

TEST(KlossDynamicLaw, SteadyStateHasNoDerivativeAndTheStaticTorque) {
  const KlossDynamicLaw law(paperMotor(), 0.03);
  ASSERT_EQ(law.stateCount(), 1);
  EXPECT_EQ(law.stateNames().size(), 1u);
  EXPECT_DOUBLE_EQ(law.stateScales()[0], 517.14);
  EXPECT_DOUBLE_EQ(law.fastestTimeConstant(), 0.03);
  const SupplyState rated;
  for (double w : {0.0, 60.0, 100.0, 102.1, 104.72, 110.0}) {
    double x = 0, xdot = 1;
    law.initialState(rated, w, true, &x);
    MotorEvaluation e;
    law.evaluate(rated, w, &x, e, &xdot);
    EXPECT_EQ(e.torque, klossRotorTorque(paperMotor(), w));
    EXPECT_EQ(xdot, 0.0);
  }
  double x = 5;
  law.initialState(rated, 50.0, false, &x);
  EXPECT_EQ(x, 0.0);  // de-energised
}

TEST(KlossDynamicLaw, TorqueFollowsTheStaticCurveWithTheFirstOrderLag) {
  // At a fixed speed the solution of T_e·dM/dt + M = M_st is M_st·(1 − e^{−t/T_e}); integrate
  // with classical RK4 and compare.
  const double te = 0.03, w = 95.0;
  const KlossDynamicLaw law(paperMotor(), te);
  const SupplyState rated;
  const double m_st = law.steadyTorque(rated, w);
  double x = 0, t = 0;
  const double h = 1e-4;
  auto f = [&](double xs) {
    double d = 0;
    MotorEvaluation e;
    law.evaluate(rated, w, &xs, e, &d);
    return d;
  };
  while (t < 3 * te - 1e-12) {
    const double k1 = f(x), k2 = f(x + 0.5 * h * k1), k3 = f(x + 0.5 * h * k2), k4 = f(x + h * k3);
    x += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    t += h;
  }
  EXPECT_NEAR(x, m_st * (1 - std::exp(-t / te)), 1e-9 * m_st);
}

TEST(KlossDynamicLaw, SwitchOffDropsTheTorqueAndItStaysOff) {
  const KlossDynamicLaw law(paperMotor(), 0.03);
  SupplyState on, off;
  off.connected = false;
  double x = 300;
  law.switchStates(on, off, 100.0, &x);
  EXPECT_EQ(x, 0.0);
  double xdot = 1;
  MotorEvaluation e;
  law.evaluate(off, 100.0, &x, e, &xdot);
  EXPECT_EQ(e.torque, 0.0);
  EXPECT_EQ(xdot, 0.0);
  // Switching back on keeps the state (the torque builds up again with T_e).
  x = 0;
  law.switchStates(off, on, 100.0, &x);
  EXPECT_EQ(x, 0.0);
  law.evaluate(on, 100.0, &x, e, &xdot);
  EXPECT_NEAR(xdot, law.steadyTorque(on, 100.0) / 0.03, 1e-9);
  EXPECT_THROW(KlossDynamicLaw(paperMotor(), 0.0), std::invalid_argument);
}

const char* kScene = R"(source: unit test
simulation: {t_end: 1}
crank: {radius: 0.2, offset_deg: 90}
rods: {model: massless, length: 0.8}
carts: {count: 1, mass: 1000}
motor: {omega_sync: 104.72, breakdown_torque: 517.14, critical_slip: 0.1145, rotor_inertia: 0.4}
reducer: {ratio: 9.8, efficiency: 0.9}
coupling: {type: rigid}
)";

TEST(MotorLawFactory, BuildsTheLawOfMotorModel) {
  const Scene kloss = parseSceneText(kScene, "t.yaml");
  EXPECT_EQ(makeMotorLaw(kloss)->description(), "Kloss formula (static)");
  const Scene dyn = parseSceneText(kScene, "t.yaml", {"motor.model=kloss_dynamic"});
  auto law = makeMotorLaw(dyn);
  EXPECT_EQ(law->stateCount(), 1);
  EXPECT_NEAR(law->fastestTimeConstant(), 1.0 / (2 * M_PI * 50 * 0.1145), 1e-15);
  const Scene given = parseSceneText(kScene, "t.yaml", {"motor.model=kloss_dynamic", "motor.torque_time_constant=0.05"});
  EXPECT_DOUBLE_EQ(makeMotorLaw(given)->fastestTimeConstant(), 0.05);
  EXPECT_EQ(makeMotorLaw(given)->description(), "dynamic Kloss characteristic (T_e = 0.05 s)");
}

}  // namespace
}  // namespace rollerdyn
