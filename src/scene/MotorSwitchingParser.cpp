#include "scene/MotorSwitchingParser.h"

#include <cmath>

#include "scene/MotorModels.h"

namespace rollerdyn {

namespace {

constexpr double kDegToRad = M_PI / 180.0;

// "a number > t_on = 0.5 [s] (motor.start.t_on)": a bound taken from another key.
std::string laterThan(const char* what, double bound, const char* key) {
  return std::string("a number > ") + what + " = " + formatNumber(bound) + " [s] (" + key + ")";
}

// A time key that must come after an earlier event: blames whichever of the two a --set changed
// last, like the other cross-key rules.
void requireLater(const scene_detail::Reader& in, const std::string& later_key, double later, const std::string& earlier_key,
                  double earlier, const char* earlier_name, const char* later_name) {
  if (later > earlier) return;
  if (scene_detail::blameSecond(in.doc(), later_key, earlier_key))
    in.doc().fail(earlier_key,
                  std::string("a number < ") + later_name + " = " + formatNumber(later) + " [s] (" + later_key + ")",
                  formatNumber(earlier));
  in.doc().fail(later_key, laterThan(earlier_name, earlier, earlier_key.c_str()), formatNumber(later));
}

void readStarDelta(const scene_detail::Reader& in, MotorStart& m, double omega_sync) {
  const SceneDocument& doc = in.doc();
  const bool by_time = in.has("motor.start.changeover_time"), by_speed = in.has("motor.start.changeover_speed");
  const std::string ways = "exactly one of motor.start.changeover_time or motor.start.changeover_speed";
  if (by_time && by_speed) {
    const bool speed_last = scene_detail::blameSecond(doc, "motor.start.changeover_time", "motor.start.changeover_speed");
    const std::string blamed = speed_last ? "motor.start.changeover_speed" : "motor.start.changeover_time";
    const std::string other = speed_last ? "motor.start.changeover_time" : "motor.start.changeover_speed";
    doc.fail(blamed, ways + " (" + other + " is given too)", describeNode(doc.find(blamed)));
  }
  if (by_time) m.changeover_time = in.number("motor.start.changeover_time");
  if (by_speed) m.changeover_speed = in.number("motor.start.changeover_speed");
  if (m.method != StartMethod::StarDelta) return;  // validated, not used
  if (!by_time && !by_speed) doc.failMissing("motor.start.changeover_time", ways + " (motor.start.method is star_delta)");
  if (by_time)
    requireLater(in, "motor.start.changeover_time", m.changeover_time, "motor.start.t_on", m.t_on, "t_on",
                 "changeover_time");
  if (by_speed && !(m.changeover_speed < omega_sync))
    doc.fail("motor.start.changeover_speed",
             "a rotor speed in (0, omega_sync = " + formatNumber(omega_sync) + ") [rad/s] (motor.omega_sync)",
             formatNumber(m.changeover_speed));
}

// A key the scene gives that the run would not use: an error naming the key, the key that makes it
// idle and why; but a warning (Scene::ignored_keys) when that deciding key was changed by a later
// --set than the one that gave the key, i.e. the user switched, say, the method of a scene written
// for another one on the command line (docs/startup.md).
void idleKey(const scene_detail::Reader& in, Scene& scene, const std::string& key, const std::string& decider,
             const std::string& decided, const std::string& why) {
  if (!in.has(key)) return;
  const SceneDocument& doc = in.doc();
  if (scene_detail::blameSecond(doc, key, decider)) {
    scene.ignored_keys.push_back({key, doc.originOf(key), decided + " (" + doc.originOf(decider) + "): " + why +
                                                               "; the key is ignored"});
    return;
  }
  doc.fail(key, "no " + key + " with " + decided + " (" + why + "; remove the key or change " + decider + ")",
           describeNode(doc.find(key)));
}

// The soft starter's own keys under another method, and its start time without a current limit.
// `method`, `is`: the deciding key and its value in words.
void refuseIdleSoftStarterKeys(const scene_detail::Reader& in, Scene& scene, const std::string& method,
                               const std::string& is) {
  const MotorStart& m = scene.motor_start;
  if (m.method != StartMethod::SoftStarter) {
    idleKey(in, scene, "motor.start.initial_voltage", method, is, "only a soft_starter starts at a reduced voltage U_0");
    idleKey(in, scene, "motor.start.current_limit", method, is,
            m.method == StartMethod::FrequencyConverter
                ? "only the soft_starter's current limit is modelled, not a frequency converter's"
                : "only a soft_starter limits the current");
    idleKey(in, scene, "motor.start.max_start_time", method, is,
            "only a current-limited soft_starter has a start time after which it trips");
  } else if (!(m.current_limit > 0)) {
    idleKey(in, scene, "motor.start.max_start_time", "motor.start.current_limit",
            "motor.start.current_limit = 0 (no limit)",
            "without a current limit the soft starter closes its bypass at the end of the ramp and never trips");
  }
}

// Every motor.start / motor.stop key that the chosen method (or the other keys) leaves without
// effect: refused, or warned about (idleKey).
void refuseIdleKeys(const scene_detail::Reader& in, Scene& scene) {
  const MotorStart& m = scene.motor_start;
  const std::string method = "motor.start.method", is = std::string("motor.start.method ") + toString(m.method);
  if (m.method != StartMethod::StarDelta)
    for (const char* key : {"motor.start.changeover_time", "motor.start.changeover_speed", "motor.start.changeover_gap"})
      idleKey(in, scene, key, method, is, "only a star_delta start changes over from star to delta");
  if (m.method != StartMethod::SoftStarter && m.method != StartMethod::FrequencyConverter)
    idleKey(in, scene, "motor.start.ramp_time", method, is,
            "only a soft_starter or a frequency_converter ramps; this method gives its supply at once");
  refuseIdleSoftStarterKeys(in, scene, method, is);
  if (m.method != StartMethod::FrequencyConverter)
    for (const char* key : {"motor.start.initial_frequency", "motor.start.boost"})
      idleKey(in, scene, key, method, is, "only a frequency_converter sets the supply frequency and a voltage boost");
  if (!(scene.motor_stop.brake_torque > 0))
    idleKey(in, scene, "motor.stop.brake_delay", "motor.stop.brake_torque", "motor.stop.brake_torque = 0 (no brake)",
            "there is no brake to engage");
}

// The soft starter's ramp, initial voltage, current limit and start time after which it trips;
// the limit needs a law that knows the stator current (motor/Supply.h).
void readSoftStarter(const scene_detail::Reader& in, MotorStart& m, const std::string& needed_by) {
  const SceneDocument& doc = in.doc();
  m.initial_voltage = m.method == StartMethod::SoftStarter
                          ? in.requiredNumber("motor.start.initial_voltage", "required when " + needed_by)
                          : in.numberOr("motor.start.initial_voltage", 1.0);
  m.current_limit = in.number("motor.start.current_limit");
  m.max_start_time = in.number("motor.start.max_start_time");
  if (m.method == StartMethod::SoftStarter && m.current_limit > 0 && m.max_start_time > 0) {
    if (!in.has("motor.start.max_start_time") && !(m.max_start_time > m.ramp_time))
      doc.failMissing("motor.start.max_start_time",
                      "a start time > ramp_time = " + formatNumber(m.ramp_time) +
                          " [s] (motor.start.ramp_time; its default " + formatNumber(m.max_start_time) +
                          " s is shorter; 0 = never trips)");
    requireLater(in, "motor.start.max_start_time", m.max_start_time, "motor.start.ramp_time", m.ramp_time, "ramp_time",
                 "max_start_time");
  }
}

// A current limit needs a law that knows the stator current (motor/Supply.h): a machine law.
void requireLawWithCurrent(const scene_detail::Reader& in, const Scene& scene) {
  const SceneDocument& doc = in.doc();
  const MotorStart& m = scene.motor_start;
  if (!(m.method == StartMethod::SoftStarter && m.current_limit > 0 && !isMachineLaw(scene.induction.model))) return;
  const std::string laws = motorModelWords(false, "or");
  if (scene_detail::blameSecond(doc, "motor.start.current_limit", "motor.model"))
    doc.fail("motor.model", laws + " (motor.start.current_limit needs a model of the stator current)",
             toString(scene.induction.model));
  doc.fail("motor.start.current_limit",
           std::string("0 with motor.model ") + toString(scene.induction.model) +
               " (no stator current in that law; use motor.model " + laws + ")",
           formatNumber(m.current_limit));
}

// The frequency converter's initial frequency (below f_n) and voltage boost.
void readFrequencyConverter(const scene_detail::Reader& in, const Scene& scene, MotorStart& m,
                            const std::string& needed_by) {
  m.initial_frequency = m.method == StartMethod::FrequencyConverter
                            ? in.requiredNumber("motor.start.initial_frequency", "required when " + needed_by)
                            : in.numberOr("motor.start.initial_frequency", 0.0);
  m.boost = in.number("motor.start.boost");
  if (m.method == StartMethod::FrequencyConverter && !(m.initial_frequency < scene.induction.frequency))
    in.doc().fail("motor.start.initial_frequency",
                  "a frequency in (0, f_n = " + formatNumber(scene.induction.frequency) + ") [Hz] (motor.frequency)",
                  formatNumber(m.initial_frequency));
}

// The switch-off after the switch-on (and after a star-delta changeover), a brake only after a
// switch-off, a restart after the switch-off and after the brake engaged.
void readMotorStop(const scene_detail::Reader& in, const MotorStart& m, MotorStop& st) {
  const SceneDocument& doc = in.doc();
  st.t_off = in.number("motor.stop.t_off");
  st.brake_torque = in.number("motor.stop.brake_torque");
  st.brake_delay = in.number("motor.stop.brake_delay");
  st.t_restart = in.number("motor.stop.t_restart");
  const bool off = std::isfinite(st.t_off);
  if (off) {
    requireLater(in, "motor.stop.t_off", st.t_off, "motor.start.t_on", m.t_on, "t_on", "t_off");
    if (m.method == StartMethod::StarDelta && std::isfinite(m.changeover_time))
      requireLater(in, "motor.stop.t_off", st.t_off, "motor.start.changeover_time",
                   m.changeover_time + m.changeover_gap, "changeover_time + changeover_gap", "t_off");
  }
  if (!off && st.brake_torque > 0)
    doc.fail("motor.stop.brake_torque", "0 without motor.stop.t_off (the brake acts after the switch-off)",
             formatNumber(st.brake_torque));
  if (!std::isfinite(st.t_restart)) return;
  if (!off) doc.failMissing("motor.stop.t_off", "a switch-off time before motor.stop.t_restart");
  requireLater(in, "motor.stop.t_restart", st.t_restart, "motor.stop.t_off", st.t_off, "t_off", "t_restart");
  if (st.brake_torque > 0 && !(st.t_off + st.brake_delay < st.t_restart))
    doc.fail("motor.stop.brake_delay",
             "a delay that engages the brake before motor.stop.t_restart = " + formatNumber(st.t_restart) +
                 " s (t_off + brake_delay < t_restart)",
             formatNumber(st.brake_delay));
}

}  // namespace

void readMotorSwitching(const scene_detail::Reader& in, Scene& scene) {
  MotorStart& m = scene.motor_start;
  m.method = in.choiceOf<StartMethod>("motor.start.method");
  m.t_on = in.number("motor.start.t_on");
  m.phase = in.number("motor.start.phase_deg") * kDegToRad;
  readStarDelta(in, m, scene.motor.omega_sync);
  m.changeover_gap = in.number("motor.start.changeover_gap");
  const bool ramped = m.method == StartMethod::SoftStarter || m.method == StartMethod::FrequencyConverter;
  const std::string needed_by = std::string("motor.start.method is ") + toString(m.method);
  m.ramp_time = ramped ? in.requiredNumber("motor.start.ramp_time", "required when " + needed_by)
                       : in.numberOr("motor.start.ramp_time", 0.0);
  readSoftStarter(in, m, needed_by);
  readFrequencyConverter(in, scene, m, needed_by);
  requireLawWithCurrent(in, scene);
  readMotorStop(in, m, scene.motor_stop);
  refuseIdleKeys(in, scene);
}

}  // namespace rollerdyn
