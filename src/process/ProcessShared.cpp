#include "process/ProcessShared.h"

#include <map>
#include <mutex>
#include <string>

namespace rollerdyn {

void* processShared(const char* name, void* (*create)()) {
  static std::mutex mutex;
  static auto* objects = new std::map<std::string, void*>();  // never destroyed: used until exit
  std::lock_guard<std::mutex> lock(mutex);
  void*& object = (*objects)[name];
  if (!object) object = create();
  return object;
}

}  // namespace rollerdyn
