// The catalogue fit kept on disk (FitCache.h) and the keys of both fit caches: the key changes
// with every input the fit reads and with nothing else, a kept fit gives bit for bit the law of a
// fresh one, a bad file is refitted and rewritten, an unwritable folder means no cache.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <set>
#include <string>

#include "MachineFixtures.h"
#include "io/ReadFile.h"
#include "motor/CatalogueFit.h"
#include "motor/CircuitLaw.h"
#include "motor/FitCache.h"
#include "motor/MotorLawFactory.h"
#include "motor/ParkLaw.h"
#include "scene/Scene.h"
#include "scene/SceneParser.h"

namespace rollerdyn {
namespace {

namespace fs = std::filesystem;

// Sets (or, with nullptr, unsets) an environment variable for the scope; restores it after.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const char* value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = std::string(old);
    if (value) ::setenv(name, value, 1);
    else ::unsetenv(name);
  }
  ~ScopedEnv() {
    if (old_) ::setenv(name_.c_str(), old_->c_str(), 1);
    else ::unsetenv(name_.c_str());
  }

 private:
  std::string name_;
  std::optional<std::string> old_;
};

// A fresh empty folder under the system's temporary folder (never the user's cache).
std::string freshFolder() {
  std::string pattern = (fs::temp_directory_path() / "rollerdyn-fit-cache-XXXXXX").string();
  return ::mkdtemp(pattern.data());
}

// A catalogue a double cage can meet exactly (X_σr1 = X_σs), so its fit stops after few starts:
// the doubleCage fixture's values at rated slip 0.03, computed by the circuit's closed form.
MotorCatalogue exactCatalogue() {
  InductionMachineParameters m = test::doubleCage();
  m.L_sigma_r[0] = m.L_sigma_s;
  const double w_n = m.synchronousSpeed() * (1 - 0.03);
  const test::ClosedForm rated = test::closedForm(m, 0.03), start = test::closedForm(m, 1.0);
  MotorCatalogue c;
  c.power = rated.torque * w_n;
  c.omega_nominal = w_n;
  c.current = rated.current;
  c.power_factor = 0.85;
  c.efficiency = 0.9;
  c.starting_torque_ratio = start.torque / rated.torque;
  c.breakdown_torque_ratio = 2.2;
  c.starting_current_ratio = start.current / rated.current;
  return c;
}
const CatalogueSupply kSupply{380.0, 50.0, 3};

// Changes a value: doubles by a part in a thousand (or to 1 from 0), integers by one, flags and
// enumerations to another value.
void perturb(double& x) { x = x == 0 ? 1.0 : x * 1.001; }
void perturb(int& x) { x += 1; }
void perturb(bool& x) { x = !x; }
template <class E, class = std::enable_if_t<std::is_enum_v<E>>>
void perturb(E& x) {
  x = static_cast<E>(static_cast<int>(x) == 0 ? 1 : 0);
}
// Perturbs the n-th of `fields`; returns how many there are.
template <class... T>
int perturbNth(int n, T&... fields) {
  int i = 0;
  ((i++ == n ? perturb(fields) : void()), ...);
  return i;
}

TEST(FitCache, KeyChangesWithEveryInputOfTheFitAndNamesTheMethodsVersion) {
  const MotorCatalogue c0 = exactCatalogue();
  const std::string base = catalogueFitKey(c0, kSupply, 2);
  EXPECT_NE(base.find("catalogue_fit_version=" + std::to_string(kCatalogueFitVersion) + ";"), std::string::npos) << base;
  // The build's hash of the fitting code's sources: 16 hexadecimal digits.
  const size_t at = base.find("fit_sources=");
  ASSERT_NE(at, std::string::npos) << base;
  EXPECT_EQ(base.find_first_not_of("0123456789abcdef", at + 12), at + 28) << base;
  std::set<std::string> keys{base};
  int count = 0;
  for (int n = 0;; ++n) {
    MotorCatalogue c = c0;
    CatalogueSupply s = kSupply;
    int cages = 2;
    auto& [power, omega_nominal, current, power_factor, efficiency, m_s, m_k, i_s, catalogue_cages] = c;
    auto& [line_voltage, frequency, pole_pairs] = s;
    count = perturbNth(n, power, omega_nominal, current, power_factor, efficiency, m_s, m_k, i_s, line_voltage,
                       frequency, pole_pairs, cages);
    if (n >= count) break;
    EXPECT_TRUE(keys.insert(catalogueFitKey(c, s, cages)).second) << "input " << n << " leaves the key unchanged";
  }
  EXPECT_EQ(count, 12);
  // motor.catalogue.cages is not read by the fit (its argument `cages` is): no new key.
  MotorCatalogue other_cages = c0;
  other_cages.cages = 1;
  EXPECT_EQ(catalogueFitKey(other_cages, kSupply, 2), base);
  // The last bit of a value counts.
  MotorCatalogue last_bit = c0;
  last_bit.current = std::nextafter(last_bit.current, 1e9);
  EXPECT_NE(catalogueFitKey(last_bit, kSupply, 2), base);
}

