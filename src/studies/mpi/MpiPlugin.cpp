// The MPI plug-in (librollerdyn_mpi.so, studies/MpiTransport.h): the only code of rollerdyn that
// links the MPI library. Opened by SweepMpi.cpp when an MPI launcher started the process.
#include <mpi.h>

#include <cstdlib>

#include "studies/MpiTransport.h"

namespace rollerdyn {
namespace {

void finalizeAtExit() {
  int initialized = 0, finalized = 0;
  MPI_Initialized(&initialized);
  MPI_Finalized(&finalized);
  if (initialized && !finalized) MPI_Finalize();
}

class MpiLibraryTransport final : public MpiTransport {
 public:
  void start(int* rank, int* size) override {
    int initialized = 0;
    MPI_Initialized(&initialized);
    if (!initialized) {
      int provided = 0;
      MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
      std::atexit(finalizeAtExit);
    }
    MPI_Comm_rank(MPI_COMM_WORLD, rank);
    MPI_Comm_size(MPI_COMM_WORLD, size);
  }

  bool probe(int source, int tag, bool wait, MpiMessage* message) override {
    const int src = source == kAnySource ? MPI_ANY_SOURCE : source;
    const int tg = tag == kAnyTag ? MPI_ANY_TAG : tag;
    MPI_Status st;
    int flag = 1;
    if (wait)
      MPI_Probe(src, tg, MPI_COMM_WORLD, &st);
    else
      MPI_Iprobe(src, tg, MPI_COMM_WORLD, &flag, &st);
    if (!flag) return false;
    message->source = st.MPI_SOURCE;
    message->tag = st.MPI_TAG;
    MPI_Get_count(&st, MPI_CHAR, &message->chars);
    return true;
  }

  void sendChars(const char* data, int n, int dest, int tag) override {
    MPI_Send(data, n, MPI_CHAR, dest, tag, MPI_COMM_WORLD);
  }
  void receiveChars(char* data, int n, int source, int tag) override {
    MPI_Recv(data, n, MPI_CHAR, source, tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  }
  void sendIndex(unsigned long long index, int dest, int tag) override {
    MPI_Send(&index, 1, MPI_UNSIGNED_LONG_LONG, dest, tag, MPI_COMM_WORLD);
  }
  unsigned long long receiveIndex(int source, int tag) override {
    unsigned long long index = 0;
    MPI_Recv(&index, 1, MPI_UNSIGNED_LONG_LONG, source, tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    return index;
  }
};

}  // namespace
}  // namespace rollerdyn

extern "C" __attribute__((visibility("default"))) rollerdyn::MpiTransport* rollerdyn_mpi_transport() {
  static rollerdyn::MpiLibraryTransport* transport = new rollerdyn::MpiLibraryTransport();
  return transport;
}
