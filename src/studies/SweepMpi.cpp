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

double runMpiSweep(const std::vector<std::size_t>& todo, const std::function<SweepPoint(std::size_t)>& compute,
                   const std::function<void(std::size_t, const SweepPoint&, int)>& record,
                   bool dispatcher_computes, const std::atomic<bool>* interrupt) {
  const MpiWorld w = startMpi();
  MpiTransport& mpi = transport();
  if (w.rank != 0) {
    // Worker: keeps up to kDepth indices (the one it computes and the next), so the round trip
    // to rank 0 for the next index overlaps the computation instead of idling between points.
    // Each message to rank 0 carries one finished row (empty the first time) and asks for more.
    std::deque<unsigned long long> queue;
    std::string payload;
    mpi.sendChars(payload.data(), 0, 0, kTagResult);
    for (;;) {
      for (;;) {  // take what rank 0 sent; wait only when there is nothing to compute
        MpiMessage m;
        const bool waiting = mpi.probe(0, MpiTransport::kAnyTag, queue.empty(), &m);
        if (!waiting) break;
        const unsigned long long index = mpi.receiveIndex(0, m.tag);
        if (m.tag == kTagStop) return 0.0;  // sent only when nothing is queued here
        queue.push_back(index);
      }
      const unsigned long long index = queue.front();
      queue.pop_front();
      const nlohmann::json row = {{"index", index}, {"point", sweepPointToJson(compute(std::size_t(index)))}};
      payload = row.dump();
      mpi.sendChars(payload.data(), int(payload.size()), 0, kTagResult);
    }
  }
  // Rank 0: hands out indices from one queue, to the workers and to its own computing thread.
  std::mutex mu;
  std::size_t next = 0;
  auto take = [&](std::size_t* index) {
    std::lock_guard<std::mutex> lock(mu);
    if (next >= todo.size() || (interrupt && interrupt->load())) return false;
    *index = todo[next++];
    return true;
  };
  std::mutex record_mu;
  std::thread local;
  if (dispatcher_computes)
    local = std::thread([&] {
      std::size_t i = 0;
      while (take(&i)) {
        const SweepPoint p = compute(i);
        std::lock_guard<std::mutex> lock(record_mu);
        record(i, p, 0);
      }
    });
  int active = w.size - 1;
  std::vector<int> outstanding(std::size_t(w.size), 0);  // indices sent to each worker, rows not yet back
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
    buffer.assign(std::size_t(m.chars), '\0');
    mpi.receiveChars(buffer.data(), m.chars, m.source, kTagResult);
    const std::size_t from = std::size_t(m.source);
    if (!buffer.empty()) {
      const nlohmann::json row = nlohmann::json::parse(buffer);
      const SweepPoint p = sweepPointFromJson(row.at("point"));
      --outstanding[from];
      std::lock_guard<std::mutex> lock(record_mu);
      record(row.at("index").get<std::size_t>(), p, m.source);
    }
    std::size_t i = 0;
    while (outstanding[from] < kDepth && take(&i)) {
      mpi.sendIndex(i, m.source, kTagWork);
      ++outstanding[from];
    }
    if (outstanding[from] == 0) {  // no more work and nothing in flight there: release it
      mpi.sendIndex(0, m.source, kTagStop);
      --active;
    }
    busy += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
  if (local.joinable()) local.join();
  if (!dispatcher_computes && w.size == 1) {
    // A single rank that only dispatches would compute nothing: compute here instead.
    std::size_t i = 0;
    while (take(&i)) record(i, compute(i), 0);
  }
  return busy;
}

}  // namespace rollerdyn
