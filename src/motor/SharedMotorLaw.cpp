#include "motor/SharedMotorLaw.h"

#include <map>
#include <mutex>
#include <string>

#include "motor/MotorLawFactory.h"

namespace rollerdyn {

std::shared_ptr<const MotorLaw> sharedMotorLaw(const Scene& scene) {
  static std::mutex mutex;
  static std::map<std::string, std::shared_ptr<const MotorLaw>> laws;
  const std::string key = motorLawKey(scene);
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
