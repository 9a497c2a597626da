// The MPI calls of a sweep over ranks (SweepMpi.cpp), behind a plug-in: the MPI library and its
// dependencies (Open MPI: nine shared libraries with hwloc and libevent) cost a plain
// `rollerdyn` a quarter of its start-up's CPU in dynamic loading and relocations, and only
// `rollerdyn sweep` under mpirun/srun needs them. The plug-in (studies/mpi/MpiPlugin.cpp, built
// when CMake finds MPI, as librollerdyn_mpi.so next to the program) implements this interface;
// SweepMpi.cpp opens it with dlopen() only when an MPI launcher started the process. The plug-in holds no rollerdyn code:
// it moves bytes and point indices, the sweep's logic stays in SweepMpi.cpp.
#pragma once

namespace rollerdyn {

// A message waiting to be received.
struct MpiMessage {
  int source = 0;  // the sending rank
  int tag = 0;     // its tag
  int chars = 0;   // its length in characters (a message of characters)
};

class MpiTransport {
 public:
  static constexpr int kAnySource = -1;  // probe: from any rank
  static constexpr int kAnyTag = -1;     // probe: any tag

  virtual ~MpiTransport() = default;
  // MPI_Init_thread (MPI_THREAD_FUNNELED: only the main thread calls MPI) the first time, with
  // MPI_Finalize at exit; this process's rank and the number of ranks of the world.
  virtual void start(int* rank, int* size) = 0;
  // Whether a message from `source` with `tag` waits (wait: block until one does), and which.
  virtual bool probe(int source, int tag, bool wait, MpiMessage* message) = 0;
  // A message of `n` characters, and its receipt into `data` (n characters of room).
  virtual void sendChars(const char* data, int n, int dest, int tag) = 0;
  virtual void receiveChars(char* data, int n, int source, int tag) = 0;
  // A message of one point index, and its receipt.
  virtual void sendIndex(unsigned long long index, int dest, int tag) = 0;
  virtual unsigned long long receiveIndex(int source, int tag) = 0;
};

}  // namespace rollerdyn

// The plug-in's one exported function (C linkage, looked up by name with dlsym): its transport,
// one per process, never destroyed.
extern "C" rollerdyn::MpiTransport* rollerdyn_mpi_transport();
