#include "studies/SweepMpi.h"

#include <chrono>
#include <cstdlib>
#include <deque>
#include <mutex>
#include <stdexcept>
#include <thread>

#ifdef ROLLERDYN_HAVE_MPI
#include <mpi.h>
#endif

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

namespace {

constexpr int kTagResult = 1;  // worker -> rank 0: a finished row (or nothing) and a request
constexpr int kTagWork = 2;    // rank 0 -> worker: a point index
constexpr int kTagStop = 3;    // rank 0 -> worker: no more work
constexpr int kDepth = 2;      // indices a worker holds at most: the one it computes and the next

void finalizeAtExit() {
  int initialized = 0, finalized = 0;
  MPI_Initialized(&initialized);
  MPI_Finalized(&finalized);
  if (initialized && !finalized) MPI_Finalize();
}

}  // namespace

MpiWorld startMpi() {
  int initialized = 0;
  MPI_Initialized(&initialized);
  if (!initialized) {
    // FUNNELED: only the main thread calls MPI; rank 0's computing thread never does.
    int provided = 0;
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
    std::atexit(finalizeAtExit);
  }
  MpiWorld w;
  MPI_Comm_rank(MPI_COMM_WORLD, &w.rank);
  MPI_Comm_size(MPI_COMM_WORLD, &w.size);
  return w;
}

double runMpiSweep(const std::vector<std::size_t>& todo, const std::function<SweepPoint(std::size_t)>& compute,
                   const std::function<void(std::size_t, const SweepPoint&, int)>& record,
                   bool dispatcher_computes, const std::atomic<bool>* interrupt) {
  const MpiWorld w = startMpi();
  if (w.rank != 0) {
    // Worker: keeps up to kDepth indices (the one it computes and the next), so the round trip
    // to rank 0 for the next index overlaps the computation instead of idling between points.
    // Each message to rank 0 carries one finished row (empty the first time) and asks for more.
    std::deque<unsigned long long> queue;
    std::string payload;
    MPI_Send(payload.data(), 0, MPI_CHAR, 0, kTagResult, MPI_COMM_WORLD);
    for (;;) {
      for (;;) {  // take what rank 0 sent; wait only when there is nothing to compute
        int flag = 0;
        MPI_Status st;
        MPI_Iprobe(0, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &st);
        if (!flag && !queue.empty()) break;
        if (!flag) MPI_Probe(0, MPI_ANY_TAG, MPI_COMM_WORLD, &st);
        unsigned long long index = 0;
        MPI_Recv(&index, 1, MPI_UNSIGNED_LONG_LONG, 0, st.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        if (st.MPI_TAG == kTagStop) return 0.0;  // sent only when nothing is queued here
        queue.push_back(index);
      }
      const unsigned long long index = queue.front();
      queue.pop_front();
      const nlohmann::json row = {{"index", index}, {"point", sweepPointToJson(compute(std::size_t(index)))}};
      payload = row.dump();
      MPI_Send(payload.data(), int(payload.size()), MPI_CHAR, 0, kTagResult, MPI_COMM_WORLD);
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
    int flag = 0;
    MPI_Status st;
    MPI_Iprobe(MPI_ANY_SOURCE, kTagResult, MPI_COMM_WORLD, &flag, &st);
    if (!flag) {
      // Polling with a short sleep, not a blocking receive: Open MPI's blocking calls spin and
      // would take a core from rank 0's computing thread.
      std::this_thread::sleep_for(std::chrono::microseconds(200));
      continue;
    }
    const auto t0 = std::chrono::steady_clock::now();
    int count = 0;
    MPI_Get_count(&st, MPI_CHAR, &count);
    buffer.assign(std::size_t(count), '\0');
    MPI_Recv(buffer.data(), count, MPI_CHAR, st.MPI_SOURCE, kTagResult, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    const std::size_t from = std::size_t(st.MPI_SOURCE);
    if (!buffer.empty()) {
      const nlohmann::json row = nlohmann::json::parse(buffer);
      const SweepPoint p = sweepPointFromJson(row.at("point"));
      --outstanding[from];
      std::lock_guard<std::mutex> lock(record_mu);
      record(row.at("index").get<std::size_t>(), p, st.MPI_SOURCE);
    }
    std::size_t i = 0;
    while (outstanding[from] < kDepth && take(&i)) {
      unsigned long long index = i;
      MPI_Send(&index, 1, MPI_UNSIGNED_LONG_LONG, st.MPI_SOURCE, kTagWork, MPI_COMM_WORLD);
      ++outstanding[from];
    }
    if (outstanding[from] == 0) {  // no more work and nothing in flight there: release it
      unsigned long long none = 0;
      MPI_Send(&none, 1, MPI_UNSIGNED_LONG_LONG, st.MPI_SOURCE, kTagStop, MPI_COMM_WORLD);
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

#else  // built without MPI

bool mpiBuilt() { return false; }

MpiWorld startMpi() {
  throw std::runtime_error(
      "sweep: this rollerdyn was built without MPI (CMake did not find it; install libopenmpi-dev and "
      "rebuild), so it cannot share a sweep over the ranks of mpirun or srun; run it without the launcher "
      "(it then uses --threads)");
}

double runMpiSweep(const std::vector<std::size_t>&, const std::function<SweepPoint(std::size_t)>&,
                   const std::function<void(std::size_t, const SweepPoint&, int)>&, bool,
                   const std::atomic<bool>*) {
  startMpi();
  return 0.0;
}

#endif

}  // namespace rollerdyn
