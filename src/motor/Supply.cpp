#include "motor/Supply.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "scene/MotorModels.h"
#include "scene/Scene.h"

namespace rollerdyn {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
using Stage = SupplyPhase::Stage;

// An event timed at te is due at t when te <= t up to round-off of the time itself.
bool due(double te, double t) { return te <= t + 1e-12 * std::max(1.0, std::abs(t)); }

// The supply s after a star-delta changeover (start.method star_delta): the delta phase voltage
// leads the star's by π/6.
SupplyState inDelta(const MotorStart& start, SupplyState s) {
  if (start.method == StartMethod::StarDelta) s.phase += M_PI / 6.0;
  return s;
}

// The supply s with the breaker open.
SupplyState disconnected(SupplyState s) {
  s.connected = false;
  s.voltage = 0.0;
  return s;
}

bool sameSupply(const SupplyState& a, const SupplyState& b) {
  return a.connected == b.connected && a.voltage == b.voltage && a.frequency == b.frequency && a.phase == b.phase;
}

}  // namespace

const char* toString(SupplyPhase::Stage s) {
  switch (s) {
    case Stage::Waiting: return "waiting";
    case Stage::Star: return "star";
    case Stage::Gap: return "open transition";
    case Stage::Ramp: return "ramp";
    case Stage::Rated: return "rated";
    case Stage::Off: return "off";
    case Stage::Braking: return "braking";
    case Stage::Restarted: return "restarted";
    case Stage::Limited: return "current-limited";
    case Stage::Tripped: return "tripped";
  }
  return "?";
}

Supply::Supply() = default;

Supply::Supply(const MotorStart& start, const MotorStop& stop, double omega_sync, double rated_frequency,
               double brake_smoothing_speed, const MotorLaw* law)
    : start_(start), stop_(stop), omega_sync_(omega_sync), rated_frequency_(rated_frequency),
      brake_speed_(brake_smoothing_speed), law_(law) {
  if (!(omega_sync > 0)) throw std::invalid_argument("Supply: the synchronous speed must be > 0");
  if (stop.brake_torque > 0 && !(brake_smoothing_speed > 0))
    throw std::invalid_argument("Supply: the brake smoothing speed must be > 0");
  checkStartMethod();
  if (start_.method == StartMethod::SoftStarter && start_.current_limit > 0) setUpCurrentLimit();
  constant_ = start_.method == StartMethod::DirectOnLine && start_.t_on <= 0 && std::isinf(stop_.t_off);
}

void Supply::checkStartMethod() const {
  if (start_.method == StartMethod::FrequencyConverter) {
    if (!(rated_frequency_ > 0)) throw std::invalid_argument("Supply: the rated frequency must be > 0");
    if (!(start_.initial_frequency > 0 && start_.initial_frequency < rated_frequency_))
      throw std::invalid_argument("motor.start.initial_frequency must lie in (0, f_n = " +
                                  std::to_string(rated_frequency_) + " Hz), got " +
                                  std::to_string(start_.initial_frequency));
  }
  if ((start_.method == StartMethod::SoftStarter || start_.method == StartMethod::FrequencyConverter) &&
      !(start_.ramp_time > 0))
    throw std::invalid_argument("Supply: a ramped start needs motor.start.ramp_time > 0");
  if (start_.method == StartMethod::StarDelta && std::isnan(start_.changeover_time) &&
      std::isnan(start_.changeover_speed))
    throw std::invalid_argument("Supply: a star-delta start needs a changeover time or speed");
}

void Supply::setUpCurrentLimit() {
  const bool has_current = law_ && std::isfinite(law_->steadyCurrent(SupplyState{}, 0.0));
  if (!has_current)
    throw std::invalid_argument(
        "motor.start.current_limit needs a motor model with a stator current (motor.model " +
        motorModelWords(false, "or") + "); the Kloss laws have none");
  limit_speed_ = findLimitSpeed();
  if (start_.max_start_time > 0 && !(start_.max_start_time > start_.ramp_time))
    throw std::invalid_argument("motor.start.max_start_time must exceed motor.start.ramp_time");
}

SupplyPhase Supply::initialPhase() const {
  SupplyPhase p;
  applyDueEvents(p, 0.0, 0.0, false, nullptr, nullptr);
  return p;
}

