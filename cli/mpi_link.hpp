// What the MPI commands share (batch --mpi, puzzle solve and generate
// --mpi, docs/batch.md): the session around a run and byte messages.
// Only built with MPI.
#pragma once

#ifdef ORTHORAY_MPI
#include <mpi.h>

#include <string>

namespace orthoray::cli {

// MPI_Init_thread and MPI_Finalize around a run; only the main thread of a
// rank calls MPI (MPI_THREAD_FUNNELED).
class MpiSession {
public:
    MpiSession();
    ~MpiSession();
    MpiSession(const MpiSession&) = delete;
    MpiSession& operator=(const MpiSession&) = delete;
    int rank = 0, size = 1;
};

void send(const std::string& bytes, int to, int tag);
// Receives the message `probed` (by MPI_Probe or MPI_Iprobe) describes.
std::string receive(const MPI_Status& probed);

// Any failure ends every rank at once.
[[noreturn]] void abort_all(const char* what, int status);

} // namespace orthoray::cli
#endif