Scene catalogueScene(const std::vector<std::string>& overrides = {}) {
  std::vector<std::string> all{"motor.model=circuit"};
  all.insert(all.end(), overrides.begin(), overrides.end());
  return parseSceneFile(std::string(ROLLERDYN_SOURCE_DIR) + "/model/balanced-4cart.yaml", all);
}

TEST(FitCache, AKeyOutsideTheMotorChangesNeitherKey) {
  const Scene a = catalogueScene(), b = catalogueScene({"carts.mass=777"});
  ASSERT_NE(a.carts.mass, b.carts.mass);
  EXPECT_EQ(sceneCatalogueFitKey(a, 2), sceneCatalogueFitKey(b, 2));
  EXPECT_EQ(motorLawKey(a), motorLawKey(b));
  const Scene c = catalogueScene({"motor.catalogue.current=40"});  // a motor key does
  EXPECT_NE(sceneCatalogueFitKey(a, 2), sceneCatalogueFitKey(c, 2));
  EXPECT_NE(motorLawKey(a), motorLawKey(c));
}

TEST(SharedMotorLaw, EveryMotorFieldChangesTheKey) {
  const Scene base = catalogueScene();
  std::set<std::string> keys{motorLawKey(base)};
  int count = 0;
  for (int n = 0;; ++n) {
    Scene s = base;
    auto& [enabled, omega_sync, breakdown_torque, critical_slip, rotor_inertia] = s.motor;
    auto& [model, te, voltage, frequency, connection, pole_pairs, circuit, catalogue] = s.induction;
    auto& [R_s, L_sigma_s, L_m, R_r, L_sigma_r, R_r2, L_sigma_r2] = circuit;
    auto& [power, omega_nominal, current, power_factor, efficiency, m_s, m_k, i_s, cages] = catalogue;
    count = perturbNth(n, enabled, omega_sync, breakdown_torque, critical_slip, rotor_inertia, model, te, voltage,
                       frequency, connection, pole_pairs, R_s, L_sigma_s, L_m, R_r, L_sigma_r, R_r2, L_sigma_r2, power,
                       omega_nominal, current, power_factor, efficiency, m_s, m_k, i_s, cages);
    if (n >= count) break;
    EXPECT_TRUE(keys.insert(motorLawKey(s)).second) << "motor field " << n << " leaves the key unchanged";
  }
  EXPECT_EQ(count, 27);
}

// Every output of both catalogue laws of two machines, compared bit for bit.
void expectSameLaws(const InductionMachineParameters& a, const InductionMachineParameters& b) {
  const CircuitLaw ca(a), cb(b);
  const ParkLaw pa(a), pb(b);
  const SupplyState supply;
  for (int i = 0; i <= 20; ++i) {
    const double w = a.synchronousSpeed() * i / 20.0;
    EXPECT_EQ(ca.steadyTorque(supply, w), cb.steadyTorque(supply, w)) << w;
    EXPECT_EQ(ca.steadyCurrent(supply, w), cb.steadyCurrent(supply, w)) << w;
    double xa[6] = {0}, xb[6] = {0}, da[6] = {0}, db[6] = {0};
    pa.initialState(supply, w, true, xa);
    pb.initialState(supply, w, true, xb);
    for (int k = 0; k < pa.stateCount(); ++k) xa[k] = xb[k] = xa[k] * 0.9 + 0.01 * k;  // off steady state
    MotorEvaluation ea, eb;
    pa.evaluate(supply, w, xa, ea, da);
    pb.evaluate(supply, w, xb, eb, db);
    EXPECT_EQ(ea.torque, eb.torque) << w;
    EXPECT_EQ(ea.stator_current, eb.stator_current) << w;
    for (int k = 0; k < pa.stateCount(); ++k) EXPECT_EQ(da[k], db[k]) << w << " state " << k;
  }
}

