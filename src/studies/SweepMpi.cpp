#include "studies/SweepMpi.h"

#include <chrono>
#include <cstdlib>
#include <deque>
#include <mutex>
#include <stdexcept>
#include <thread>

#include <dlfcn.h>

#include <filesystem>

#include "studies/MpiTransport.h"
#include "studies/SweepProgress.h"

namespace rollerdyn {

MpiLaunch detectMpiLaunch() {
  MpiLaunch l;
  auto size_from = [](const char* name) {
    const char* v = std::getenv(name);
    return v ? std::atoi(v) : 0;
  };
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK", "SLURM_PROCID"}) {
    if (!std::getenv(name)) continue;
    l.launched = true;
    l.variable = name;
    if (l.variable == "OMPI_COMM_WORLD_SIZE" || l.variable == "PMI_SIZE") l.world_size = size_from(name);
    // Tasks of this srun step (not SLURM_NTASKS: a batch script's own shell has that too).
    if (l.variable == "SLURM_PROCID") l.world_size = size_from("SLURM_STEP_NUM_TASKS");
    break;
  }
  return l;
}

#ifdef ROLLERDYN_HAVE_MPI
bool mpiBuilt() { return true; }
#else
bool mpiBuilt() { return false; }
#endif

std::string mpiPluginPath() {
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  return (self.parent_path() / ROLLERDYN_MPI_PLUGIN).string();
}

namespace {

constexpr int kTagResult = 1;  // worker -> rank 0: a finished row (or nothing) and a request
constexpr int kTagWork = 2;    // rank 0 -> worker: a point index
constexpr int kTagStop = 3;    // rank 0 -> worker: no more work
constexpr int kDepth = 2;      // indices a worker holds at most: the one it computes and the next

// The MPI plug-in, opened the first time a sweep needs MPI (MpiTransport.h).
MpiTransport& transport() {
  static MpiTransport* const opened = [] {
    if (!mpiBuilt())
      throw std::runtime_error(
          "sweep: this rollerdyn was built without MPI (CMake did not find it; install libopenmpi-dev and "
          "rebuild), so it cannot share a sweep over the ranks of mpirun or srun; run it without the launcher "
          "(it then uses --threads)");
    const std::string path = mpiPluginPath();
    // RTLD_GLOBAL: the MPI library opens components of its own that expect its symbols global.
    void* library = dlopen(path.c_str(), RTLD_NOW | RTLD_GLOBAL);
    if (!library) {
      const char* why = dlerror();
      throw std::runtime_error("sweep: started by an MPI launcher, but the MPI plug-in " + path +
                               " could not be loaded (" + std::string(why ? why : "unknown reason") +
                               "); it is built beside rollerdyn when CMake finds MPI: rebuild, or run the sweep "
                               "without the launcher (it then uses --threads)");
    }
    auto get = reinterpret_cast<MpiTransport* (*)()>(dlsym(library, "rollerdyn_mpi_transport"));
    if (!get)
      throw std::runtime_error("sweep: the MPI plug-in " + path +
                               " is not rollerdyn's (it lacks the transport function); rebuild rollerdyn");
    return get();
  }();
  return *opened;
}

}  // namespace

MpiWorld startMpi() {
  MpiWorld w;
  transport().start(&w.rank, &w.size);
  return w;
}

namespace {

// Worker: takes what rank 0 sent; waits only when there is nothing to compute. False once rank 0
// said stop (sent only when nothing is queued here).
bool receiveIndices(MpiTransport& mpi, std::deque<unsigned long long>* queue) {
  for (;;) {
    MpiMessage m;
    const bool waiting = mpi.probe(0, MpiTransport::kAnyTag, queue->empty(), &m);
    if (!waiting) return true;
    const unsigned long long index = mpi.receiveIndex(0, m.tag);
    if (m.tag == kTagStop) return false;
    queue->push_back(index);
  }
}

// Worker: keeps up to kDepth indices (the one it computes and the next), so the round trip
// to rank 0 for the next index overlaps the computation instead of idling between points.
// Each message to rank 0 carries one finished row (empty the first time) and asks for more.
void computeForRankZero(MpiTransport& mpi, const std::function<SweepPoint(std::size_t)>& compute) {
  std::deque<unsigned long long> queue;
  std::string payload;
  mpi.sendChars(payload.data(), 0, 0, kTagResult);
  while (receiveIndices(mpi, &queue)) {
    const unsigned long long index = queue.front();
    queue.pop_front();
    const nlohmann::json row = {{"index", index}, {"point", sweepPointToJson(compute(std::size_t(index)))}};
    payload = row.dump();
    mpi.sendChars(payload.data(), int(payload.size()), 0, kTagResult);
  }
}

// Rank 0's one queue of the points not yet handed out, shared by the workers' requests and its own
// computing thread; empty once interrupted.
class PointQueue {
 public:
  PointQueue(const std::vector<std::size_t>& todo, const std::atomic<bool>* interrupt)
      : todo_(todo), interrupt_(interrupt) {}
  bool take(std::size_t* index) {
    std::lock_guard<std::mutex> lock(mu_);
    if (next_ >= todo_.size() || (interrupt_ && interrupt_->load())) return false;
    *index = todo_[next_++];
    return true;
  }

