// The dynamic Kloss characteristic's default time constant T_e = 1/(ω1·s_kr) is the lag with
// which the space-phasor machine's torque follows a change of slip near synchronous speed: with
// R_s = 0 the stator flux is fixed by the supply and the rotor flux relaxes with σL_r/R_r, which
// equals 1/(ω1·s_kr) for the circuit's own breakdown slip s_kr.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "MachineFixtures.h"
#include "motor/CatalogueFit.h"
#include "motor/KlossDynamicLaw.h"
#include "motor/MotorLawFactory.h"
#include "motor/ParkLaw.h"
#include "scene/SceneParser.h"

namespace rollerdyn {
namespace {

TEST(DynamicKlossTimeConstant, EqualsTheParkMachinesTorqueLagNearSynchronousSpeed) {
  InductionMachineParameters m = test::mslMachine();
  m.R_s = 0.0;
  const ParkLaw park(m);
  double m_k = 0;
  const double s_k = breakdownSlip(m, &m_k);
  KlossMotor kloss{true, m.synchronousSpeed(), m_k, s_k, 0.29};
  const double te = KlossDynamicLaw::defaultTimeConstant(kloss, m.frequency);

  // Steady at slip 0.01, then the speed steps to slip 0.012 and stays there.
  const double w1 = m.synchronousSpeed() * (1 - 0.01), w2 = m.synchronousSpeed() * (1 - 0.012);
  std::vector<double> x(4);
  park.initialState({}, w1, true, x.data());
  const double m1 = park.steadyTorque({}, w1), m2 = park.steadyTorque({}, w2);
  const double target = m1 + (1 - std::exp(-1.0)) * (m2 - m1);
  auto torque = [&](const std::vector<double>& y) {
    MotorEvaluation e;
    park.evaluate({}, w2, y.data(), e, nullptr);
    return e.torque;
  };
  auto f = [&](const std::vector<double>& y, std::vector<double>& d) {
    MotorEvaluation e;
    park.evaluate({}, w2, y.data(), e, d.data());
  };
  const double h = te / 2000;
  double t = 0, m_prev = torque(x), t_cross = -1;
  std::vector<double> k1(4), k2(4), k3(4), k4(4), tmp(4);
  while (t < 5 * te && t_cross < 0) {
    f(x, k1);
    for (int i = 0; i < 4; ++i) tmp[i] = x[i] + 0.5 * h * k1[i];
    f(tmp, k2);
    for (int i = 0; i < 4; ++i) tmp[i] = x[i] + 0.5 * h * k2[i];
    f(tmp, k3);
    for (int i = 0; i < 4; ++i) tmp[i] = x[i] + h * k3[i];
    f(tmp, k4);
    for (int i = 0; i < 4; ++i) x[i] += h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
    t += h;
    const double mt = torque(x);
    if (mt >= target) t_cross = t - h * (mt - target) / (mt - m_prev);
    m_prev = mt;
  }
  ASSERT_GT(t_cross, 0);
  // The rotor flux turns at the slip frequency while it relaxes; at s/s_kr ≈ 0.06 that bends
  // the exponential by well under 2 %.
  EXPECT_NEAR(t_cross / te, 1.0, 0.02) << "T_e = " << te << " s, Park's 63 % time = " << t_cross << " s";
  RecordProperty("T_e", std::to_string(te));
  RecordProperty("park_63_percent_time", std::to_string(t_cross));
}

// The law a scene builds for motor.model: kloss_dynamic without motor.torque_time_constant: its
// T_e is 1/(ω1·s_kr), ω1 = 2π·f_n (Klyuchev (1985)), and after a step of the rotor speed its
// torque moves from the old static torque to the new one as M2 + (M1 − M2)·e^{−t/T_e}, the
// solution of T_e·dM/dt + M = M_static(s2) with that T_e. The torque's state is integrated here
// by classical RK4 from the law's own derivative; the exponential is written out by hand.
TEST(DynamicKlossTimeConstant, DefaultOfASceneIsOneOverSupplyFrequencyTimesCriticalSlipAndSetsTheStepResponse) {
  const char* scene_text = R"(source: unit test
simulation: {t_end: 1}
crank: {radius: 0.2, offset_deg: 90}
rods: {model: massless, length: 0.8}
carts: {count: 1, mass: 1000}
motor: {model: kloss_dynamic, omega_sync: 104.72, breakdown_torque: 517.14, critical_slip: 0.1145,
        rotor_inertia: 0.4}
reducer: {ratio: 9.8, efficiency: 0.9}
coupling: {type: rigid}
)";
  for (double f_n : {50.0, 60.0}) {
    const Scene scene = parseSceneText(scene_text, "t.yaml", {"motor.frequency=" + std::to_string(f_n)});
    ASSERT_EQ(scene.induction.torque_time_constant, 0.0);  // not given: the default applies
    const double te = 1.0 / (2 * M_PI * f_n * 0.1145);    // 27.80 ms at 50 Hz, 23.16 ms at 60 Hz
    const auto law = makeMotorLaw(scene);
    ASSERT_EQ(law->stateCount(), 1);
    EXPECT_NEAR(law->fastestTimeConstant(), te, 1e-12 * te) << "f_n = " << f_n << " Hz";

    // Steady at slip 0.02, then the rotor speed steps to slip 0.05 and stays there.
    const double w1 = 104.72 * (1 - 0.02), w2 = 104.72 * (1 - 0.05);
    const SupplyState rated;
    const double m1 = law->steadyTorque(rated, w1), m2 = law->steadyTorque(rated, w2);
    ASSERT_GT(m2 - m1, 100.0);  // a step of some hundred N·m
    double x = 0;
    law->initialState(rated, w1, true, &x);
    ASSERT_EQ(x, m1);
    auto dxdt = [&](double xs) {
      double d = 0;
      MotorEvaluation e;
      law->evaluate(rated, w2, &xs, e, &d);
      return d;
    };
    const double h = te / 1000;
    double t = 0, worst = 0, t63 = -1, prev = x;
    const double m63 = m1 + (1 - std::exp(-1.0)) * (m2 - m1);
    for (int i = 0; i < 5000; ++i) {
      const double k1 = dxdt(x), k2 = dxdt(x + 0.5 * h * k1), k3 = dxdt(x + 0.5 * h * k2), k4 = dxdt(x + h * k3);
      x += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
      t += h;
      worst = std::max(worst, std::abs(x - (m2 + (m1 - m2) * std::exp(-t / te))));
      if (t63 < 0 && x >= m63) t63 = t - h * (x - m63) / (x - prev);
      prev = x;
    }
    EXPECT_LT(worst, 1e-9 * (m2 - m1)) << "largest departure from M2 + (M1 − M2)·e^(−t/T_e), T_e = " << te << " s";
    EXPECT_NEAR(t63, te, 1e-6 * te) << "63 % of the step after " << t63 << " s, T_e = " << te << " s";
  }
}

}  // namespace
}  // namespace rollerdyn