SupplyState Supply::state(const SupplyPhase& p, double t, double omega_rotor) const {
  SupplyState s;
  s.phase = start_.phase;
  switch (p.stage) {
    case Stage::Waiting:
    case Stage::Gap: return disconnected(s);
    case Stage::Off:
    case Stage::Braking:
    case Stage::Tripped: return disconnected(inDelta(start_, s));
    case Stage::Star:
      s.voltage = 1.0 / std::sqrt(3.0);
      s.line_current_factor = 1.0 / std::sqrt(3.0);
      return s;
    case Stage::Rated:
    case Stage::Restarted: return inDelta(start_, s);
    case Stage::Ramp: return ramped(s, t, omega_rotor);
    case Stage::Limited:
      s.voltage = std::min(1.0, limitedVoltage(omega_rotor));
      return s;
  }
  return s;
}

SupplyState Supply::ramped(SupplyState s, double t, double omega_rotor) const {
  const double x = std::clamp((t - start_.t_on) / start_.ramp_time, 0.0, 1.0);
  if (start_.method == StartMethod::FrequencyConverter) {
    const double F0 = start_.initial_frequency / rated_frequency_;
    s.frequency = F0 + (1.0 - F0) * x;
    s.voltage = start_.boost + (1.0 - start_.boost) * s.frequency;
    return s;
  }
  s.voltage = std::min(start_.initial_voltage + (1.0 - start_.initial_voltage) * x, limitedVoltage(omega_rotor));
  return s;
}

double Supply::limitedVoltage(double omega_rotor) const {
  if (!(start_.current_limit > 0) || !law_) return kInf;
  SupplyState rated;
  rated.phase = start_.phase;
  const double I_rated_voltage = law_->steadyCurrent(rated, omega_rotor);
  return I_rated_voltage > 0 && std::isfinite(I_rated_voltage) ? start_.current_limit / I_rated_voltage : kInf;
}

double Supply::findLimitSpeed() const {
  // The highest speed in [0, ω0] at which I_1 still exceeds the limit, bracketed by the scan.
  constexpr int kScan = 400;
  auto above = [this](double w) { return limitedVoltage(w) < 1.0; };  // I_1(ω) > I_lim
  int last_above = -1;
  for (int i = 0; i <= kScan; ++i)
    if (above(omega_sync_ * i / kScan)) last_above = i;
  if (last_above < 0) return 0.0;
  if (last_above == kScan) {
    SupplyState rated;
    char buf[320];
    std::snprintf(buf, sizeof buf,
                  "motor.start.current_limit = %g A is at or below the motor's no-load current %.4g A at the rated "
                  "voltage (its stator current at the synchronous speed): the soft starter could never close its "
                  "bypass; give a limit above it (typically 2 ... 4 times the rated current)",
                  start_.current_limit, law_->steadyCurrent(rated, omega_sync_));
    throw std::invalid_argument(buf);
  }
  double lo = omega_sync_ * last_above / kScan, hi = omega_sync_ * (last_above + 1) / kScan;
  for (int it = 0; it < 200 && hi - lo > 1e-14 * omega_sync_; ++it) {
    const double mid = 0.5 * (lo + hi);
    (above(mid) ? lo : hi) = mid;
  }
  return hi;  // I_1(hi) ≤ I_lim: the voltage is U_n there
}

double Supply::tripTime() const {
  const bool limited = start_.method == StartMethod::SoftStarter && start_.current_limit > 0;
  return limited && start_.max_start_time > 0 ? start_.t_on + start_.max_start_time : kInf;
}

std::string Supply::tripStatus(double t) const {
  char buf[512];
  std::snprintf(buf, sizeof buf,
                "%s at t = %.4g s: the motor had not reached the rotor speed %.4g rad/s, from which it draws no more "
                "than motor.start.current_limit = %g A at the rated voltage, within motor.start.max_start_time = %g s "
                "of the switch-on; the starter disconnected it (a failed start)",
                kTripStatus, t, limit_speed_, start_.current_limit, start_.max_start_time);
  return buf;
}

double Supply::brakeTorque(const SupplyPhase& p, double omega_rotor) const {
  if (p.stage != Stage::Braking) return 0.0;
  return -stop_.brake_torque * std::tanh(omega_rotor / brake_speed_);
}

double Supply::nextEventTime(const SupplyPhase& p) const {
  const double t_off = stop_.t_off;
  switch (p.stage) {
    case Stage::Waiting: return start_.t_on;
    case Stage::Star: return std::min(std::isnan(start_.changeover_time) ? kInf : start_.changeover_time, t_off);
    case Stage::Gap: return std::min(p.since + start_.changeover_gap, t_off);
    case Stage::Ramp: return std::min(start_.t_on + start_.ramp_time, t_off);
    case Stage::Rated: return t_off;
    case Stage::Off: return hasBrake() ? t_off + stop_.brake_delay : stop_.t_restart;
    case Stage::Braking: return stop_.t_restart;
    case Stage::Restarted: return kInf;
    case Stage::Limited: return std::min(tripTime(), t_off);
    case Stage::Tripped: return kInf;
  }
  return kInf;
}

