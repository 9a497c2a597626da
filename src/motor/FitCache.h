// The catalogue fits kept on disk, so that a process does not fit again what an earlier one
// fitted (a double-cage fit takes 1-2 s against ~0.3 s for a whole run with Kloss's law).
// One small text file a fit, named by a hash of its key (catalogueFitKey, CatalogueFit.h: every
// input the fit reads and the fitting method's version) and holding the whole key, so a file of
// another key, another version, or a hash collision is never taken for this one. Numbers are
// hexadecimal floating point: a kept fit gives bit for bit the machine fitted.
// Folder: $ROLLERDYN_CACHE_DIR, else $XDG_CACHE_HOME/rollerdyn, else $HOME/.cache/rollerdyn.
// A missing, unreadable, corrupt or truncated file is a miss (the fit is computed and the file
// written anew); a folder that cannot be written means no cache (one note on stderr a process).
// Files are written atomically (AtomicFile.h), so processes in parallel never read a half file.
#pragma once

#include <optional>
#include <string>

#include "motor/InductionMachine.h"

namespace rollerdyn {

// What a cache file holds besides the key.
struct KeptFit {
  InductionMachineParameters machine;
  int starts = 0;
  int evaluations = 0;
  std::string fitted_on;  // "2026-11-28 00:41 UTC"
  double fit_seconds = 0; // [s]
};

// The cache folder from the environment (header); "" when none is set (no HOME either).
std::string fitCacheFolder();
// The file of `key` in fitCacheFolder(); "" when there is no folder.
std::string fitCacheFile(const std::string& key);

// The file's text, and back; parseKeptFit gives nullopt for any text not written by formatKeptFit
// for this key (another key or version, truncated, corrupt, a machine out of range).
std::string formatKeptFit(const std::string& key, const KeptFit& fit);
std::optional<KeptFit> parseKeptFit(const std::string& text, const std::string& key);

// Reads the kept fit of `key` from `file`; nullopt when there is none usable.
std::optional<KeptFit> readKeptFit(const std::string& file, const std::string& key);
// Writes it; false (and one note on stderr a process) when the file cannot be written.
bool writeKeptFit(const std::string& file, const std::string& key, const KeptFit& fit);

}  // namespace rollerdyn