TEST(FitCache, ALawFromAKeptFitGivesBitIdenticalTorquesAndCurrents) {
  const std::string folder = freshFolder();
  ScopedEnv env("ROLLERDYN_CACHE_DIR", folder.c_str());
  const MotorCatalogue c = exactCatalogue();
  const CatalogueFit fresh = fitCatalogueThroughDiskCache(c, kSupply, 2);
  EXPECT_FALSE(fresh.origin.from_cache);
  ASSERT_EQ(fs::path(fresh.origin.cache_file).parent_path(), fs::path(folder));
  ASSERT_TRUE(fs::exists(fresh.origin.cache_file));
  const CatalogueFit kept = fitCatalogueThroughDiskCache(c, kSupply, 2);
  EXPECT_TRUE(kept.origin.from_cache);
  EXPECT_EQ(kept.origin.cache_file, fresh.origin.cache_file);
  EXPECT_EQ(kept.origin.fitted_on, fresh.origin.fitted_on);
  EXPECT_EQ(kept.origin.fit_seconds, fresh.origin.fit_seconds);
  EXPECT_EQ(kept.starts, fresh.starts);
  EXPECT_EQ(kept.evaluations, fresh.evaluations);
  EXPECT_EQ(kept.max_relative_error, fresh.max_relative_error);
  const InductionMachineParameters &a = fresh.machine, &b = kept.machine;
  EXPECT_EQ(a.R_s, b.R_s);
  EXPECT_EQ(a.L_sigma_s, b.L_sigma_s);
  EXPECT_EQ(a.L_m, b.L_m);
  EXPECT_EQ(a.cages, b.cages);
  for (int k = 0; k < 2; ++k) {
    EXPECT_EQ(a.R_r[k], b.R_r[k]);
    EXPECT_EQ(a.L_sigma_r[k], b.L_sigma_r[k]);
  }
  EXPECT_EQ(a.pole_pairs, b.pole_pairs);
  EXPECT_EQ(a.phase_voltage, b.phase_voltage);
  EXPECT_EQ(a.frequency, b.frequency);
  expectSameLaws(a, b);
  fs::remove_all(folder);
}

TEST(FitCache, ACorruptTruncatedOrForeignFileIsRefused) {
  const std::string key = catalogueFitKey(exactCatalogue(), kSupply, 2);
  KeptFit fit;
  fit.machine = test::doubleCage();
  fit.starts = 3;
  fit.evaluations = 1234;
  fit.fitted_on = "2026-11-28 00:41 UTC";
  fit.fit_seconds = 0.1;
  const std::string text = formatKeptFit(key, fit);
  const std::optional<KeptFit> back = parseKeptFit(text, key);
  ASSERT_TRUE(back);
  EXPECT_EQ(back->machine.L_sigma_r[1], fit.machine.L_sigma_r[1]);
  EXPECT_EQ(back->fit_seconds, 0.1);
  for (size_t n = 0; n < text.size(); ++n) EXPECT_FALSE(parseKeptFit(text.substr(0, n), key)) << "cut at " << n;
  EXPECT_FALSE(parseKeptFit("\x7f" "ELF garbage\n", key));
  EXPECT_FALSE(parseKeptFit(text + "more\n", key));
  const std::string version = "catalogue_fit_version=" + std::to_string(kCatalogueFitVersion) + ";";
  std::string older = text;
  older.replace(older.find(version), version.size(), "catalogue_fit_version=0;");
  EXPECT_FALSE(parseKeptFit(older, key));  // another version of the method
  MotorCatalogue other = exactCatalogue();
  other.efficiency = 0.91;
  EXPECT_FALSE(parseKeptFit(text, catalogueFitKey(other, kSupply, 2)));  // another motor's file
  KeptFit negative = fit;
  negative.machine.R_r[0] = -1;
  EXPECT_FALSE(parseKeptFit(formatKeptFit(key, negative), key));  // a machine out of range
}

