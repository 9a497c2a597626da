// The dynamic Kloss characteristic's default time constant T_e = 1/(ω1·s_kr) is the lag with
// which the space-phasor machine's torque follows a change of slip near synchronous speed: with
// R_s = 0 the stator flux is fixed by the supply and the rotor flux relaxes with σL_r/R_r, which
// equals 1/(ω1·s_kr) for the circuit's own breakdown slip s_kr.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "MachineFixtures.h"
#include "motor/CatalogueFit.h"
#include "motor/KlossDynamicLaw.h"
#include "motor/ParkLaw.h"

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

}  // namespace
}  // namespace rollerdyn