 private:
  const std::vector<std::size_t>& todo_;
  const std::atomic<bool>* interrupt_;
  std::mutex mu_;
  std::size_t next_ = 0;
};

// Rows reach the caller's record one at a time, from rank 0's computing thread and from the workers.
struct RowRecorder {
  const std::function<void(std::size_t, const SweepPoint&, int)>& record;
  std::mutex mu;
  void operator()(std::size_t index, const SweepPoint& p, int rank) {
    std::lock_guard<std::mutex> lock(mu);
    record(index, p, rank);
  }
};

void computeOnRankZero(PointQueue& points, const std::function<SweepPoint(std::size_t)>& compute,
                       RowRecorder& rows) {
  std::size_t i = 0;
  while (points.take(&i)) {
    const SweepPoint p = compute(i);
    rows(i, p, 0);
  }
}

// One worker's message: a finished row, recorded; false when it carried none (its first request).
bool recordRowOf(MpiTransport& mpi, const MpiMessage& m, std::string* buffer, RowRecorder& rows) {
  buffer->assign(std::size_t(m.chars), '\0');
  mpi.receiveChars(buffer->data(), m.chars, m.source, kTagResult);
  if (buffer->empty()) return false;
  const nlohmann::json row = nlohmann::json::parse(*buffer);
  const SweepPoint p = sweepPointFromJson(row.at("point"));
  rows(row.at("index").get<std::size_t>(), p, m.source);
  return true;
}

// Tops a worker up to kDepth indices in flight; with no more work and nothing in flight there it is
// released (false).
bool topUpWorker(MpiTransport& mpi, int worker, PointQueue& points, int* outstanding) {
  std::size_t i = 0;
  while (*outstanding < kDepth && points.take(&i)) {
    mpi.sendIndex(i, worker, kTagWork);
    ++*outstanding;
  }
  if (*outstanding != 0) return true;
  mpi.sendIndex(0, worker, kTagStop);
  return false;
}

// Rank 0 answers the workers until every one is released; returns the time spent on it [s].
double serveWorkers(MpiTransport& mpi, int world_size, PointQueue& points, RowRecorder& rows) {
  int active = world_size - 1;
  std::vector<int> outstanding(std::size_t(world_size), 0);  // indices sent to each worker, rows not yet back
  std::string buffer;
  double busy = 0;  // [s]
  while (active > 0) {
    MpiMessage m;
    if (!mpi.probe(MpiTransport::kAnySource, kTagResult, false, &m)) {
      // Polling with a short sleep, not a blocking receive: Open MPI's blocking calls spin and
      // would take a core from rank 0's computing thread.
      std::this_thread::sleep_for(std::chrono::microseconds(200));
      continue;
    }
    const auto t0 = std::chrono::steady_clock::now();
    int& in_flight = outstanding[std::size_t(m.source)];
    if (recordRowOf(mpi, m, &buffer, rows)) --in_flight;
    if (!topUpWorker(mpi, m.source, points, &in_flight)) --active;
    busy += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
  return busy;
}

}  // namespace

double runMpiSweep(const std::vector<std::size_t>& todo, const std::function<SweepPoint(std::size_t)>& compute,
                   const std::function<void(std::size_t, const SweepPoint&, int)>& record,
                   bool dispatcher_computes, const std::atomic<bool>* interrupt) {
  const MpiWorld w = startMpi();
  MpiTransport& mpi = transport();
  if (w.rank != 0) {
    computeForRankZero(mpi, compute);
    return 0.0;
  }
  // Rank 0: hands out indices from one queue, to the workers and to its own computing thread.
  PointQueue points(todo, interrupt);
  RowRecorder rows{record, {}};
  std::thread local;
  if (dispatcher_computes) local = std::thread([&] { computeOnRankZero(points, compute, rows); });
  const double busy = serveWorkers(mpi, w.size, points, rows);
  if (local.joinable()) local.join();
  // A single rank that only dispatches would compute nothing: compute here instead.
  if (!dispatcher_computes && w.size == 1) computeOnRankZero(points, compute, rows);
  return busy;
}

}  // namespace rollerdyn
