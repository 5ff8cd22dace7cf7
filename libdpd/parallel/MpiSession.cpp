#include "parallel/MpiSession.hpp"

#include "parallel/Communicator.hpp"

#ifdef DPD_HAVE_MPI
#include <mpi.h>
#endif

namespace dpd {

MpiSession::MpiSession(int& argc, char**& argv) {
#ifdef DPD_HAVE_MPI
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
