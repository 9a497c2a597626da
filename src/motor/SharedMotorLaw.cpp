#include "motor/SharedMotorLaw.h"

#include <cstdio>
#include <map>
#include <mutex>
#include <string>

#include "motor/MotorLawFactory.h"

namespace rollerdyn {

namespace {

// Every number a law is built from, exactly (hexadecimal floating point).
std::string motorKey(const Scene& s) {
  const KlossMotor& k = s.motor;
  const InductionMotor& m = s.induction;
  const MotorCircuit& c = m.circuit;
  const MotorCatalogue& g = m.catalogue;
  const double numbers[] = {k.omega_sync, k.breakdown_torque, k.critical_slip, k.rotor_inertia,
                            m.torque_time_constant, m.voltage, m.frequency,
                            c.R_s, c.L_sigma_s, c.L_m, c.R_r, c.L_sigma_r, c.R_r2, c.L_sigma_r2,
                            g.power, g.omega_nominal, g.current, g.power_factor, g.efficiency,
                            g.starting_torque_ratio, g.breakdown_torque_ratio, g.starting_current_ratio};
  std::string key = std::to_string(int(m.model)) + "/" + std::to_string(int(m.connection)) + "/" +
                    std::to_string(m.pole_pairs) + "/" + std::to_string(g.cages);
  char buf[40];
  for (double x : numbers) {
    std::snprintf(buf, sizeof buf, "/%a", x);
    key += buf;
  }
  return key;
}

}  // namespace

std::shared_ptr<const MotorLaw> sharedMotorLaw(const Scene& scene) {
  static std::mutex mutex;
  static std::map<std::string, std::shared_ptr<const MotorLaw>> laws;
  const std::string key = motorKey(scene);
  {
    std::lock_guard<std::mutex> lock(mutex);
    const auto it = laws.find(key);
    if (it != laws.end()) return it->second;
  }
  std::shared_ptr<const MotorLaw> law = makeMotorLaw(scene);  // outside the lock: fits take time
  std::lock_guard<std::mutex> lock(mutex);
  return laws.emplace(key, std::move(law)).first->second;
}

}  // namespace rollerdyn
