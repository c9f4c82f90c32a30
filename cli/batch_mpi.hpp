// `mpirun -n P orthoray batch ... --mpi`: the same batch spread over P
// processes on any number of machines (docs/batch.md). Only built with MPI.
#pragma once

#include "batch_instance.hpp"

namespace orthoray::cli {

#ifdef ORTHORAY_MPI
// Rank 0 expands the inputs, owns the results file (with every guarantee
// of a local batch) and hands out chunks of instances on request, sized to
// a quarter of the work left per rank (at least 1, at most 64), so the
// last chunks are small and no rank waits long for another; it also decides
// instances on --jobs threads (default 1). The other ranks ask for a chunk,
// decide its instances one at a time and send each result line back.
// Returns rank 0's exit status (the other ranks return 0).
int run_on_ranks(const BatchArgs& args);
#endif

} // namespace orthoray::cli
