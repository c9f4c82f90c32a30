#include "mpi_link.hpp"

#include <cstdio>
#include <cstdlib>

namespace orthoray::cli {

MpiSession::MpiSession() {
    int provided = 0;
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
}

MpiSession::~MpiSession() {
    // Rank 0's report may still sit in stdio's buffers, and MPI_Finalize
    // can block long enough for mpirun, told to stop, to send SIGKILL.
    std::fflush(nullptr);
    MPI_Finalize();
}

void send(const std::string& bytes, int to, int tag) {
    MPI_Send(bytes.data(), static_cast<int>(bytes.size()), MPI_CHAR, to, tag, MPI_COMM_WORLD);
}

std::string receive(const MPI_Status& probed) {
    int count = 0;
    MPI_Get_count(&probed, MPI_CHAR, &count);
    std::string bytes(static_cast<std::size_t>(count), '\0');
    MPI_Recv(bytes.data(), count, MPI_CHAR, probed.MPI_SOURCE, probed.MPI_TAG, MPI_COMM_WORLD,
             MPI_STATUS_IGNORE);
    return bytes;
}

void abort_all(const char* what, int status) {
    std::fprintf(stderr, "orthoray: %s\n", what);
    MPI_Abort(MPI_COMM_WORLD, status);
    std::_Exit(status);
}

} // namespace orthoray::cli
