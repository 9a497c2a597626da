#include "studies/Optimizer.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <map>
#include <mutex>
#include <thread>
#include <sstream>
#include <stdexcept>

#include <nlopt.hpp>

#include "studies/OptimizeGrid.h"
#include "studies/OptimizeOptions.h"
#include "scene/SceneSchema.h"

namespace rollerdyn {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

nlopt::algorithm algorithmOf(const std::string& method) {
  if (method == "bobyqa") return nlopt::LN_BOBYQA;
  if (method == "cobyla") return nlopt::LN_COBYLA;
  if (method == "direct-l") return nlopt::GN_DIRECT_L;
  return nlopt::GN_CRS2_LM;  // crs2
}

std::string resultText(nlopt::result r) {
  switch (r) {
    case nlopt::SUCCESS: return "success";
    case nlopt::STOPVAL_REACHED: return "objective reached the stop value";
    case nlopt::FTOL_REACHED: return "objective change below tolerance";
    case nlopt::XTOL_REACHED: return "step below the parameter tolerance";
    case nlopt::MAXEVAL_REACHED: return "maximum number of evaluations reached";
    case nlopt::MAXTIME_REACHED: return "time limit reached";
    default: return "stopped (NLopt result " + std::to_string(int(r)) + ")";
  }
}

// Why a design's run is no usable answer ("" when it is): it did not complete, did not reach steady
// state, or the crank does not turn steadily.
std::string unusableRunReason(const SweepPoint& p) {
  const double omega_min = p.metric("omega_crank_min");
  if (!p.complete) return "did not complete: " + p.status;
  if (!p.steady)
    return "no steady state by t_end (a longer simulation.t_end, or a start at speed with "
           "initial.crank_speed, may settle it)";
  if (!(omega_min > 0)) {
    std::ostringstream os;
    os << "the crank does not turn steadily (rocks or stops): omega_crank_min = " << omega_min << " rad/s";
    return os.str();
  }
  return "";
}

// The search: evaluations in the unit box u in [0,1]^n (x = lower + u·(upper − lower)), so a
// step means the same fraction of every range whatever its unit; NLopt's callbacks go through
// it. Objective and constraints of one design come from one run (cache by the texts applied).
class Search {
 public:
  Search(const OptimizeOptions& o, OptimizeResult& r) : o_(o), r_(r) {
    sweep_.scene_path = o.scene_path;
    sweep_.scene_input = o.scene_input;
    sweep_.base_overrides = o.base_overrides;
    sweep_.model = o.model;
    sweep_.interrupt = o.interrupt;
    for (const SampleRange& p : o.params) {
      SweepParameter sp;
      sp.key = p.key;
      sweep_.params.push_back(sp);
    }
  }

  // The design at u, run now unless already evaluated. Thread-safe: the runs of parallel local
  // searches (multistart) proceed side by side; history, cache and bounds are guarded.
  OptimizeEvaluation evaluate(const std::vector<double>& u) {
    OptimizeEvaluation e = designAt(u);
    {
      std::lock_guard<std::mutex> lock(mu_);
      ++r_.requests;
      const auto hit = cache_.find(e.texts);
      if (hit != cache_.end()) return r_.history[hit->second];
    }
    e.point = runSweepPoint(sweep_, e.texts, e.x);
    judge(e);
    return keep(e);
  }

  std::size_t requests() {
    std::lock_guard<std::mutex> lock(mu_);
    return r_.requests;
  }

