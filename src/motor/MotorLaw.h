// The interface every induction-motor law implements, so that both models (reduced and
// multibody, each formulation) and every analysis call the same law per motor.model, and the
// starting method (motor.start / motor.stop) is kept apart from the machine it supplies.
//
// A law maps (supply at this instant, rotor speed, its own states) to the electromagnetic
// torque at the rotor and the time derivatives of its states. Static laws (Kloss, the
// equivalent circuit) have no states; the dynamic Kloss characteristic has one (the torque);
// the space-phasor (Park) machine has the stator and rotor flux linkages (4, or 6 with a double
// cage) in a frame that turns with the supply voltage, so that a steady run has constant states.
//
// Torque and speed are at the ROTOR here (N·m, rad/s); the models reduce them to the crank axis
// (×u·η, ÷u) themselves. Positive torque drives the rotor forwards; at negative slip the law
// returns generator (negative) torque.
#pragma once

#include <limits>
#include <string>
#include <vector>

namespace rollerdyn {

// What the starting method applies to the stator terminals at one instant, relative to the
// motor's rated supply. One struct for every law: the static laws scale with it (torque ∝ U²,
// ω0 ∝ f, s_kr ∝ f_n/f), the space-phasor model builds its terminal voltage from it.
struct SupplyState {
  bool connected = true;   // stator connected to the supply; false: switched off (no torque
                           // from the static laws; the Park model's stator current is zero)
  double voltage = 1.0;    // U/U_n: fundamental phase voltage over the rated phase voltage [-]
                           // (a delta-rated motor started in star: 1/√3)
  double frequency = 1.0;  // f/f_n: supply frequency over the rated frequency [-] (> 0)
  double phase = 0.0;      // angle of the voltage space phasor in the frame that turns with the
                           // supply [rad]: the point on the wave at switch-on; it jumps by π/6
                           // at a star-delta changeover
  double line_current_factor = 1.0;  // line current over the equivalent star's phase current [-]:
                           // 1/√3 for a delta-rated motor's windings connected in star. The laws
                           // model the delta machine as its equivalent star under U/√3, which gives
                           // the star's torque (1/3) but 1/√3 of the line current; the star's real
                           // line current, its winding current, is 1/3 of direct on line.
};

// What a law computes at one instant. NaN where a law has no such quantity (Kloss has no
// current).
struct MotorEvaluation {
  static constexpr double kNotModelled = std::numeric_limits<double>::quiet_NaN();
  double torque = 0;                          // electromagnetic torque on the rotor M [N·m]
  double stator_current = kNotModelled;       // RMS stator phase current, |i_s|/√2 [A]
  double electrical_power = kNotModelled;     // power drawn from the supply [W]
  double copper_loss = kNotModelled;          // stator + rotor copper losses [W]
  double magnetic_energy = kNotModelled;      // energy stored in the machine's inductances [J]
};

class MotorLaw {
 public:
  virtual ~MotorLaw() = default;

  // What the user reads, e.g. "Kloss formula (static)", "equivalent circuit, double cage".
  virtual std::string description() const = 0;
  // Rated synchronous rotor speed ω0 [rad/s].
  virtual double synchronousSpeed() const = 0;

  // Number of states the law integrates (0 for static laws); their names with units, as CSV
  // column names ("psi_sd[Wb]"), and a natural magnitude of each for the integrators' absolute
  // tolerances.
  virtual int stateCount() const { return 0; }
  virtual std::vector<std::string> stateNames() const { return {}; }
  virtual std::vector<double> stateScales() const { return {}; }
  // Shortest time constant of the law's own dynamics [s] (infinity for static laws): tells the
  // run whether it needs a stiff integrator.
  virtual double fastestTimeConstant() const { return std::numeric_limits<double>::infinity(); }

  // States at the start of a run: `steady` false: the machine de-energised (every flux and the
  // dynamic torque zero); true: in steady state at this rotor speed under `supply`. x has
  // stateCount() entries.
  virtual void initialState(const SupplyState& supply, double omega_rotor, bool steady,
                            double* x) const {}
  // Torque (and the other outputs) at time-local supply, rotor speed ω_r [rad/s] and states x;
  // writes stateCount() derivatives to xdot (xdot may be null for static laws).
  virtual void evaluate(const SupplyState& supply, double omega_rotor, const double* x,
                        MotorEvaluation& out, double* xdot) const = 0;
  // Maps the states across a switching event (switch-off, a star-delta changeover, a phase
  // jump), where they are not continuous (e.g. stator current forced to zero by a breaker).
  virtual void switchStates(const SupplyState& before, const SupplyState& after,
                            double omega_rotor, double* x) const {}

  // The law's quasi-static torque at the rotor for a steady supply and speed [N·m]: the
  // torque-speed curve (starting torque at ω_r = 0, plots, start checks).
  virtual double steadyTorque(const SupplyState& supply, double omega_rotor) const = 0;
  // Its RMS stator phase current in steady state [A]; NaN when the law has no current.
  virtual double steadyCurrent(const SupplyState& supply, double omega_rotor) const {
    return MotorEvaluation::kNotModelled;
  }
};

}  // namespace rollerdyn
