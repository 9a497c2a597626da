// When a run without a drive has come to rest: one rule for both models (like the stall rule of
// StallDetector.h for a driven machine), so that a machine that friction and loads have stopped
// ends its run with that status instead of creeping on.
//
// With the motor off (and the crank speed not prescribed) the machine has come to rest when every
// cart has stayed slower than the friction law's smoothing speed v_s (loads.velocity_smoothing)
// for 1 s of simulated time; the reported time is when that spell began. Why:
//  * the smoothed sign tanh(v/v_s) of the friction and load laws (physics/RollerLoads.h) has no
//    sticking: a machine that real friction holds creeps on at cart speeds far below v_s, a
//    drift of the law, not a motion (e.g. balanced-4cart with f = 0.3: 1e-5 m/s against
//    v_s = 1 mm/s), and its equations are stiff there;
//  * every cart at once below v_s happens in a moving machine only where the crank nearly
//    stops; a crank passing a dead centre slowly leaves the band within a fraction of a second,
//    so the 1 s of the stall rule separates the two as well.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace rollerdyn {

class RestDetector {
 public:
  static constexpr double kWindow = 1.0;  // sustained time below v_s [s]

  // applies: no motor and no prescribed crank speed; v_s [m/s] > 0.
  RestDetector(bool applies, double v_s) : active_(applies), v_s_(v_s) {}

  // Feed one output row: the carts' speeds [m/s]. True once the machine has come to rest.
  template <class Speeds>
  bool update(double t, const Speeds& cart_speeds, int n) {
    if (!active_) return false;
    double fastest = 0.0;
    for (int j = 0; j < n; ++j) fastest = std::max(fastest, std::abs(double(cart_speeds[j])));
    if (!(fastest <= v_s_)) {
      since_ = -1.0;
      return false;
    }
    if (since_ < 0.0) since_ = t;
    return t - since_ >= kWindow;
  }

  // The status line both models write; it starts with "the machine came to rest", which
  // motionOfStatus() reads back.
  std::string status() const {
    char buf[400];
    std::snprintf(buf, sizeof buf,
                  "the machine came to rest at t = %.4g s: with the motor off, friction and loads hold it (every "
                  "cart slower than the friction law's smoothing speed v_s = %.3g m/s for %.0f s, where the "
                  "smoothed law only lets it creep)",
                  since_, v_s_, kWindow);
    return buf;
  }
  // "at_rest" or "" from a run's status line.
  static std::string motionOfStatus(const std::string& status) {
    return status.rfind("the machine came to rest", 0) == 0 ? "at_rest" : "";
  }

 private:
  bool active_;
  double v_s_;
  double since_ = -1.0;
};

}  // namespace rollerdyn