double Supply::triggerSpeed(const SupplyPhase& p) const {
  if (p.stage == Stage::Star) return start_.changeover_speed;
  if (p.stage == Stage::Limited) return limit_speed_;
  return kNaN;
}

SupplyPhase Supply::after(const SupplyPhase& p, double t, double omega_rotor, bool by_speed) const {
  auto to = [t](Stage s) { return SupplyPhase{s, t}; };
  // A switch-off due at the same time ends the stage in off, whatever it would have led to.
  auto unless_off = [&](Stage s) { return due(stop_.t_off, t) ? to(Stage::Off) : to(s); };
  const Stage delta = start_.changeover_gap > 0 ? Stage::Gap : Stage::Rated;
  switch (p.stage) {
    case Stage::Waiting: return to(switchOnStage());
    case Stage::Star: return by_speed ? to(delta) : unless_off(delta);
    case Stage::Gap: return unless_off(Stage::Rated);
    case Stage::Ramp:
      // The ramp has reached U_n; a motor that would still draw more than the limit there stays
      // current-limited (a real soft starter closes its bypass only once the motor is up to speed).
      return unless_off(omega_rotor < limit_speed_ ? Stage::Limited : Stage::Rated);
    case Stage::Limited: return by_speed ? to(Stage::Rated) : unless_off(Stage::Tripped);
    case Stage::Tripped: return p;
    case Stage::Rated: return to(Stage::Off);
    case Stage::Off: return hasBrake() && !due(stop_.t_restart, t) ? to(Stage::Braking) : to(Stage::Restarted);
    case Stage::Braking: return to(Stage::Restarted);
    case Stage::Restarted: return p;
  }
  return p;
}

SupplyPhase::Stage Supply::switchOnStage() const {
  switch (start_.method) {
    case StartMethod::DirectOnLine: return Stage::Rated;
    case StartMethod::StarDelta: return Stage::Star;
    default: return Stage::Ramp;
  }
}

bool Supply::applyDueEvents(SupplyPhase& p, double t, double omega_rotor, bool speed_reached, const MotorLaw* law,
                            double* x) const {
  bool changed = false;
  for (int guard = 0; guard < 16; ++guard) {
    const double w_trigger = triggerSpeed(p);
    const bool by_speed = !std::isnan(w_trigger) && (speed_reached || omega_rotor >= w_trigger);
    if (!by_speed && !due(nextEventTime(p), t)) return changed;
    const SupplyState before = state(p, t, omega_rotor);
    const SupplyPhase next = after(p, t, omega_rotor, by_speed);
    if (next == p) return changed;
    p = next;
    changed = true;
    speed_reached = false;  // the speed event happens once
    const SupplyState now = state(p, t, omega_rotor);
    if (law && law->stateCount() > 0 && !sameSupply(before, now)) law->switchStates(before, now, omega_rotor, x);
  }
  throw std::logic_error("Supply: events at one instant do not settle");
}

double Supply::ratedFrom() const {
  switch (start_.method) {
    case StartMethod::DirectOnLine: return start_.t_on;
    case StartMethod::StarDelta:
      return std::isnan(start_.changeover_time) ? kNaN : start_.changeover_time + start_.changeover_gap;
    default:
      return limit_speed_ > 0 ? kNaN : start_.t_on + start_.ramp_time;  // limited: until up to speed
  }
}

SupplyState Supply::atSwitchOn() const {
  const SupplyPhase p = after(SupplyPhase{}, start_.t_on, 0.0, false);
  return state(p, start_.t_on, 0.0);
}

Supply makeSupply(const Scene& scene, const MotorLaw* law) {
  const double r = scene.hasCamDrive() ? 0.5 * scene.cam.stroke : scene.crank.radius;
  const double brake_speed = scene.reducer.ratio * scene.loads.velocity_smoothing / r;
  return Supply(scene.motor_start, scene.motor_stop, scene.motor.omega_sync, scene.induction.frequency, brake_speed,
                law);
}

bool motorSteadyAtStart(const Scene& scene, const Supply& supply) {
  return supply.state(supply.initialPhase(), 0.0, 0.0).connected && scene.initial.crank_speed != 0.0;
}

}  // namespace rollerdyn
