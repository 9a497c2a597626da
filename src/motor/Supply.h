// What the starting equipment applies to the motor over time: the supply at the stator
// terminals (SupplyState, MotorLaw.h) and the mechanical brake on the shaft, from the scene's
// motor.start / motor.stop settings (scene/MotorSwitching.h) and the events latched so far.
//
// A run moves through stages, each with its own smooth supply law:
//   waiting (before t_on: disconnected) -> star (star-delta) | ramp (soft starter, frequency
//   converter) | rated -> [gap: star-delta open transition] -> rated -> off (after t_off)
//   -> braking (off, brake engaged) -> restarted (rated again, after t_restart);
//   a current-limited soft start: ramp -> [limited] -> rated (the bypass) | tripped.
// The stage and the time it began form a SupplyPhase, which the run keeps (the reduced model in
// its loop, the multibody model in the State): the supply inside one stage is a smooth function
// of time (and of the rotor speed under a current limit), so an integrator never steps across a
// jump. Each run stops its integrator at every event, i.e. at nextEventTime() or where the rotor
// speed reaches triggerSpeed() (the speed-triggered star-delta changeover, found by root
// finding), applies the event with applyDueEvents() (which maps the motor law's states through
// MotorLaw::switchStates) and restarts the integrator.
//
// The supply laws inside the stages (U and f relative to the rated U_n, f_n):
//   star        U = 1/√3 (a delta-rated motor with its windings in star), f = 1, phase φ0
//   delta/rated U = 1, f = 1, phase φ0 + π/6 after a star-delta changeover (the delta phase
//               voltage is the line voltage, which leads the star phase voltage by 30°), else φ0
//   soft start  U = U_0 + (1 - U_0)·(t - t_on)/t_ramp, f = 1; with a current limit I_lim
//               U = min(U_ramp, I_lim/I_1(ω_r)), I_1 the law's quasi-static stator current at
//               U_n, f_n and the present rotor speed (the equivalent circuit is linear, so the
//               current scales with U): the starter's current control taken as ideal and
//               quasi-static (a dynamic law can overshoot I_lim in its transients)
//   limited     after the ramp, while the motor would draw more than I_lim at U_n:
//               U = min(1, I_lim/I_1(ω_r)). It ends where the rotor speed reaches ω_lim, the
//               speed from which I_1 ≤ I_lim (limitSpeed(); U reaches 1 there continuously) and
//               the bypass closes (rated), an event located like the star-delta changeover by
//               speed; or, still limited at t_on + motor.start.max_start_time, the starter trips
//               (tripped: disconnected for the rest of the run, a failed start)
//   converter   f = F(t) = f_0/f_n + (1 - f_0/f_n)·(t - t_on)/t_ramp, U = boost + (1 - boost)·F
//   brake       M_b·tanh(ω_r/ω_b) against the rotation, M_b = motor.stop.brake_torque, from
//               t_off + brake_delay until a restart; ω_b the rotor speed at which the carts move at
//               the load laws' smoothing speed v_s (a sign law smoothed like the roller forces)
#pragma once

#include <limits>
#include <string>

#include "motor/MotorLaw.h"
#include "scene/MotorSwitching.h"

namespace rollerdyn {

struct SupplyPhase {
  enum class Stage { Waiting, Star, Gap, Ramp, Rated, Off, Braking, Restarted, Limited, Tripped };
  Stage stage = Stage::Waiting;
  double since = 0;  // time the stage began [s]
  bool operator==(const SupplyPhase& o) const { return stage == o.stage && since == o.since; }
};

const char* toString(SupplyPhase::Stage stage);

class Supply {
 public:
  // start/stop: the scene's settings; omega_sync: rated synchronous rotor speed ω0 [rad/s];
  // rated_frequency: f_n [Hz] (turns motor.start.initial_frequency into f_0/f_n);
  // brake_smoothing_speed: ω_b [rad/s at the rotor] (> 0); law: the motor law the supply feeds,
  // needed only for a current limit (std::invalid_argument when the law models no current).
  Supply(const MotorStart& start, const MotorStop& stop, double omega_sync, double rated_frequency,
         double brake_smoothing_speed, const MotorLaw* law = nullptr);
  // The constant rated supply, connected all the time (the scenes without motor.start/stop).
  Supply();

  // True when nothing ever switches: direct on line at t = 0 and never off. Such a run needs no
  // events and its tables no supply columns.
  bool constant() const { return constant_; }
  bool hasBrake() const { return stop_.brake_torque > 0; }

  // True in the stages where the motor gets its rated supply (rated, restarted): where a slow
  // drive counts as stalled (a star or a ramp stage may legitimately be slow).
  static bool fullSupply(const SupplyPhase& p) {
    return p.stage == SupplyPhase::Stage::Rated || p.stage == SupplyPhase::Stage::Restarted;
  }

  // The phase at t = 0 (events due at t = 0 applied: a switch-on at t_on = 0).
  SupplyPhase initialPhase() const;

