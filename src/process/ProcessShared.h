// One object per process and name, whichever copy of the static libraries asks. The reduced
// model is a shared library that carries its own hidden copy of the layers below it
// (CMakeLists.txt: --exclude-libs), so a function-local static in those layers exists twice in
// a process: the in-process memories of fitted motors and built laws (CatalogueFit.cpp,
// SharedMotorLaw.cpp) would be filled twice. This small shared library is linked, not copied,
// into every binary, so what it hands out is one per process.
#pragma once

namespace rollerdyn {

// The object registered under `name`, made by `create` the first time (thread-safe). Never
// destroyed. Every caller of one name must mean the same type (built from the same source).
void* processShared(const char* name, void* (*create)());

// Typed: the T under `name`, default-constructed the first time.
template <class T>
T& processShared(const char* name) {
  return *static_cast<T*>(processShared(name, []() -> void* { return new T(); }));
}

}  // namespace rollerdyn