TEST(FitCache, ACorruptFileIsFittedAgainAndRewritten) {
  const std::string folder = freshFolder();
  ScopedEnv env("ROLLERDYN_CACHE_DIR", folder.c_str());
  const MotorCatalogue c = exactCatalogue();
  const std::string file = fitCacheFile(catalogueFitKey(c, kSupply, 2));
  ASSERT_FALSE(file.empty());
  { std::ofstream(file) << "rollerdyn catalogue fit\nkey garbage\n"; }
  const CatalogueFit refit = fitCatalogueThroughDiskCache(c, kSupply, 2);
  EXPECT_FALSE(refit.origin.from_cache);
  EXPECT_EQ(refit.origin.cache_file, file);
  EXPECT_TRUE(parseKeptFit(readFileContents(file), catalogueFitKey(c, kSupply, 2)));  // rewritten whole
  const CatalogueFit kept = fitCatalogueThroughDiskCache(c, kSupply, 2);
  EXPECT_TRUE(kept.origin.from_cache);
  EXPECT_EQ(kept.machine.R_r[1], refit.machine.R_r[1]);
  fs::remove_all(folder);
}

TEST(FitCache, AnUnwritableFolderMeansNoCacheWithOneNote) {
  const std::string folder = freshFolder();
  { std::ofstream(folder + "/a-file") << "x"; }
  const std::string below_a_file = folder + "/a-file/cache";  // cannot be made, even by root
  ScopedEnv env("ROLLERDYN_CACHE_DIR", below_a_file.c_str());
  testing::internal::CaptureStderr();
  const CatalogueFit a = fitCatalogueThroughDiskCache(exactCatalogue(), kSupply, 2);
  const CatalogueFit b = fitCatalogueThroughDiskCache(exactCatalogue(), kSupply, 2);
  const std::string err = testing::internal::GetCapturedStderr();
  EXPECT_FALSE(a.origin.from_cache);
  EXPECT_FALSE(b.origin.from_cache);
  EXPECT_EQ(a.origin.cache_file, "");
  EXPECT_EQ(a.machine.R_s, b.machine.R_s);
  EXPECT_NE(a.origin.describe().find("not kept"), std::string::npos) << a.origin.describe();
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
  EXPECT_NE(err.find("ROLLERDYN_CACHE_DIR"), std::string::npos) << err;
  fs::remove_all(folder);
}

TEST(FitCache, FolderIsTheOwnVariableElseXdgElseHome) {
  ScopedEnv own("ROLLERDYN_CACHE_DIR", "/tmp/own"), xdg("XDG_CACHE_HOME", "/tmp/xdg"), home("HOME", "/tmp/home");
  EXPECT_EQ(fitCacheFolder(), "/tmp/own");
  {
    ScopedEnv none("ROLLERDYN_CACHE_DIR", nullptr);
    EXPECT_EQ(fitCacheFolder(), "/tmp/xdg/rollerdyn");
    ScopedEnv no_xdg("XDG_CACHE_HOME", nullptr);
    EXPECT_EQ(fitCacheFolder(), "/tmp/home/.cache/rollerdyn");
    ScopedEnv no_home("HOME", nullptr);
    EXPECT_EQ(fitCacheFolder(), "");
    EXPECT_EQ(fitCacheFile("any key"), "");
  }
  const std::string file = fitCacheFile("any key");
  EXPECT_EQ(fs::path(file).parent_path(), fs::path("/tmp/own"));
  EXPECT_NE(fitCacheFile("another key"), file);
}

TEST(FitOrigin, SaysWhereTheFitCameFrom) {
  EXPECT_EQ((FitOrigin{false, "/c/f.txt", "2026-11-28 00:41 UTC", 1.678}).describe(),
            "fitted now in 1.68 s, kept in /c/f.txt");
  EXPECT_EQ((FitOrigin{true, "/c/f.txt", "2026-11-28 00:41 UTC", 1.678}).describe(),
            "from the cache /c/f.txt (fitted on 2026-11-28 00:41 UTC in 1.68 s)");
  EXPECT_EQ((FitOrigin{false, "", "2026-11-28 00:41 UTC", 0.5}).describe(),
            "fitted now in 0.50 s, not kept (no writable cache folder)");
}

}  // namespace
}  // namespace rollerdyn
