// When a run is hopeless: one rule for both models, fed the same output rows, so that the
// multibody and the reduced model end a run at the same time for the same scene.
//
// A drive from rest either turns, or it cannot turn. It cannot turn in three ways, each read from
// the motion itself rather than from a fixed time:
//  * held: the crank and the motor side both stay within ±1 % of the synchronous crank speed
//    ω0/u for 1 s. Kinetic energy is then nil, so there is nothing to swing with, and the drive
//    sits where the motor's torque (at slip ≈ 1, its starting torque) balances the load: the
//    load at that crank angle is above the motor's torque margin. Why 1 % and 1 s: the smoothed
//    load laws (tanh(v/v_s)) never stop an overloaded drive dead, it creeps at a cart speed of
//    order v_s (1e-3 m/s, a crank speed ~5e-3 rad/s), far inside ±1 % (0.107 rad/s for the
//    papers' drives); a drive with any margin leaves that band within thr·J/ΔM (0.1 s for
//    ΔM = 150 N·m on 150 kg·m²), and a turning or swinging crank only passes through the band at
//    its dead centres or turning points, in a few hundredths of a second. A drive with a small
//    margin on a large inertia (a 10 000 kg·m² flywheel: 1032 N·m against 76 N·m, ~1.1 s to leave
//    the band) is still gaining speed there: a spell in which the crank speed grows by a tenth of
//    the band starts again, so only a crank that stays put is held;
//  * driven backwards: the crank has turned more than one revolution backwards from the furthest
//    forward angle it reached: the load overpowers the motor (whose torque only falls at slip
//    above 1) and turns the machine the wrong way;
//  * rocking without gain: the crank swings back and forth and its swings have stopped growing.
//    A swing is the crank's travel between two reversals. A motor at high slip feeds energy into
//    a swing (the Kloss torque rises with the rotor speed on the unstable branch s > s_kr, so it
//    pushes harder forwards than backwards), the loads and the coupling damper take energy out.
//    While the motor feeds more than the loads take, each swing reaches further than the last one
//    the same way round (its amplitude in crank angle grows), until the crank gets over a dead
//    centre and turns: a rocking-then-starting drive, which is NOT stalled, however long the
//    rocking takes. The balance is read once per oscillation, where a forward swing turns back:
//    it gained when the swing was longer than the last forward one, or when it turned back
//    further forwards than the last one did (by more than kSwingGain of its length: net
//    progress, as of a turning crank that dips backwards at each dead centre). After
//    kSwingsWithoutGain oscillations in a row without gain, the energy balance of an oscillation
//    is nil or negative: the crank has settled into a limit cycle or dies out, and cannot get
//    over the dead centre any more.
// The reported time is when the hopeless state began (the start of the held spell, the furthest
// forward angle, the first of the swings without gain).
#pragma once

#include <cmath>
#include <cstdio>
#include <string>

namespace rollerdyn {

enum class StallKind {
  None,               // the drive turns, or may still start
  Held,               // at rest: the load at this angle is above the motor's torque
  DrivenBackwards,    // the load turns the machine backwards
  RockingWithoutGain  // swings back and forth that no longer grow: it cannot start
};

class StallDetector {
 public:
  static constexpr double kSpeedFraction = 0.01;  // band of "at rest", of ω0/u [-]
  static constexpr double kRestWindow = 1.0;      // time at rest that means held [s]
  static constexpr double kBreakawayGain = 0.1;   // forward speed gain within a spell, of the band,
                                                  // that restarts it (creep under a balanced load
                                                  // stays far below: ~5e-3 rad/s of 0.107) [-]
  static constexpr double kSwingGain = 0.01;      // relative growth of a swing that counts as gain [-]
  static constexpr int kSwingsWithoutGain = 3;    // successive oscillations without gain
  static constexpr double kTwoPi = 6.283185307179586476925286766559;

  // sync_crank_speed = ω0/u [rad/s] (> 0). A scene without a motor never stalls.
  StallDetector(bool motor_enabled, double sync_crank_speed)
      : active_(motor_enabled), threshold_(kSpeedFraction * sync_crank_speed) {}

  // Feed one output row; true once the drive is hopeless (kind() says how). Angle in rad,
  // speeds in rad/s, all at the crank axis.
  bool update(double t, double phi_crank, double omega_crank, double omega_motor) {
    if (!active_ || kind_ != StallKind::None) return kind_ != StallKind::None;
    if (!std::isfinite(phi_crank) || !std::isfinite(omega_crank)) return false;
    if (first_) {
      first_ = false;
      phi_max_ = swing_begin_ = extreme_ = last_forward_turn_ = phi_crank;
      t_max_ = t;
    }
    // Driven backwards.
    if (phi_crank > phi_max_) phi_max_ = phi_crank, t_max_ = t;
    if (phi_max_ - phi_crank > kTwoPi) return stall(StallKind::DrivenBackwards, t_max_);
    if (heldAtRest(t, omega_crank, omega_motor)) return stall(StallKind::Held, rest_since_);
    if (followSwings(t, phi_crank, omega_crank)) return stall(StallKind::RockingWithoutGain, rocking_since_);
    return false;
  }

