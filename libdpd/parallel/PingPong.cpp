#include "parallel/PingPong.hpp"

#include "parallel/Communicator.hpp"

#include <stdexcept>
#include <vector>

#ifdef DPD_HAVE_MPI
#include <mpi.h>
#endif

namespace dpd {

double oneWaySeconds(const Communicator& comm, std::size_t bytes, int repeats) {
    if (comm.size() < 2) throw std::invalid_argument("a ping-pong needs two ranks (mpirun -np 2)");
    double seconds = 0.0;
#ifdef DPD_HAVE_MPI
    std::vector<char> buffer(bytes, 1);
    const int count = static_cast<int>(bytes);
    MPI_Barrier(MPI_COMM_WORLD);
    const double start = MPI_Wtime();
    for (int k = 0; k < repeats; ++k) {
        if (comm.rank() == 0) {
            MPI_Send(buffer.data(), count, MPI_BYTE, 1, 0, MPI_COMM_WORLD);
            MPI_Recv(buffer.data(), count, MPI_BYTE, 1, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        } else if (comm.rank() == 1) {
            MPI_Recv(buffer.data(), count, MPI_BYTE, 0, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
            MPI_Send(buffer.data(), count, MPI_BYTE, 0, 0, MPI_COMM_WORLD);
        }
    }
    seconds = (MPI_Wtime() - start) / (2.0 * repeats);
    MPI_Bcast(&seconds, 1, MPI_DOUBLE, 0, MPI_COMM_WORLD);
#else
    (void)bytes;
    (void)repeats;
#endif
    return seconds;
}

}  // namespace dpd
