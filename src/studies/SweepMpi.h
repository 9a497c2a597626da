// Sweeps over MPI ranks (`mpirun -n N rollerdyn sweep ...`, `srun rollerdyn sweep ...`): MPI does
// the transport, rank 0 hands out point indices on request and collects the rows (dynamic load
// balancing: points differ 100x in cost, so a static split would leave ranks idle), workers
// compute one point at a time. MPI is started only when an MPI launcher started this process
// (its environment: OMPI_COMM_WORLD_SIZE, PMI_SIZE, PMIX_RANK or SLURM_PROCID), so a plain
// `rollerdyn` never touches MPI. The MPI library itself is loaded only then, from a plug-in next
// to the program (MpiTransport.h), built when CMake finds MPI (ROLLERDYN_HAVE_MPI): a plain
// `rollerdyn` does not load it at all.
#pragma once

#include <atomic>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "studies/Sweep.h"

namespace rollerdyn {

// Whether the environment says an MPI launcher (mpirun, srun, ...) started this process, and the
// number of processes it started when it says so (0 when unknown). `variable` names the evidence.
struct MpiLaunch {
  bool launched = false;   // an MPI launcher's variable is set
  int world_size = 0;      // processes launched, from the launcher's variables; 0: unknown
  std::string variable;    // the variable found, e.g. OMPI_COMM_WORLD_SIZE
};
MpiLaunch detectMpiLaunch();

// Whether this rollerdyn was built with MPI (its MPI plug-in was built beside it).
bool mpiBuilt();

// Where the MPI plug-in is looked for: the folder of the running program (/proc/self/exe).
std::string mpiPluginPath();

// MPI_Init (once; MPI_Finalize at exit) and this process's rank and the number of ranks. Opens
// the MPI plug-in the first time. Throws std::runtime_error when built without MPI or when the
// plug-in cannot be loaded (the message names its path and the loader's reason).
struct MpiWorld {
  int rank = 0;   // this process, 0 .. size-1
  int size = 1;   // number of ranks
};
MpiWorld startMpi();

// Computes the points `todo` (indices into the designs) on every rank. Call on every rank with
// the same compute. On rank 0, record(index, point, rank) is called for every finished point,
// serialised, with the rank that computed it; workers return when rank 0 has no more work. On
// rank 0, interrupt stops handing out points (the ones in flight are still collected).
// dispatcher_computes: rank 0 also computes points on one thread beside the dispatching.
// Returns, on rank 0, the wall time its main thread spent serving workers' messages (receive,
// read the row, record it, reply) [s]: divided by the points, the service time that bounds how
// many ranks one dispatcher can feed; 0 on workers.
double runMpiSweep(const std::vector<std::size_t>& todo, const std::function<SweepPoint(std::size_t)>& compute,
                 const std::function<void(std::size_t, const SweepPoint&, int)>& record,
                 bool dispatcher_computes, const std::atomic<bool>* interrupt);

}  // namespace rollerdyn
