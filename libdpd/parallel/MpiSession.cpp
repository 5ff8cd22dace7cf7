#include "parallel/MpiSession.hpp"

#include "parallel/Communicator.hpp"

#ifdef DPD_HAVE_MPI
#include <mpi.h>
#endif

#include <cstdlib>

namespace dpd {

namespace {

// Whether a launcher started this process as one rank of several (OpenMPI's mpirun, or a PMI/PMIx
// launcher such as Slurm's srun). A program started by hand is one rank and does not start MPI at
// all: a singleton MPI_Init costs a third of a second and depends on the MPI runtime's health.
bool launchedAsRank() {
    for (const char* variable : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"})
        if (std::getenv(variable)) return true;
    return false;
}

}  // namespace

MpiSession::MpiSession(int& argc, char**& argv) {
#ifdef DPD_HAVE_MPI
    if (!launchedAsRank()) return;
    // Only the main thread calls MPI (the OpenMP threads work between the calls).
    int provided = 0;
    MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
    started_ = true;
    auto& world = const_cast<Communicator&>(Communicator::world());
    MPI_Comm_rank(MPI_COMM_WORLD, &world.rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &world.size_);
#else
    (void)argc;
    (void)argv;
#endif
}

MpiSession::~MpiSession() {
#ifdef DPD_HAVE_MPI
    if (started_) MPI_Finalize();
#endif
}

}  // namespace dpd
