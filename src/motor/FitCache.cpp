#include "motor/FitCache.h"

#include <atomic>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <sstream>
#include <type_traits>

#include "io/AtomicFile.h"
#include "io/ReadFile.h"
#include "process/ProcessShared.h"

namespace rollerdyn {

namespace {

constexpr const char* kHeader = "rollerdyn catalogue fit";

std::string environment(const char* name) {
  const char* v = std::getenv(name);
  return v ? std::string(v) : std::string();
}

// FNV-1a, 64 bits: the file name only (the file holds the whole key).
std::uint64_t hash64(const std::string& s) {
  std::uint64_t h = 1469598103934665603ULL;
  for (unsigned char c : s) h = (h ^ c) * 1099511628211ULL;
  return h;
}

std::string hex(double x) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%a", x);
  return buf;
}

// A double written by hex(): the whole word must be a number.
bool parseDouble(const std::string& word, double& x) {
  if (word.empty()) return false;
  char* end = nullptr;
  x = std::strtod(word.c_str(), &end);
  return end == word.c_str() + word.size();
}

bool parseInt(const std::string& word, int& x) {
  if (word.empty()) return false;
  char* end = nullptr;
  const long v = std::strtol(word.c_str(), &end, 10);
  x = int(v);
  return end == word.c_str() + word.size() && long(x) == v;
}

// Every field of the machine, named by a structured binding: a field added to
// InductionMachineParameters fails to compile here until the file keeps it.
template <class Machine, class F>
void eachMachineField(Machine& m, F&& f) {
  auto& [R_s, L_sigma_s, L_m, cages, R_r, L_sigma_r, pole_pairs, phase_voltage, frequency] = m;
  f(R_s), f(L_sigma_s), f(L_m), f(cages), f(R_r[0]), f(R_r[1]), f(L_sigma_r[0]), f(L_sigma_r[1]), f(pole_pairs),
      f(phase_voltage), f(frequency);
}

}  // namespace

std::string fitCacheFolder() {
  const std::string own = environment("ROLLERDYN_CACHE_DIR");
  if (!own.empty()) return own;
  const std::string xdg = environment("XDG_CACHE_HOME");
  if (!xdg.empty()) return xdg + "/rollerdyn";
  const std::string home = environment("HOME");
  if (!home.empty()) return home + "/.cache/rollerdyn";
  return "";
}

std::string fitCacheFile(const std::string& key) {
  const std::string folder = fitCacheFolder();
  if (folder.empty()) return "";
  char name[64];
  std::snprintf(name, sizeof name, "/catalogue-fit-%016llx.txt", static_cast<unsigned long long>(hash64(key)));
  return folder + name;
}

std::string formatKeptFit(const std::string& key, const KeptFit& fit) {
  std::string machine;
  eachMachineField(fit.machine, [&](const auto& x) {
    if (!machine.empty()) machine += ' ';
    if constexpr (std::is_same_v<std::decay_t<decltype(x)>, double>) machine += hex(x);
    else machine += std::to_string(x);
  });
  return std::string(kHeader) + "\n" + "key " + key + "\n" + "fitted_on " + fit.fitted_on + "\n" +
         "fit_seconds " + hex(fit.fit_seconds) + "\n" + "machine " + machine + "\n" +
         "starts " + std::to_string(fit.starts) + "\n" + "evaluations " + std::to_string(fit.evaluations) + "\n" +
         "end\n";
}

namespace {

// The machine line's words into m's fields, in eachMachineField's order; false on a word missing,
// unreadable or left over.
bool parseMachine(const std::string& line, InductionMachineParameters& m) {
  std::istringstream words(line);
  bool ok = true;
  eachMachineField(m, [&](auto& x) {
    std::string w;
    if (!(words >> w)) ok = false;
    else if constexpr (std::is_same_v<std::decay_t<decltype(x)>, double>) ok = ok && parseDouble(w, x);
    else ok = ok && parseInt(w, x);
  });
  std::string extra;
  return ok && !(words >> extra);
}

// Whether a machine read back passes its own checks: a damaged file is fitted again, not trusted.
bool isValidMachine(const InductionMachineParameters& m) {
  try {
    m.validate();
  } catch (const std::exception&) {
    return false;
  }
  return true;
}

}  // namespace

std::optional<KeptFit> parseKeptFit(const std::string& text, const std::string& key) {
  if (text.size() < 4 || text.compare(text.size() - 4, 4, "end\n") != 0) return std::nullopt;  // cut short
  std::istringstream in(text);
  std::string line;
  // The next line, which must begin with `label` and a space; its rest.
  auto field = [&](const std::string& label, std::string& rest) {
    if (!std::getline(in, line) || line.compare(0, label.size() + 1, label + " ") != 0) return false;
    rest = line.substr(label.size() + 1);
    return true;
  };
  KeptFit fit;
  std::string rest;
  if (!std::getline(in, line) || line != kHeader) return std::nullopt;
  if (!field("key", rest) || rest != key) return std::nullopt;
  if (!field("fitted_on", fit.fitted_on)) return std::nullopt;
  if (!field("fit_seconds", rest) || !parseDouble(rest, fit.fit_seconds)) return std::nullopt;
  if (!field("machine", rest) || !parseMachine(rest, fit.machine)) return std::nullopt;
  if (!field("starts", rest) || !parseInt(rest, fit.starts)) return std::nullopt;
  if (!field("evaluations", rest) || !parseInt(rest, fit.evaluations)) return std::nullopt;
  if (!std::getline(in, line) || line != "end" || std::getline(in, line)) return std::nullopt;
  if (!isValidMachine(fit.machine)) return std::nullopt;
  return fit;
}

std::optional<KeptFit> readKeptFit(const std::string& file, const std::string& key) {
  if (file.empty()) return std::nullopt;
  try {
    return parseKeptFit(readFileContents(file), key);
  } catch (const std::exception&) {
    return std::nullopt;  // none yet, or unreadable: fitted anew
  }
}

bool writeKeptFit(const std::string& file, const std::string& key, const KeptFit& fit) {
  std::string why = "neither ROLLERDYN_CACHE_DIR, XDG_CACHE_HOME nor HOME is set";
  if (!file.empty()) try {
      writeFileAtomic(file, formatKeptFit(key, fit));
      return true;
    } catch (const std::exception& e) {
      why = e.what();
    }
  static std::atomic<bool>& said = processShared<std::atomic<bool>>("fit cache note said");  // once a process
  if (!said.exchange(true))
    std::cerr << "note: the motor's fitted circuit cannot be kept for later runs (" << why
              << "); each run fits it again. Set ROLLERDYN_CACHE_DIR to a writable folder to keep it.\n";
  return false;
}

}  // namespace rollerdyn
