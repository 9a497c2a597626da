// Identification against known values (IdentifyValidation.h). The "measurements" are runs of the
// model with the true values at accuracy 1e-10 plus Gaussian noise of 0.2 % of each signal's RMS
// value from fixed seeds; the identification starts from the scene's values.
#include "studies/IdentifyValidation.h"

#include <cmath>
#include <sstream>

#include "io/FieldFormat.h"
#include "scene/SceneSchema.h"
#include "studies/Identify.h"
#include "studies/SyntheticMeasurements.h"

namespace rollerdyn::validation {

namespace {

constexpr double kStiffness = kCouplingCaseStiffness;
constexpr double kDamping = kCouplingCaseDamping;
constexpr double kNoise = kCouplingCaseNoise;

IdentifyOptions couplingFit(const ItemContext& ctx, const std::string& model, std::vector<std::string> sets) {
  IdentifyOptions o = couplingCaseFit(ctx.path("balanced-4cart.yaml"), model, std::move(sets));
  o.interrupt = ctx.interrupt;
  return o;
}

std::vector<std::string> truthSets(std::vector<std::string> sets) { return couplingCaseTruth(std::move(sets)); }

// The smallest k with P(X < k) ≤ 1 % for X ~ Binomial(n, p): a count of hits below k has less
// than a 1 % chance when the intervals hold their nominal probability p.
int binomialFirstPercentile(int n, double p) {
  double below = 0;
  for (int k = 0; k <= n; ++k) {
    const double pk = std::exp(std::lgamma(n + 1.0) - std::lgamma(k + 1.0) - std::lgamma(n - k + 1.0) +
                               k * std::log(p) + (n - k) * std::log1p(-p));
    if (below + pk > 0.01) return k;
    below += pk;
  }
  return n;
}

// One key's estimate against its true value, into the claim's line; true when within 3σ and 10 %.
bool keyWithinTruth(const IdentifiedKey& key, double truth, std::ostringstream& line) {
  const double err = std::abs(key.value - truth);
  line << key.key << " = " << significant(key.value, 6) << " ± " << significant(key.std, 2) << " (true "
       << formatNumber(truth) << ", error " << significant(err / key.std, 2) << " σ, "
       << significant(100 * err / truth, 2) << " %); ";
  return err <= 3 * key.std && err <= 0.1 * truth;
}

// (1) The case: circuit motor, multibody model, three signals.
void claimCircuitMotorCase(ValidationSection& s, const ItemContext& ctx) {
  const std::vector<std::string> sets = {"motor.model=circuit"};
  const RunResult truth = truthRun(ctx.path("balanced-4cart.yaml"), truthSets(sets), 3.0, 0.005, "multibody");
  IdentifyOptions o = couplingFit(ctx, "multibody", sets);
  o.data = measureRun(truth, {"omega_crank", "omega_motor", "stator_current"}, kNoise, 1);
  const IdentifyResult r = runIdentify(o);
  const double truths[2] = {kStiffness, kDamping};
  bool holds = r.converged;
  std::ostringstream line;
  line << "Circuit motor (motor.model circuit), multibody model, 3 s (" << r.t.size()
       << " samples of omega_crank, omega_motor, stator_current): ";
  for (std::size_t k = 0; k < r.keys.size(); ++k) holds = keyWithinTruth(r.keys[k], truths[k], line) && holds;
  line << "correlation " << (r.correlation.size() == 2 ? significant(r.correlation[0][1], 2) : "n/a") << ", "
       << r.iterations << " iterations, " << r.runs << " runs, " << significant(r.wall_seconds, 3)
       << " s wall; " << r.convergence << ". Both within 3σ (a Gaussian estimate misses that in 0.3 % of cases) "
       << "and within 10 %";
  s.claim(holds, line.str());
}

// The fits over noise seeds: how often each key's 2σ interval holds its true value.
struct Coverage {
  int hits[2] = {0, 0};
  int converged = 0, runs = 0;
  double wall = 0;
};

Coverage coverageOverSeeds(const ItemContext& ctx, int seeds) {
  const RunResult truth = truthRun(ctx.path("balanced-4cart.yaml"), truthSets({}), 2.5, 0.005, "reduced");
  Coverage c;
  for (int seed = 1; seed <= seeds && !ctx.interrupted(); ++seed) {
    IdentifyOptions o = couplingFit(ctx, "reduced", {});
    o.data = measureRun(truth, {"omega_crank", "omega_motor"}, kNoise, 1000 + static_cast<std::uint64_t>(seed));
    const IdentifyResult r = runIdentify(o);
    c.converged += r.converged ? 1 : 0;
    c.runs += r.runs;
    c.wall += r.wall_seconds;
    const double truths[2] = {kStiffness, kDamping};
    for (int k = 0; k < 2; ++k) c.hits[k] += std::abs(r.keys[k].value - truths[k]) <= 2 * r.keys[k].std ? 1 : 0;
  }
  return c;
}

// (2) Coverage of the 2σ intervals over noise seeds: reduced model (milliseconds a run), 2.5 s.
void claimCoverage(ValidationSection& s, const ItemContext& ctx) {
  const int seeds = ctx.quick ? 10 : 50;
  const Coverage c = coverageOverSeeds(ctx, seeds);
  const int need = binomialFirstPercentile(seeds, 0.9545);
  std::ostringstream line;
  line << "Coverage over " << seeds << " noise seeds (reduced model, 2.5 s, omega_crank and omega_motor): the 2σ "
       << "interval holds the true coupling.stiffness in " << c.hits[0] << " and the true coupling.damping in "
       << c.hits[1] << " of " << seeds << " fits (nominal 95.45 %, expected " << significant(0.9545 * seeds, 3)
       << "); " << c.converged << " of " << seeds << " converged, " << c.runs << " runs, " << significant(c.wall, 3)
       << " s wall in all. Holds when every fit converged and each count is at least " << need
       << " (the 1st percentile of Binomial(" << seeds << ", 0.9545): fewer hits would have a chance below 1 % "
       << "if the intervals were right)";
  s.claim(c.converged == seeds && c.hits[0] >= need && c.hits[1] >= need, line.str());
}

}  // namespace

ValidationSection identificationChecks(const ItemContext& ctx) {
  ValidationSection s("identify", "Parameter identification from synthetic measurements");
  s.text() << "`rollerdyn identify` on measurements the model makes itself: a start of `balanced-4cart` with the "
              "coupling's true values c = " << formatNumber(kStiffness) << " N·m/rad and k = " << formatNumber(kDamping)
           << " N·m·s/rad (the scene's: 200000 and 8000), run at accuracy 1e-10, every output row measured with "
              "Gaussian noise of 0.2 % of the signal's RMS value (fixed seeds); the search starts from the scene's "
              "values, σ of each signal estimated from the residuals, the last 30 % of the span held out.\n\n";
  claimCircuitMotorCase(s, ctx);
  claimCoverage(s, ctx);
  return s;
}

}  // namespace rollerdyn::validation
