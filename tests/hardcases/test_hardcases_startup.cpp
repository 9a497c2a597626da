// Hard cases of starting and stopping (HardCaseSupport.h: both models at a and a/10, no NaN,
// constraint error, energy audit, convergence of crank speed and coupling torque, and the models'
// agreement; each case's constants measured and claimed 3x). Machine: Loveikin, Pochka,
// Romasevych (2018) (tests/support/Loveikin2018Scene.h) driven by its 4A200M6U3 as the space-phasor
// (Park) machine, the double-cage circuit fitted to the motor's catalogue (model/balanced-4cart.yaml,
// `rollerdyn motor`: per phase of the equivalent star, U_ph = 219.4 V, 50 Hz, p = 3), written here
// so the cases do not depend on the fit. Its fastest electrical time constant is 1.6 ms and it
// oscillates at the supply frequency after every switching: the integrators must resolve a
// 20 ms oscillation and then step over it once it has decayed. The energy audit is the
// mechanical one (motor work = ∫M·ω dt, brake, damping, friction, loads, ΔT, ΔV): the electrical
// side is the law's own (validated with the motor laws).
//
// Claims: as in test_hardcases.cpp, 3x the constants measured on this build (Release, g++ 12), the
// multibody model per formulation (constrained: Runge-Kutta-Merson, the scene default; minimal:
// CVODE Adams, the largest over a·{0.7, 0.85, 1, 1.2, 1.4}), given beside each claim as
// "measured": residual/(a·E) (larger of a and a/10), dw/(a·W), dM/(a·M); the models' agreement
// max|dw|/W, max|dM|/M at a/10 (their one physical difference, the guide friction's normal forces,
// as in every case with friction). The electrical law is not stiff enough here for BDF
// (motor/Stiffness.h: 1.6 ms against the 0.5 ms switch), so CVODE runs Adams in both models.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "HardCaseSupport.h"
#include "motor/MotorLaw.h"

