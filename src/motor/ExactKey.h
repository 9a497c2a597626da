// The exact text of the inputs a computed result depends on, for cache keys (CatalogueFit.h,
// MotorLawFactory.h): each value after its name, doubles in hexadecimal floating point (printf's
// %a, exact: two inputs that differ in their last bit give different keys), integers, flags and
// enumerations in decimal.
#pragma once

#include <cstdio>
#include <string>
#include <type_traits>

namespace rollerdyn {

class ExactKey {
 public:
  ExactKey& add(const char* name, double x) {
    char buf[48];
    std::snprintf(buf, sizeof buf, "%a", x);
    return put(name, buf);
  }
  ExactKey& add(const char* name, int x) { return put(name, std::to_string(x)); }
  ExactKey& add(const char* name, bool x) { return put(name, x ? "1" : "0"); }
  template <class E, class = std::enable_if_t<std::is_enum_v<E>>>
  ExactKey& add(const char* name, E x) {
    return put(name, std::to_string(static_cast<long long>(x)));
  }
  ExactKey& add(const char* name, const std::string& x) { return put(name, x); }
  const std::string& text() const { return text_; }

 private:
  ExactKey& put(const char* name, const std::string& value) {
    if (!text_.empty()) text_ += ';';
    text_ += name;
    text_ += '=';
    text_ += value;
    return *this;
  }
  std::string text_;
};

}  // namespace rollerdyn
