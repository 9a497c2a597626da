#include "report/ToolVersion.h"

#include <ctime>

#ifndef ROLLERDYN_VERSION
#define ROLLERDYN_VERSION "unknown"
#endif
#ifndef ROLLERDYN_GIT_COMMIT
#define ROLLERDYN_GIT_COMMIT ""
#endif

namespace rollerdyn {

std::string toolVersionText() {
  std::string v = std::string("rollerdyn ") + ROLLERDYN_VERSION;
  if (std::string(ROLLERDYN_GIT_COMMIT).size()) v += std::string(" (commit ") + ROLLERDYN_GIT_COMMIT + ")";
  return v;
}

std::string utcTimestamp() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char b[40];
  std::strftime(b, sizeof b, "%Y-%m-%d %H:%M UTC", &utc);
  return b;
}

}  // namespace rollerdyn
