#include "motor/SharedMotorLaw.h"

#include <map>
#include <mutex>
#include <string>

#include "motor/MotorLawFactory.h"
#include "process/ProcessShared.h"

namespace rollerdyn {

std::shared_ptr<const MotorLaw> sharedMotorLaw(const Scene& scene) {
  struct Memory {
    std::mutex mutex;
    std::map<std::string, std::shared_ptr<const MotorLaw>> laws;
  };
  // One per process, also when the reduced model's library asks (ProcessShared.h).
  static Memory& memory = processShared<Memory>("motor laws v1");
  const std::string key = motorLawKey(scene);
  {
    std::lock_guard<std::mutex> lock(memory.mutex);
    const auto it = memory.laws.find(key);
    if (it != memory.laws.end()) return it->second;
  }
  std::shared_ptr<const MotorLaw> law = makeMotorLaw(scene);  // outside the lock: fits take time
  std::lock_guard<std::mutex> lock(memory.mutex);
  return memory.laws.emplace(key, std::move(law)).first->second;
}

}  // namespace rollerdyn