  StallKind kind() const { return kind_; }
  // Whether the crank has rocked and its last completed oscillation still gained (it may yet get
  // over a dead centre: the start is undecided, not hopeless).
  bool swingsGrowing() const { return kind_ == StallKind::None && last_amplitude_ > 0 && without_gain_ == 0; }
  double since() const { return since_; }  // when the hopeless state began [s], -1 if none

  // The status line both models write; it starts with "motor stalled" (held, driven backwards)
  // or "the crank rocks" (rocking without gain), which motionOfStatus() reads back.
  std::string status() const { return statusOf(kind_, since_); }
  static std::string statusAt(double t) { return statusOf(StallKind::Held, t); }
  static std::string statusOf(StallKind kind, double t) {
    char buf[256];
    switch (kind) {
      case StallKind::DrivenBackwards:
        std::snprintf(buf, sizeof buf,
                      "motor stalled at t = %.4g s: the load turns the crank backwards (more than one "
                      "revolution back from the furthest angle it reached)", t);
        break;
      case StallKind::RockingWithoutGain:
        std::snprintf(buf, sizeof buf,
                      "the crank rocks back and forth from t = %.4g s and its swings no longer grow, so it "
                      "cannot get over a dead centre: run ended early", t);
        break;
      default:
        std::snprintf(buf, sizeof buf, "motor stalled at t = %.4g s", t);
    }
    return buf;
  }
  // "stalled", "rocking" or "" from a run's status line. A soft starter that tripped because the
  // start was still current-limited at its maximum start time (the status line of
  // Supply::tripStatus) is a drive that did not start: "stalled".
  static std::string motionOfStatus(const std::string& status) {
    if (status.rfind("motor stalled", 0) == 0) return "stalled";
    if (status.rfind("the soft starter tripped", 0) == 0) return "stalled";
    if (status.rfind("the crank rocks", 0) == 0) return "rocking";
    return "";
  }

 private:
  bool stall(StallKind k, double since) {
    kind_ = k;
    since_ = since;
    return true;
  }

  // Held at rest: both speeds inside the band for kRestWindow.
  bool heldAtRest(double t, double omega_crank, double omega_motor) {
    if (!(std::abs(omega_crank) <= threshold_ && std::abs(omega_motor) <= threshold_)) {
      rest_since_ = -1.0;
      return false;
    }
    // A crank gaining speed forwards is breaking away, not held: on a large inertia (a heavy
    // flywheel, a large rotor) it may need longer than kRestWindow to leave the band. The spell
    // starts again whenever the speed has grown by kBreakawayGain of the band since it began.
    if (rest_since_ < 0 || omega_crank - omega_rest_start_ > kBreakawayGain * threshold_)
      rest_since_ = t, omega_rest_start_ = omega_crank;
    return t - rest_since_ >= kRestWindow;
  }

  // Swings: the direction changes only when the speed leaves the band on the other side. True once
  // kSwingsWithoutGain successive oscillations did not gain.
  bool followSwings(double t, double phi_crank, double omega_crank) {
    const int dir = omega_crank > threshold_ ? 1 : omega_crank < -threshold_ ? -1 : direction_;
    if (direction_ > 0 && dir < 0 && oscillationWithoutGain(t)) return true;
    if (direction_ != 0 && dir != direction_) {  // any reversal starts a new swing
      swing_begin_ = extreme_;
      extreme_ = phi_crank;
    }
    if (dir > 0) extreme_ = std::max(extreme_, phi_crank);
    if (dir < 0) extreme_ = std::min(extreme_, phi_crank);
    if (dir == 0) extreme_ = phi_crank;
    direction_ = dir;
    return false;
  }

  // A forward swing turned back at extreme_: one oscillation, gaining or not. True once
  // kSwingsWithoutGain in a row did not gain.
  bool oscillationWithoutGain(double t) {
    const double amplitude = extreme_ - swing_begin_;
    const bool gain = !(last_amplitude_ > 0) || amplitude > last_amplitude_ * (1.0 + kSwingGain) ||
                      extreme_ - last_forward_turn_ > kSwingGain * amplitude;
    if (gain) {
      without_gain_ = 0;
    } else if (without_gain_++ == 0) {
      rocking_since_ = t;
    }
    last_amplitude_ = amplitude;
    last_forward_turn_ = extreme_;
    return without_gain_ >= kSwingsWithoutGain;
  }

  bool active_;
  double threshold_;
  bool first_ = true;
  StallKind kind_ = StallKind::None;
  double since_ = -1.0;
  double phi_max_ = 0, t_max_ = 0;   // furthest forward angle and when [rad], [s]
  double rest_since_ = -1.0;         // start of the current spell at rest [s]
  double omega_rest_start_ = 0;      // crank speed when that spell began [rad/s]
  int direction_ = 0;                // +1 forwards, -1 backwards, 0 not yet moved
  double swing_begin_ = 0, extreme_ = 0;  // the current swing's start and furthest angle [rad]
  double last_forward_turn_ = 0;     // where the last forward swing turned back [rad]
  double last_amplitude_ = -1;       // extent of the last forward swing [rad]
  int without_gain_ = 0;
  double rocking_since_ = -1.0;
};

}  // namespace rollerdyn