  // The supply in phase p at time t and rotor speed ω_r [rad/s].
  SupplyState state(const SupplyPhase& p, double t, double omega_rotor) const;
  // Brake torque on the rotor in phase p [N·m], signed against ω_r (0 unless braking).
  double brakeTorque(const SupplyPhase& p, double omega_rotor) const;

  // The next time-triggered event after phase p began [s] (infinity when none): switch-on,
  // changeover, end of a ramp or of the open transition, switch-off, brake engaging, restart.
  double nextEventTime(const SupplyPhase& p) const;
  // The rotor speed [rad/s] whose upward crossing is the next event (the star-delta changeover
  // by speed, the soft starter's bypass after a current-limited stage); NaN when phase p has none.
  double triggerSpeed(const SupplyPhase& p) const;

  // Soft starter with a current limit: ω_lim, the rotor speed from which the law's steady
  // stator current at the rated supply stays within the limit (I_1(ω_r) ≤ I_lim for
  // ω_lim ≤ ω_r ≤ ω0), found by a scan of 400 speeds refined by bisection [rad/s]; NaN without a
  // limit. 0 when even the standstill current is within it (the limit never acts at U_n).
  double limitSpeed() const { return limit_speed_; }
  // The time at which a start still current-limited trips the starter [s] (t_on +
  // max_start_time); infinity when it never trips (no limit, or max_start_time = 0).
  double tripTime() const;
  // The run's status line at a trip at time t: begins with kTripStatus (the stall rule's
  // motionOfStatus reads a trip as a drive that did not start), then why.
  static constexpr const char* kTripStatus = "the soft starter tripped";
  std::string tripStatus(double t) const;
  static bool tripped(const SupplyPhase& p) { return p.stage == SupplyPhase::Stage::Tripped; }

  // Applies every event due at time t in phase p: those timed at or before t (to round-off), and,
  // when `speed_reached` or ω_r >= triggerSpeed(p), the speed-triggered one. For each event the
  // law's states x (law->stateCount() values; law may be null when it has none) are mapped by
  // MotorLaw::switchStates. Returns whether the phase changed.
  bool applyDueEvents(SupplyPhase& p, double t, double omega_rotor, bool speed_reached, const MotorLaw* law,
                      double* x) const;

  // The time at which the supply first reaches its rated state (U = U_n, f = f_n, connected) in
  // a plain start: t_on for direct on line, t_on + t_ramp for the ramps, the changeover (+ gap)
  // for a timed star-delta; NaN for a speed-triggered changeover and for a current-limited soft
  // start (known only in the run).
  double ratedFrom() const;
  // The supply the start begins with (at t_on, rotor at rest): the star voltage, U_0, f_0 ...
  SupplyState atSwitchOn() const;

  const MotorStart& start() const { return start_; }
  const MotorStop& stop() const { return stop_; }

 private:
  // The start settings each method needs (constructor; std::invalid_argument when one is missing
  // or out of range).
  void checkStartMethod() const;
  // A soft starter's current limit: ω_lim, after checking that the law models a stator current
  // and that max_start_time, when given, exceeds the ramp (constructor; std::invalid_argument).
  void setUpCurrentLimit();
  // The phase that follows p by the event at time t and rotor speed ω_r (one event).
  SupplyPhase after(const SupplyPhase& p, double t, double omega_rotor, bool by_speed) const;
  // The stage the switch-on leads to: rated (direct on line), star or ramp.
  SupplyPhase::Stage switchOnStage() const;
  // s in the ramp stage at time t: U and f of the soft starter (current-limited at ω_r) or the
  // frequency converter.
  SupplyState ramped(SupplyState s, double t, double omega_rotor) const;
  // U/U_n the current limit allows at rotor speed ω_r (≥ 1 when it does not act; +inf without a limit).
  double limitedVoltage(double omega_rotor) const;
  // ω_lim for the limit (constructor; std::invalid_argument when the limit is at or below the
  // no-load current, so that the bypass could never close).
  double findLimitSpeed() const;

  MotorStart start_;
  MotorStop stop_;
  double omega_sync_ = 1, rated_frequency_ = 50, brake_speed_ = 1;
  const MotorLaw* law_ = nullptr;
  bool constant_ = true;
  double limit_speed_ = std::numeric_limits<double>::quiet_NaN();
};

struct Scene;

// The supply of a scene's motor.start / motor.stop settings, for both models: ω0 from the motor,
// f_n the motor's rated frequency, ω_b = u·v_s/r (the rotor speed at which the crank moves the
// carts at the load laws' smoothing speed v_s; cam drive: r = stroke/2).
Supply makeSupply(const Scene& scene, const MotorLaw* law);

// The scene's motor is energised at t = 0 in steady state: connected at t = 0 while the machine
// already turns (initial.crank_speed != 0), i.e. it was running before; otherwise its electrical
// states start from zero (a start from rest, or a switch-on later).
bool motorSteadyAtStart(const Scene& scene, const Supply& supply);

}  // namespace rollerdyn
