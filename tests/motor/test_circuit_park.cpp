// The equivalent-circuit law and the space-phasor (Park) machine on their own and against the
// circuit's closed form: steady states, power balance, switching, supply scaling, stiffness.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <vector>

#include "MachineFixtures.h"
#include "motor/CircuitLaw.h"
#include "motor/ParkLaw.h"
#include "numerics/CvodeIntegrator.h"

namespace rollerdyn {
namespace {

using test::closedForm;

double speedAt(const InductionMachineParameters& m, double s, double f_ratio = 1.0) {
  return m.synchronousSpeed() * f_ratio * (1.0 - s);
}

const std::vector<double> kSlips = {-0.5, -0.05, -1e-3, 1e-4, 1e-3, 0.01, 0.0347, 0.1, 0.3, 0.7, 1.0, 1.5};

TEST(CircuitLaw, MatchesTheClosedFormAtEverySlip) {
  for (const auto& m : {test::mslMachine(), test::krause3hp(), test::doubleCage()}) {
    const CircuitLaw law(m);
    for (double s : kSlips) {
      const test::ClosedForm ref = closedForm(m, s);
      const double w = speedAt(m, s);
      EXPECT_NEAR(law.steadyTorque({}, w), ref.torque, 1e-10 * std::abs(ref.torque)) << s;
      EXPECT_NEAR(law.steadyCurrent({}, w), ref.current, 1e-10 * ref.current) << s;
    }
  }
}

TEST(CircuitLaw, PowerBalanceAndZeroTorqueAtSynchronousSpeed) {
  for (const auto& m : {test::mslMachine(), test::doubleCage()}) {
    const CircuitLaw law(m);
    for (double s : kSlips) {
      const double w = speedAt(m, s);
      MotorEvaluation e;
      law.evaluate({}, w, nullptr, e, nullptr);
      // P_in = copper losses + M·ω_r (no other losses in the circuit)
      EXPECT_NEAR(e.electrical_power, e.copper_loss + e.torque * w, 1e-10 * std::abs(e.electrical_power)) << s;
      EXPECT_GT(e.magnetic_energy, 0);
      if (s < 0) {
        EXPECT_LT(e.torque, 0) << "generating above synchronous speed";
      }
    }
    EXPECT_NEAR(law.steadyTorque({}, m.synchronousSpeed()), 0.0, 1e-12);
    EXPECT_DOUBLE_EQ(law.synchronousSpeed(), m.synchronousSpeed());
    SupplyState off;
    off.connected = false;
    MotorEvaluation e;
    law.evaluate(off, 10.0, nullptr, e, nullptr);
    EXPECT_EQ(e.torque, 0.0);
    EXPECT_EQ(e.stator_current, 0.0);
  }
}

TEST(CircuitLaw, FollowsTheSupplyVoltageAndFrequency) {
  const InductionMachineParameters m = test::mslMachine();
  const CircuitLaw law(m);
  SupplyState half;
  half.voltage = 0.5;
  half.frequency = 0.5;
  for (double s : {0.02, 0.1, 1.0}) {
    const test::ClosedForm ref = closedForm(m, s, 0.5, 0.5);
    EXPECT_NEAR(law.steadyTorque(half, speedAt(m, s, 0.5)), ref.torque, 1e-10 * ref.torque);
  }
  EXPECT_NEAR(law.steadyTorque(half, 0.5 * m.synchronousSpeed()), 0.0, 1e-12);
}

// --- the space-phasor machine -------------------------------------------------------------

// Validation item: the Park model in steady state gives the circuit's torque and current at
// every slip, to 1e-6 relative (here far tighter: both are exact linear algebra).
TEST(ParkLaw, SteadyStateIsTheCircuitsAtEverySlip) {
  for (const auto& m : {test::mslMachine(), test::krause3hp(), test::doubleCage()}) {
    const ParkLaw law(m);
    const int n = law.stateCount();
    ASSERT_EQ(n, m.cages == 2 ? 6 : 4);
    const double psi_scale = law.stateScales()[0];
    for (double s : kSlips) {
      const test::ClosedForm ref = closedForm(m, s);
      const double w = speedAt(m, s);
      std::vector<double> x(n), xdot(n);
      law.initialState({}, w, true, x.data());
      MotorEvaluation e;
      law.evaluate({}, w, x.data(), e, xdot.data());
      EXPECT_NEAR(e.torque, ref.torque, 1e-6 * std::abs(ref.torque)) << s;
      EXPECT_NEAR(e.stator_current, ref.current, 1e-6 * ref.current) << s;
      // constant states in the frame of the supply
      for (int i = 0; i < n; ++i) EXPECT_NEAR(xdot[i], 0.0, 1e-9 * m.supplyAngularFrequency() * psi_scale) << s;
      EXPECT_NEAR(law.steadyTorque({}, w), ref.torque, 1e-6 * std::abs(ref.torque));
      EXPECT_NEAR(law.steadyCurrent({}, w), ref.current, 1e-6 * ref.current);
    }
  }
}

// The same steady state reached by integrating the equations from a de-energised machine at a
// fixed speed (CVODE BDF): the transient dies out and leaves the circuit's torque.
TEST(ParkLaw, TransientFromRestSettlesOnTheCircuitsTorque) {
  const InductionMachineParameters m = test::mslMachine();
  const ParkLaw law(m);
  const double s = 0.04, w = speedAt(m, s);
  OdeProblem p;
  p.bdf = true;
  p.rhs = [&](double, const double* y, double* yd) {
    MotorEvaluation e;
    law.evaluate({}, w, y, e, yd);
    return true;
  };
  p.y0 = Eigen::VectorXd::Zero(4);
  p.rtol = 1e-11;
  p.atol = Eigen::VectorXd::Constant(4, 1e-12 * law.stateScales()[0]);
  p.absolute_only.assign(4, false);
  p.stop_time = 8.0;
  CvodeIntegrator integ(p);
  ASSERT_TRUE(integ.advanceTo(8.0)) << integ.error();
  MotorEvaluation e;
  law.evaluate({}, w, integ.y().data(), e, nullptr);
  const test::ClosedForm ref = closedForm(m, s);
  EXPECT_NEAR(e.torque, ref.torque, 1e-6 * ref.torque);
  EXPECT_NEAR(e.stator_current, ref.current, 1e-6 * ref.current);
}

// P_el = copper loss + M·ω_r + dW/dt at any state, connected or not (the energy audit's identity):
// dW/dt along the flow by a central difference.
TEST(ParkLaw, PowerBalanceHoldsAtArbitraryStates) {
  for (const auto& m : {test::mslMachine(), test::doubleCage()}) {
    const ParkLaw law(m);
    const int n = law.stateCount();
    const double psi = law.stateScales()[0];
    for (bool connected : {true, false}) {
      SupplyState sup;
      sup.connected = connected;
      sup.phase = 0.3;
      sup.voltage = 0.8;
      for (int trial = 0; trial < 5; ++trial) {
        std::vector<double> x(n), xd(n), xp(n), xm(n);
        for (int i = 0; i < n; ++i) x[i] = psi * std::sin(1.7 * i + 2.3 * trial + 0.4);
        if (!connected) law.switchStates(SupplyState{}, sup, 50.0, x.data());
        const double w = 20.0 + 30.0 * trial;
        MotorEvaluation e, ep, em;
        law.evaluate(sup, w, x.data(), e, xd.data());
        const double h = 1e-7;
        for (int i = 0; i < n; ++i) xp[i] = x[i] + h * xd[i], xm[i] = x[i] - h * xd[i];
        law.evaluate(sup, w, xp.data(), ep, nullptr);
        law.evaluate(sup, w, xm.data(), em, nullptr);
        const double dW = (ep.magnetic_energy - em.magnetic_energy) / (2 * h);
        const double scale = std::abs(e.copper_loss) + std::abs(e.torque * w) + std::abs(e.electrical_power);
        EXPECT_NEAR(e.electrical_power, e.copper_loss + e.torque * w + dW, 1e-6 * scale) << connected;
        if (!connected) {
          EXPECT_EQ(e.electrical_power, 0.0);
          EXPECT_EQ(e.stator_current, 0.0);
          EXPECT_NEAR(e.torque, 0.0, 1e-12);
        }
      }
    }
  }
}

TEST(ParkLaw, SwitchOffForcesTheStatorCurrentToZeroAndKeepsTheRotorFlux) {
  const InductionMachineParameters m = test::doubleCage();
  const ParkLaw law(m);
  std::vector<double> x(6), x0(6);
  const double w = speedAt(m, 0.03);
  law.initialState({}, w, true, x.data());
  x0 = x;
  SupplyState off;
  off.connected = false;
  law.switchStates({}, off, w, x.data());
  for (int i = 2; i < 6; ++i) EXPECT_EQ(x[i], x0[i]);  // rotor fluxes continuous
  MotorEvaluation e;
  std::vector<double> xd(6);
  law.evaluate(off, w, x.data(), e, xd.data());
  EXPECT_EQ(e.stator_current, 0.0);
  // the stator flux's derivative keeps ψ_s = L_m·Σ i_r: integrate a while with RK4 and check
  const double h = 1e-5;
  for (int step = 0; step < 2000; ++step) {
    std::vector<double> k1(6), k2(6), k3(6), k4(6), t(6);
    auto f = [&](const std::vector<double>& y, std::vector<double>& d) {
      MotorEvaluation ee;
      law.evaluate(off, w, y.data(), ee, d.data());
    };
    f(x, k1);
    for (int i = 0; i < 6; ++i) t[i] = x[i] + 0.5 * h * k1[i];
    f(t, k2);
    for (int i = 0; i < 6; ++i) t[i] = x[i] + 0.5 * h * k2[i];
    f(t, k3);
    for (int i = 0; i < 6; ++i) t[i] = x[i] + h * k3[i];
    f(t, k4);
    for (int i = 0; i < 6; ++i) x[i] += h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
  }
  std::vector<double> y = x;
  law.switchStates({}, off, w, y.data());  // recomputes ψ_s from the rotor fluxes
  EXPECT_NEAR(y[0], x[0], 1e-9 * law.stateScales()[0]);
  EXPECT_NEAR(y[1], x[1], 1e-9 * law.stateScales()[0]);
  // the rotor flux has decayed (open-circuit rotor time constant) but not vanished in 20 ms
  const double before = std::hypot(x0[2], x0[3]), after = std::hypot(x[2], x[3]);
  EXPECT_LT(after, before);
  EXPECT_GT(after, 0.05 * before);
  // switching back on leaves every flux as it is
  y = x;
  law.switchStates(off, {}, w, y.data());
  EXPECT_EQ(y, x);
}

TEST(ParkLaw, SupplyPhaseRotatesTheSteadyStateAndLeavesTheTorque) {
  const InductionMachineParameters m = test::mslMachine();
  const ParkLaw law(m);
  const double w = speedAt(m, 0.05);
  std::vector<double> a(4), b(4);
  SupplyState shifted;
  shifted.phase = M_PI / 6;
  law.initialState({}, w, true, a.data());
  law.initialState(shifted, w, true, b.data());
  const std::complex<double> rot = std::polar(1.0, M_PI / 6);
  for (int k = 0; k < 2; ++k) {
    const std::complex<double> za(a[2 * k], a[2 * k + 1]), zb(b[2 * k], b[2 * k + 1]);
    EXPECT_NEAR(std::abs(zb - rot * za), 0.0, 1e-12);
  }
  EXPECT_NEAR(law.steadyTorque(shifted, w), law.steadyTorque({}, w), 1e-9);
  SupplyState v_f;
  v_f.voltage = v_f.frequency = 0.5;
  EXPECT_NEAR(law.steadyTorque(v_f, 0.5 * m.synchronousSpeed() * 0.95),
              closedForm(m, 0.05, 0.5, 0.5).torque, 1e-6 * closedForm(m, 0.05, 0.5, 0.5).torque);
}

TEST(ParkLaw, StiffnessScalesAndNames) {
  const ParkLaw single(test::mslMachine()), twin(test::doubleCage());
  EXPECT_EQ(single.stateNames().size(), 4u);
  EXPECT_EQ(twin.stateNames().size(), 6u);
  EXPECT_EQ(twin.stateNames()[4], "psi_r2d[Wb]");
  // MSL machine: the fast (leakage) time constant is a few ms, far below the 20 ms period.
  EXPECT_GT(single.fastestTimeConstant(), 1e-4);
  EXPECT_LT(single.fastestTimeConstant(), 2e-2);
  const InductionMachineParameters m = test::mslMachine();
  EXPECT_NEAR(single.stateScales()[0], std::sqrt(2.0) * 100 / (2 * M_PI * 50), 1e-12);
  EXPECT_EQ(single.description(), "space-phasor (Park) machine, single cage");
  EXPECT_DOUBLE_EQ(single.synchronousSpeed(), m.synchronousSpeed());
}

}  // namespace
}  // namespace rollerdyn