  // What NLopt minimises. Usable designs that keep the constraints: the objective. Otherwise a
  // value above every usable one seen (hi + span·(1 + violation)), so a failed, stalled or
  // violating design never looks best; with COBYLA the constraints carry the violation instead.
  double seen(const OptimizeEvaluation& e, bool constraints_by_method) {
    std::lock_guard<std::mutex> lock(mu_);
    // Before the first usable run there is no scale yet (hi_ = -inf, lo_ = +inf): a fixed, finite
    // stand-in (the upper bound of the minimised parameter, or 1), never inf or NaN, which
    // NLopt's models would turn into NaN steps.
    const bool scaled = std::isfinite(hi_) && std::isfinite(lo_);
    double fallback = 1.0;
    for (const SampleRange& p : o_.params)
      if (p.key == o_.minimize) fallback = p.upper;
    const double top = scaled ? hi_ : fallback;
    const double span = scaled ? std::max({hi_ - lo_, 1e-3 * std::abs(hi_), 1e-12}) : std::max(1.0, std::abs(fallback));
    double value = top + 10.0 * span;
    if (e.run_ok && (constraints_by_method || e.constraints_hold)) {
      value = e.objective;
    } else if (e.run_ok) {
      double violation = 0;
      for (std::size_t j = 0; j < e.constraint_values.size(); ++j)
        violation += std::max(0.0, e.constraint_values[j]) / std::max(std::abs(o_.constraints[j].bound), 1e-12);
      value = top + span * (1.0 + std::min(violation, 1e6));
    }
    value = std::isfinite(value) ? value : top + 10.0 * span;
    r_.values_handed.push_back(value);
    return value;
  }

  // Constraint j as COBYLA sees it (<= 0 holds); a design that did not run usably violates all.
  double constraintSeen(const OptimizeEvaluation& e, std::size_t j) const {
    if (!e.run_ok || !std::isfinite(e.constraint_values[j])) return std::abs(o_.constraints[j].bound) + 1.0;
    return e.constraint_values[j];
  }

  const OptimizeOptions& options() const { return o_; }
  std::string method;  // the NLopt method running now (COBYLA takes the constraints itself)
  OptimizeResult& result() { return r_; }

 private:
  // The design at scaled point u: each parameter's value as --set applies it, and that value.
  OptimizeEvaluation designAt(const std::vector<double>& u) const {
    OptimizeEvaluation e;
    for (std::size_t k = 0; k < u.size(); ++k) {
      const SampleRange& p = o_.params[k];
      const double x = p.lower + std::clamp(u[k], 0.0, 1.0) * (p.upper - p.lower);
      e.texts.push_back(formatNumber(x));
      e.x.push_back(std::stod(e.texts.back()));  // the value the run used
    }
    return e;
  }

  // A judged evaluation into the history and the cache (unless another search ran it meanwhile),
  // the usable objectives' range widened, and the caller told.
  OptimizeEvaluation keep(const OptimizeEvaluation& e) {
    std::lock_guard<std::mutex> lock(mu_);
    const auto hit = cache_.find(e.texts);  // another search may have run it meanwhile
    if (hit != cache_.end()) return r_.history[hit->second];
    r_.history.push_back(e);
    const std::size_t index = r_.history.size() - 1;
    cache_.emplace(e.texts, index);
    if (e.run_ok) {
      lo_ = std::min(lo_, e.objective);
      hi_ = std::max(hi_, e.objective);
    }
    if (o_.on_evaluation) o_.on_evaluation(r_.history.back(), index + 1);
    return e;
  }

  // The objective: the caller's function (of usable runs only), the minimised parameter's value,
  // or the metric.
  double objectiveOf(const OptimizeEvaluation& e, bool usable) const {
    if (o_.objective) return usable ? o_.objective(e) : kNaN;
    double objective = kNaN;
    for (std::size_t k = 0; k < o_.params.size(); ++k)
      if (o_.params[k].key == o_.minimize) objective = e.x[k];
    return std::isfinite(objective) ? objective : e.point.metric(o_.minimize);
  }

  // Each constraint's quantity and its value as NLopt's constraints take it (<= 0 holds).
  void constraintsOf(OptimizeEvaluation& e, bool usable) const {
    for (const OptimizeConstraint& c : o_.constraints) {
      const double m = c.value ? (usable ? c.value(e) : kNaN) : e.point.metric(c.metric);
      e.constraint_metrics.push_back(m);
      e.constraint_values.push_back(c.upper ? m - c.bound : c.bound - m);
    }
  }

  void judge(OptimizeEvaluation& e) const {
    e.reason = unusableRunReason(e.point);
    const bool usable = e.reason.empty();  // the caller's functions see usable runs only
    e.objective = objectiveOf(e, usable);
    constraintsOf(e, usable);
    if (usable) {
      if (!std::isfinite(e.objective)) {
        e.reason = o_.minimize + " not available";
      } else {
        for (std::size_t j = 0; j < e.constraint_values.size(); ++j)
          if (!std::isfinite(e.constraint_values[j])) e.reason = o_.constraints[j].metric + " not available";
      }
    }
    e.run_ok = e.reason.empty();
    e.constraints_hold = e.run_ok;
    for (double g : e.constraint_values) e.constraints_hold = e.constraints_hold && g <= 0.0;
  }

