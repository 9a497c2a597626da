// The message of the exception a call throws, so a test can compare the whole error text a user
// would read; "(no exception)" when the call returns normally.
#pragma once

#include <exception>
#include <functional>
#include <string>

namespace rollerdyn::test {

inline std::string messageOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "(no exception)";
}

}  // namespace rollerdyn::test
