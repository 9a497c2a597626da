// When a run counts as "motor stalled": one rule for both models, so that the multibody and the
// reduced model report the same stall time for the same scene.
//
// The drive has stalled when the crank OR the motor side has stayed at or below 1 % of the
// synchronous crank speed ω0/u (slip above 0.99, or running backwards) for 1 s of simulated
// time; the reported time is when that spell began. Why these numbers:
//  * the smoothed load laws (tanh(v/v_s)) never stop an overloaded drive dead: it creeps at a
//    cart speed of order v_s, so "speed <= 0" alone would never fire; 1 % of synchronous speed
//    is far below any running state and far above that creep;
//  * a start from rest passes 1 % within a few hundredths of a second with any motor that can
//    carry its load (Loveikin, Pochka, Romasevych (2018): starting torque ≈ 1 kN·m at the crank on ≈ 150 kg·m²), so no
//    grace period is needed and a drive that never starts is reported as stalled at t = 0;
//  * 1 s is longer than any dead-centre slow-down of a running drive (a crank revolution of the
//    papers' machines takes ~0.6 s) and short enough to stop a hopeless run early.
#pragma once

#include <cstdio>
#include <string>

namespace rollerdyn {

class StallDetector {
 public:
  static constexpr double kSpeedFraction = 0.01;  // of ω0/u [-]
  static constexpr double kWindow = 1.0;          // sustained time below the threshold [s]

  // sync_crank_speed = ω0/u [rad/s] (> 0). A scene without a motor never stalls.
  StallDetector(bool motor_enabled, double sync_crank_speed)
      : active_(motor_enabled), threshold_(kSpeedFraction * sync_crank_speed) {}

  // Feed one output row; true once the drive has stalled. Speeds in rad/s at the crank axis.
  bool update(double t, double omega_crank, double omega_motor) {
    if (!active_) return false;
    if (omega_crank > threshold_ && omega_motor > threshold_) {
      since_ = -1.0;
      return false;
    }
    if (since_ < 0.0) since_ = t;
    return t - since_ >= kWindow;
  }

  double since() const { return since_; }  // start of the current slow spell [s], -1 if none

  // The status line both models write, e.g. "motor stalled at t = 0.25 s".
  std::string status() const { return statusAt(since_); }
  static std::string statusAt(double t) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "motor stalled at t = %.4g s", t);
    return buf;
  }

 private:
  bool active_;
  double threshold_;
  double since_ = -1.0;
};

}  // namespace rollerdyn