  const OptimizeOptions& o_;
  OptimizeResult& r_;
  SweepOptions sweep_;
  std::map<std::vector<std::string>, std::size_t> cache_;
  std::mutex mu_;
  double lo_ = std::numeric_limits<double>::infinity(), hi_ = -std::numeric_limits<double>::infinity();
};

struct ConstraintRef {
  Search* search;
  std::size_t j;
};

double objectiveCallback(const std::vector<double>& u, std::vector<double>&, void* data) {
  Search& s = *static_cast<Search*>(data);
  if (s.options().interrupt && s.options().interrupt->load()) throw nlopt::forced_stop();
  return s.seen(s.evaluate(u), s.method == "cobyla");
}

double constraintCallback(const std::vector<double>& u, std::vector<double>&, void* data) {
  const ConstraintRef& c = *static_cast<ConstraintRef*>(data);
  return c.search->constraintSeen(c.search->evaluate(u), c.j);
}

// Runs opt from u: the words of why it stopped, an interrupt or NLopt's failure among them.
std::string stoppingReason(nlopt::opt& opt, std::vector<double>& u) {
  double seen = 0;
  try {
    return resultText(opt.optimize(u, seen));
  } catch (const nlopt::forced_stop&) {
    return "interrupted";
  } catch (const nlopt::roundoff_limited&) {
    return "stopped by round-off (no further progress possible)";
  } catch (const std::exception& e) {
    return std::string("NLopt failed: ") + e.what();
  }
}

// One NLopt run of `method` from u (unit box) with at most max_evals evaluations; the words of
// its stopping reason.
std::string runMethod(Search& search, const std::string& method, std::vector<double> u, int max_evals,
                      double initial_step) {
  const OptimizeOptions& o = search.options();
  const unsigned n = unsigned(o.params.size());
  nlopt::opt opt(algorithmOf(method), n);
  opt.set_lower_bounds(std::vector<double>(n, 0.0));
  opt.set_upper_bounds(std::vector<double>(n, 1.0));
  opt.set_min_objective(objectiveCallback, &search);
  std::vector<ConstraintRef> refs;
  for (std::size_t j = 0; j < o.constraints.size(); ++j) refs.push_back({&search, j});
  if (method == "cobyla")
    for (ConstraintRef& c : refs) opt.add_inequality_constraint(constraintCallback, &c, 0.0);
  opt.set_xtol_abs(o.x_tolerance);
  opt.set_maxeval(max_evals);
  opt.set_initial_step(initial_step);
  return stoppingReason(opt, u);
}

// Index of the feasible evaluation with the lowest objective; false when none is feasible.
bool bestFeasible(const OptimizeResult& r, std::size_t* best) {
  bool found = false;
  for (std::size_t i = 0; i < r.history.size(); ++i) {
    const OptimizeEvaluation& e = r.history[i];
    if (e.feasible() && (!found || e.objective < r.history[*best].objective)) {
      found = true;
      *best = i;
    }
  }
  return found;
}

// Design x in the unit box of the parameters' ranges.
std::vector<double> inUnitBox(const OptimizeOptions& o, const std::vector<double>& x) {
  std::vector<double> u;
  for (std::size_t k = 0; k < o.params.size(); ++k)
    u.push_back((x[k] - o.params[k].lower) / (o.params[k].upper - o.params[k].lower));
  return u;
}

// Local searches from the middle of the box and from a Latin hypercube of further starts, one per
// thread, side by side; each gets an equal share of the evaluations.
void runMultistart(const OptimizeOptions& o, const std::string& local, Search& search, OptimizeResult& r) {
  const int starts = std::max(1, std::min(o.threads, o.max_evals));
  std::vector<SampleRange> unit;
  for (std::size_t k = 0; k < o.params.size(); ++k) unit.push_back({o.params[k].key, 0.0, 1.0});
  std::vector<std::vector<double>> u0(1, std::vector<double>(o.params.size(), 0.5));
  if (starts > 1)
    for (const auto& texts : latinHypercube(unit, std::size_t(starts - 1), 1)) {
      std::vector<double> u;
      for (const std::string& t : texts) u.push_back(std::stod(t));
      u0.push_back(u);
    }
  search.method = local;
  std::vector<std::string> reasons(static_cast<std::size_t>(starts));
  std::vector<std::thread> pool;
  for (int t = 0; t < starts; ++t)
    pool.emplace_back([&, t] { reasons[std::size_t(t)] = runMethod(search, local, u0[std::size_t(t)],
                                                                   std::max(1, o.max_evals / starts), 0.1); });
  for (std::thread& th : pool) th.join();
  r.method = "multistart " + local + " x" + std::to_string(starts);
  r.scope = "local searches from " + std::to_string(starts) + " starts: the best of their minima (more starts, "
            "--threads, cover the ranges better)";
  for (int t = 0; t < starts; ++t) r.stop_reason += (t ? "; " : "") + std::string("start ") + std::to_string(t + 1) +
                                                    ": " + reasons[std::size_t(t)];
  r.found = bestFeasible(r, &r.best);
}

// Every design of the grid, on --threads threads (until an interrupt).
void evaluateAll(const OptimizeOptions& o, const std::vector<std::vector<double>>& grid, Search& search) {
  std::vector<std::thread> pool;
  std::atomic<std::size_t> next{0};
  for (int t = 0; t < std::max(1, o.threads); ++t)
    pool.emplace_back([&] {
      for (std::size_t i = next++; i < grid.size(); i = next++) {
        if (o.interrupt && o.interrupt->load()) return;
        search.evaluate(grid[i]);
      }
    });
  for (std::thread& th : pool) th.join();
}

// Whether the best design lies in another basin than the local search's best x_local (farther
// than ten times the tolerance in some parameter; any basin when the local search found none).
bool inAnotherBasin(const OptimizeOptions& o, const OptimizeResult& r, bool local_found,
                    const std::vector<double>& x_local) {
  bool elsewhere = r.found && !local_found;
  if (r.found && local_found)
    for (std::size_t k = 0; k < o.params.size(); ++k)
      elsewhere = elsewhere || std::abs(r.history[r.best].x[k] - x_local[k]) >
                                   10.0 * o.x_tolerance * (o.params[k].upper - o.params[k].lower);
  return elsewhere;
}

// auto: (1) the local method from the middle of the box, the cheap answer when there is one
// minimum; (2) a global stage: a uniform grid over the whole box, plus, for the crank offset, the
// evenly spread layouts Δφ = k·360°/n of the n carts (they cancel every harmonic of the load below
// the n-th, so δ has a sharp minimum there, which a grid or DIRECT's trisection can step over: six
// carts, δ = 0.0002 at 60° against 0.1 at 55° and 65°); (3) the local method again from the best
// design when it lies in another basin than (1)'s. A local method alone converges to the minimum
// nearest its start (six carts: 97.4° from the middle of 0:180).
// What auto did, in words: the trial read "polished by bobyqa" where no evaluation was left for it.
std::string automaticScope(const std::string& local, bool polish, bool elsewhere) {
  return std::string("global: ") + local + " from the middle of the ranges, a grid over the whole ranges" +
         (polish      ? ", whose best design lay in another basin and was polished by " + local
          : elsewhere ? ", whose best design lay in another basin; no evaluations were left to polish it "
                        "(raise --max-evals), so the optimum is the best grid design"
                      : " (no better basin found)");
}

// auto's global stage: the grid over the whole box, as much of it as the evaluations left allow
// (none after an interrupted first stage).
void runGridStage(const OptimizeOptions& o, const std::string& first, Search& search, OptimizeResult& r) {
  std::vector<std::vector<double>> grid = globalGrid(o);
  const int left = o.max_evals - int(search.requests());
  if (int(grid.size()) > left) grid.resize(std::size_t(std::max(0, left)));
  if (first != "interrupted" && !grid.empty()) {
    evaluateAll(o, grid, search);
    r.stop_reason += "; grid of " + std::to_string(grid.size()) + " designs over the whole ranges";
  }
}

// auto's third stage: the local method again from the grid's best design, with the evaluations
// left; false when none are left or the search was interrupted.
bool runPolishStage(const OptimizeOptions& o, const std::string& local, Search& search, OptimizeResult& r) {
  const int left = o.max_evals - int(search.requests());
  const bool interrupted = o.interrupt && o.interrupt->load();
  if (left <= 0 || interrupted) return false;
  search.method = local;
  r.stop_reason += "; " + local + " from the grid's best: " +
                   runMethod(search, local, inUnitBox(o, r.history[r.best].x), left, 0.02);
  r.found = bestFeasible(r, &r.best);
  return true;
}

void runAutomatic(const OptimizeOptions& o, const std::string& local, Search& search, OptimizeResult& r) {
  search.method = local;
  const int first_share = std::max(1, o.max_evals / 3);
  const std::string first = runMethod(search, local, std::vector<double>(o.params.size(), 0.5), first_share, 0.25);
  // Its budget is a third of --max-evals: "maximum number of evaluations reached" after 10 of
  // 30 read as a contradiction in the trial.
  r.stop_reason = local + " from the middle (its share: " + std::to_string(first_share) + " of the " +
                  std::to_string(o.max_evals) + " evaluations): " + first;
  std::size_t local_best = 0;
  const bool local_found = bestFeasible(r, &local_best);
  const std::vector<double> x_local = local_found ? r.history[local_best].x : std::vector<double>{};
  runGridStage(o, first, search, r);
  r.found = bestFeasible(r, &r.best);
  const bool elsewhere = inAnotherBasin(o, r, local_found, x_local);
  const bool polish = elsewhere && runPolishStage(o, local, search, r);
  r.method = local + ", grid" + (polish ? ", " + local : std::string());
  r.scope = automaticScope(local, polish, elsewhere);
}

// The method asked for by name: a local one from the middle of the box, or a global one followed
// by a local polish of its best design.
void runNamedMethod(const OptimizeOptions& o, const std::string& local, Search& search, OptimizeResult& r) {
  const bool global = r.method == "direct-l" || r.method == "crs2";
  // A global method gets 70 % of the evaluations; the rest polish its best design with the
  // local method (a global search stops far from the exact optimum, and a local one alone may
  // stop at the wrong one of several minima).
  // auto gives the global stage 20 evaluations per parameter at most (DIRECT-L then has sampled
  // every third of the range at least twice over), leaving the rest for the polish.
  const int global_evals = global ? std::max(1, int(0.7 * o.max_evals)) : o.max_evals;
  // Start in the middle of the box with steps of a quarter of each range.
  search.method = r.method;
  r.stop_reason = runMethod(search, r.method, std::vector<double>(o.params.size(), 0.5), global_evals, 0.25);
  r.found = bestFeasible(r, &r.best);
  if (!global) r.scope = "local: " + r.method + " from the middle of the ranges finds the minimum nearest to that "
                         "start, which need not be the global one (--method auto, direct-l, crs2 or multistart "
                         "search the whole ranges)";
  else r.scope = "global stage " + r.method + " over the whole ranges, then a local polish";
  const int left = o.max_evals - int(search.requests());
  if (global && r.found && left > 0 && r.stop_reason != "interrupted") {
    search.method = local;
    const std::string polish = runMethod(search, local, inUnitBox(o, r.history[r.best].x), left, 0.05);
    r.method += " then " + local;
    r.stop_reason += "; " + local + ": " + polish;
    r.found = bestFeasible(r, &r.best);
  }
}

}  // namespace

OptimizeResult runOptimize(const OptimizeOptions& o) {
  validateOptimizeOptions(o);
  OptimizeResult r;
  r.method = o.method;
  Search search(o, r);
  const std::string local = o.constraints.empty() ? "bobyqa" : "cobyla";
  if (r.method == "multistart")
    runMultistart(o, local, search, r);
  else if (o.method == "auto")
    runAutomatic(o, local, search, r);
  else
    runNamedMethod(o, local, search, r);
  return r;
}

}  // namespace rollerdyn