namespace rollerdyn::hardcases {
namespace {

Expect claims(Claims multibody, Claims multibody_minimal, Claims reduced, double models_speed, double models_torque) {
  Expect e;
  e.multibody = multibody;
  e.multibody_minimal = multibody_minimal;
  e.reduced = reduced;
  e.models_speed = models_speed;
  e.models_torque = models_torque;
  return e;
}

// The paper's machine with the fitted space-phasor motor.
Scene parkScene(const std::string& name, double t_end) {
  Scene s = hardCaseMachine();
  s.name = name;
  s.simulation.t_end = t_end;
  s.simulation.output_step = 1e-3;  // the supply-frequency transient (20 ms period) in the rows
  InductionMotor& m = s.induction;
  m.model = MotorModel::Park;
  m.voltage = 380.0;
  m.frequency = 50.0;
  m.connection = WindingConnection::Delta;
  m.pole_pairs = 3;
  m.circuit = {0.5914988630049438,    0.000629002244246838, 0.049050792743013875, 0.1710741832367215,
               0.000629002244246838,  0.45464196353551223,  0.0053410664460293265};
  return s;
}

double maxOver(const Table& t, const std::string& column, double t0, double t1, bool absolute = true) {
  double m = -INFINITY;
  const int it = t.index("t"), ic = t.index(column);
  for (const auto& row : t.rows)
    if (row[it] >= t0 && row[it] <= t1) m = std::max(m, absolute ? std::abs(row[ic]) : row[ic]);
  return m;
}

// Direct-on-line start of the Park machine from rest: de-energised fluxes, the supply applied at
// t = 0; the stator flux's DC component decays over tens of ms while the torque oscillates at
// the supply frequency (Krause, ch. 6 free acceleration), then the drive runs up (≈ 0.5 s).
TEST(HardCasesStartUp, ParkDirectOnLineStart) {
  const Scene s = parkScene("park-dol", 1.0);
  // measured: multibody 1.4e-3, 0.68, 56; minimal 0.048, 0.093, 1.8; reduced 1.4, 2.6, 1.0e2;
  // models 3.0e-4, 1.8e-3.
  const BothModels b = checkBothModels(s, 1e-6, claims({4.2e-3, 2.0, 170}, {0.15, 0.28, 5.4}, {4.2, 7.8, 310}, 9e-4, 5.4e-3));
  for (Model m : {Model::Multibody, Model::Reduced}) {
    const Table& t = (m == Model::Multibody ? b.multibody : b.reduced).at_a.timeseries;
    const double peak = maxOver(t, "motor_torque", 0, 0.1, false);
    std::printf("  %-9s park-dol: peak motor torque in 0.1 s %.5g N*m, max current %.5g A\n", name(m), peak,
                maxOver(t, "stator_current", 0, 0.1));
    // The switching transient: within 0.1 s the torque rises above the law's largest steady
    // torque (517.3 N·m at the rotor, × u·η = 4563 N·m), which no static law can give.
    // Measured 5005 N·m, 1.097x; claimed above 1.05x.
    EXPECT_GT(peak, 1.05 * 517.3365 * s.reducer.ratio * s.reducer.efficiency) << name(m);
  }
}

// Star-delta changeover at a rotor speed (root finding in every integrator): the stator flux
// built in star at U_n/√3 meets the delta voltage, √3 larger and 30° ahead, at once.
TEST(HardCasesStartUp, StarDeltaChangeoverAtSpeed) {
  Scene s = parkScene("star-delta", 1.8);
  s.motor_start.method = StartMethod::StarDelta;
  s.motor_start.changeover_speed = 80.0;
  // measured: multibody 7.4e-4, 0.52, 44; minimal 0.026, 0.36, 3.9; reduced 0.62, 5.6, 62;
  // models 9.7e-4, 8.7e-3.
  const BothModels b = checkBothModels(s, 1e-6, claims({2.2e-3, 1.6, 130}, {0.078, 1.1, 12}, {1.9, 17, 190}, 2.9e-3, 0.026));
  for (Model m : {Model::Multibody, Model::Reduced}) {
    const Table& t = (m == Model::Multibody ? b.multibody : b.reduced).at_a.timeseries;
    const int iu = t.index("supply_voltage_ratio"), iw = t.index("omega_motor"), it = t.index("t");
    int changeovers = 0;
    for (size_t i = 1; i < t.rows.size(); ++i)
      if (t.rows[i][iu] == 1.0 && t.rows[i - 1][iu] < 1.0) {
        ++changeovers;
        const double w_before = s.reducer.ratio * t.rows[i - 1][iw];
        std::printf("  %-9s star-delta: changeover between t = %.4f and %.4f s, rotor speed %.5g ... %.5g rad/s\n",
                    name(m), t.rows[i - 1][it], t.rows[i][it], w_before, s.reducer.ratio * t.rows[i][iw]);
        // Found by root finding: the last star row lies below the changeover speed, within the
        // speed gained in one 1 ms row (≈ 0.1 rad/s here).
        EXPECT_LT(w_before, 80.0) << name(m);
        EXPECT_GT(w_before, 79.8) << name(m);
      }
    EXPECT_EQ(changeovers, 1) << name(m);
  }
}

// Soft start: voltage ramp from 0.35 U_n over 1 s with a 150 A current limit.
TEST(HardCasesStartUp, SoftStartRampWithCurrentLimit) {
  Scene s = parkScene("soft-start", 1.5);
  s.motor_start.method = StartMethod::SoftStarter;
  s.motor_start.initial_voltage = 0.35;
  s.motor_start.ramp_time = 1.0;
  s.motor_start.current_limit = 150.0;
  // measured: multibody 7.8e-4, 0.57, 65; minimal 4.1e-4, 0.18, 1.7; reduced 0.22, 1.8, 50; models
  // 6.9e-4, 5.9e-3 (both formulations alike). Before the limit held after the ramp (the starter went
  // to full voltage at t_on + t_ramp, a direct-on-line step) the models differed by 3.2e-4, 1.5e-3:
  // the limited stage's voltage I_lim/I_1(ω_r) follows the rotor speed, so the models' small speed
  // difference now reaches the torque until the bypass closes at ω_lim.
  const BothModels b = checkBothModels(s, 1e-6, claims({2.2e-3, 1.7, 200}, {0.33, 0.54, 6}, {6.3, 9, 310}, 2.1e-3, 0.018));
  for (Model m : {Model::Multibody, Model::Reduced}) {
    const Table& t = (m == Model::Multibody ? b.multibody : b.reduced).at_a.timeseries;
    const double I = maxOver(t, "stator_current", 0.1, 1.0);
    std::printf("  %-9s soft-start: max current in the ramp after 0.1 s %.5g A\n", name(m), I);
    // The limit is quasi-static (Supply.h): the machine's flux transient overshoots it a little.
    // Measured 150.9 A (0.6 %); claimed within 2 %.
    EXPECT_LT(I, 150.0 * 1.02) << name(m);
  }
}

// Switch-off at speed and restart while the rotor flux lingers: the machine runs at nominal
// speed in steady state, is switched off at 0.3 s (stator current to zero, the rotor flux decays
// with the rotor's time constant while it turns), and switched on again at 0.45 s against the
// residual flux, whose phase has slipped against the supply's.
TEST(HardCasesStartUp, SwitchOffAndRestartAtSpeed) {
  Scene s = parkScene("restart", 1.0);
  s.initial.crank_speed = 10.42;
  s.motor_stop.t_off = 0.3;
  s.motor_stop.t_restart = 0.45;
  // measured: multibody 3.0e-3, 0.024, 1.8; minimal 0.059, 0.033, 1.3; reduced 0.65, 2.2, 1.2e2 (residual
  // 0.13 before the friction-work check's integral, as above); models 2.5e-4, 9.9e-3.
  const BothModels b = checkBothModels(s, 1e-6, claims({9e-3, 0.072, 5.4}, {0.18, 0.1, 3.9}, {2.0, 6.6, 360}, 7.5e-4, 0.03));
  for (Model m : {Model::Multibody, Model::Reduced}) {
    const Table& t = (m == Model::Multibody ? b.multibody : b.reduced).at_a.timeseries;
    std::printf("  %-9s restart: steady |M| before %.5g, peak after restart %.5g N*m, current %.5g A\n", name(m),
                maxOver(t, "motor_torque", 0.1, 0.3), maxOver(t, "motor_torque", 0.45, 0.6),
                maxOver(t, "stator_current", 0.45, 0.6));
  }
}

}  // namespace
}  // namespace rollerdyn::hardcases
