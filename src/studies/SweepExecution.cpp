#include "studies/SweepExecution.h"

#include <chrono>
#include <exception>
#include <functional>
#include <filesystem>
#include <limits>
#include <memory>
#include <mutex>
#include <thread>

#include "studies/SweepMpi.h"
#include "studies/SweepPointBudget.h"
#include "studies/SweepProgress.h"

namespace rollerdyn {

namespace {

// What rank 0 starts a sweep with: the progress file (none without one), an error opening it
// (raised once the workers were told to stop), the points left to compute and how many were resumed.
struct SweepStart {
  std::unique_ptr<SweepProgressFile> progress;
  std::exception_ptr setup_error;
  std::vector<std::size_t> todo;
  std::size_t resumed = 0;
};

// Opens the progress file, takes the points it saved into `points` and lists the others.
SweepStart resumeSweep(const SweepOptions& o, const SweepDesigns& d, std::vector<SweepPoint>& points) {
  SweepStart start;
  const std::size_t n = d.texts.size();
  try {
    if (!o.progress_path.empty())
      start.progress = std::make_unique<SweepProgressFile>(o.progress_path, sweepFingerprint(o, d.texts), n, o.resume);
  } catch (...) {
    start.setup_error = std::current_exception();  // raised after the workers were told to stop
  }
  std::vector<bool> have(n, false);
  if (start.progress)
    for (const auto& [i, p] : start.progress->saved()) {
      points[i] = p;
      have[i] = true;
      ++start.resumed;
    }
  if (!start.setup_error)
    for (std::size_t i = 0; i < n; ++i)
      if (!have[i]) start.todo.push_back(i);
  return start;
}

// The points of todo on this process's threads, each taking the next point left until none is
// (or Ctrl-C); returns the number of threads.
template <class Compute, class Record>
int runOnThreads(const SweepOptions& o, const std::vector<std::size_t>& todo, Compute& compute, Record& record) {
  std::size_t next = 0;
  std::mutex next_mu;
  auto worker = [&] {
    for (;;) {
      std::size_t i = 0;
      {
        std::lock_guard<std::mutex> lock(next_mu);
        if (next >= todo.size() || (o.interrupt && o.interrupt->load())) return;
        i = todo[next++];
      }
      record(i, compute(i), 0);
    }
  };
  const int threads =
      static_cast<int>(std::min<std::size_t>(std::max(1, o.threads), std::max<std::size_t>(todo.size(), 1)));
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (std::thread& t : pool) t.join();
  return threads;
}

// Design i run as a sweep point (in a child process within o.point_budget when one is set).
SweepPoint runDesign(const SweepOptions& o, const SweepDesigns& d, std::size_t i) {
  return o.point_budget > 0 ? runSweepPointWithBudget(o, d.texts[i], d.values[i], o.point_budget)
                            : runSweepPoint(o, d.texts[i], d.values[i]);
}

// Every design as a point not yet run: its values, its metrics NaN.
std::vector<SweepPoint> pointsNotYetRun(const SweepDesigns& d) {
  std::vector<SweepPoint> points;
  for (std::size_t i = 0; i < d.texts.size(); ++i) points.push_back(pointNotRun(d.texts[i], d.values[i]));
  return points;
}

// The points as they finish, from any thread or rank: into their place, counted per rank, saved to
// the progress file and shown.
struct FinishedPoints {
  const SweepOptions& o;
  std::vector<SweepPoint>& points;
  SweepProgressFile* progress;
  std::vector<std::size_t> per_rank;
  std::size_t resumed = 0;
  std::size_t done = 0, computed = 0;
  std::mutex mu;

  void operator()(std::size_t i, const SweepPoint& p, int rank) {
    std::lock_guard<std::mutex> lock(mu);
    points[i] = p;
    ++per_rank[std::size_t(rank)];
    ++computed;
    ++done;
    // A point that ends after Ctrl-C may have been cut short: shown, but not saved as finished.
    if (progress && !(o.interrupt && o.interrupt->load())) progress->append(i, points[i]);
    if (o.on_point) o.on_point(points[i], done, points.size());
  }
};

// How the sweep ran: ranks, points per rank, threads, computed and resumed points, wall time.
nlohmann::json executionJson(const SweepOptions& o, const FinishedPoints& f, int threads_per_rank,
                             double wall_seconds) {
  return {{"ranks", f.per_rank.size()},
          {"points_per_rank", f.per_rank},
          {"threads_per_rank", threads_per_rank},
          {"points_computed", f.computed},
          {"points_resumed", f.resumed},
          {"wall_seconds", wall_seconds},
          {"progress_file", o.progress_path.empty() ? std::string() : std::filesystem::path(o.progress_path).filename().string()},
          {"point_budget_cpu_seconds", o.point_budget}};
}

// The points of todo: over the MPI ranks (rank 0's dispatch time into *dispatcher_busy), else on
// this process's threads. Returns the threads per rank.
int computePoints(const SweepOptions& o, const std::vector<std::size_t>& todo,
                  const std::function<SweepPoint(std::size_t)>& compute, FinishedPoints& finished,
                  double* dispatcher_busy) {
  if (!o.mpi) return runOnThreads(o, todo, compute, finished);
  *dispatcher_busy = runMpiSweep(todo, compute, std::ref(finished), o.dispatcher_computes, o.interrupt);
  return 1;
}

void markNotRunAsInterrupted(std::vector<SweepPoint>& points) {
  for (SweepPoint& p : points)
    if (p.status == "not run") p.status = "not run (interrupted)";
}

}  // namespace

std::vector<SweepPoint> executeSweep(const SweepOptions& o, const SweepDesigns& d, SweepResult& result) {
  const auto wall0 = std::chrono::steady_clock::now();
  std::vector<SweepPoint> points = pointsNotYetRun(d);
  const std::function<SweepPoint(std::size_t)> compute = [&](std::size_t i) { return runDesign(o, d, i); };
  const MpiWorld world = o.mpi ? startMpi() : MpiWorld{};
  const bool rank0 = world.rank == 0;

  // Rank 0 alone reads and writes the progress file and decides what is left to compute.
  SweepStart start;
  if (rank0) start = resumeSweep(o, d, points);
  FinishedPoints finished{o, points, start.progress.get(), std::vector<std::size_t>(std::size_t(world.size), 0),
                          start.resumed, start.resumed, 0, {}};
  double dispatcher_busy = 0;
  const int threads = computePoints(o, start.todo, compute, finished, &dispatcher_busy);
  if (start.setup_error) std::rethrow_exception(start.setup_error);

  result.output_rank = rank0;
  if (!rank0) return {};
  if (o.interrupt && o.interrupt->load()) markNotRunAsInterrupted(points);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  result.execution = executionJson(o, finished, o.mpi ? 1 : threads, wall);
  if (o.mpi) result.execution["dispatcher_busy_seconds"] = dispatcher_busy;
  return points;
}

}  // namespace rollerdyn
