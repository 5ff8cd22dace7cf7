#include "parallel/Communicator.hpp"

#include <cstdlib>
#include <limits>
#include <stdexcept>

#ifdef DPD_HAVE_MPI
#include <mpi.h>
#endif

namespace dpd {

namespace {

// MPI counts bytes in int: a message of 2 GiB or more must be cut (not needed yet: say so).
int byteCount(std::size_t n) {
    if (n > static_cast<std::size_t>(std::numeric_limits<int>::max()))
        throw std::runtime_error("Communicator: a message of " + std::to_string(n) + " bytes (2 GiB or more)");
    return static_cast<int>(n);
}

[[maybe_unused]] std::vector<int> displacements(const std::vector<int>& counts) {
    std::vector<int> d(counts.size(), 0);
    long total = 0;
    for (std::size_t r = 0; r < counts.size(); ++r) {
        d[r] = byteCount(static_cast<std::size_t>(total));
        total += counts[r];
    }
    return d;
}

}  // namespace

bool builtWithMpi() {
#ifdef DPD_HAVE_MPI
    return true;
#else
    return false;
#endif
}

void Communicator::exchangeWithNeighbours(int below, int above, const std::vector<char>& toBelow,
                                          const std::vector<char>& toAbove, std::vector<char>& fromBelow,
                                          std::vector<char>& fromAbove) const {
    if (size_ == 1) {  // one rank is its own neighbour on both sides
        fromBelow = toAbove;
        fromAbove = toBelow;
        return;
    }
#ifdef DPD_HAVE_MPI
    // The tags tell the two directions apart (with two ranks both neighbours are the same rank).
    constexpr int kDown = 1, kUp = 2;
    long sizeToBelow = static_cast<long>(toBelow.size()), sizeToAbove = static_cast<long>(toAbove.size());
    long sizeFromBelow = 0, sizeFromAbove = 0;
    MPI_Request sizes[4];
    MPI_Irecv(&sizeFromAbove, 1, MPI_LONG, above, kDown, MPI_COMM_WORLD, &sizes[0]);
    MPI_Irecv(&sizeFromBelow, 1, MPI_LONG, below, kUp, MPI_COMM_WORLD, &sizes[1]);
    MPI_Isend(&sizeToBelow, 1, MPI_LONG, below, kDown, MPI_COMM_WORLD, &sizes[2]);
    MPI_Isend(&sizeToAbove, 1, MPI_LONG, above, kUp, MPI_COMM_WORLD, &sizes[3]);
    MPI_Waitall(4, sizes, MPI_STATUSES_IGNORE);
    fromAbove.resize(static_cast<std::size_t>(sizeFromAbove));
    fromBelow.resize(static_cast<std::size_t>(sizeFromBelow));
    MPI_Request data[4];
    MPI_Irecv(fromAbove.data(), byteCount(fromAbove.size()), MPI_BYTE, above, kDown, MPI_COMM_WORLD, &data[0]);
    MPI_Irecv(fromBelow.data(), byteCount(fromBelow.size()), MPI_BYTE, below, kUp, MPI_COMM_WORLD, &data[1]);
    MPI_Isend(toBelow.data(), byteCount(toBelow.size()), MPI_BYTE, below, kDown, MPI_COMM_WORLD, &data[2]);
    MPI_Isend(toAbove.data(), byteCount(toAbove.size()), MPI_BYTE, above, kUp, MPI_COMM_WORLD, &data[3]);
    MPI_Waitall(4, data, MPI_STATUSES_IGNORE);
#else
    (void)below;
    (void)above;
#endif
}

void Communicator::gather(const std::vector<char>& mine, std::vector<char>& all, std::vector<std::size_t>& counts) const {
    if (size_ == 1) {
        all = mine;
        counts.assign(1, mine.size());
        return;
    }
#ifdef DPD_HAVE_MPI
    const int count = byteCount(mine.size());
    std::vector<int> recvCounts(isRoot() ? size_ : 0);
    MPI_Gather(&count, 1, MPI_INT, recvCounts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
    std::vector<int> at;
    all.clear();
    counts.clear();
    if (isRoot()) {
        at = displacements(recvCounts);
        std::size_t total = 0;
        for (int c : recvCounts) {
            total += static_cast<std::size_t>(c);
            counts.push_back(static_cast<std::size_t>(c));
        }
        all.resize(total);
    }
    MPI_Gatherv(mine.data(), count, MPI_BYTE, all.data(), recvCounts.data(), at.data(), MPI_BYTE, 0, MPI_COMM_WORLD);
#endif
}

void Communicator::sum([[maybe_unused]] double* values, std::size_t n) const {
    if (size_ == 1 || n == 0) return;
#ifdef DPD_HAVE_MPI
    MPI_Allreduce(MPI_IN_PLACE, values, byteCount(n), MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
#endif
}

void Communicator::sum([[maybe_unused]] long* values, std::size_t n) const {
    if (size_ == 1 || n == 0) return;
#ifdef DPD_HAVE_MPI
    MPI_Allreduce(MPI_IN_PLACE, values, byteCount(n), MPI_LONG, MPI_SUM, MPI_COMM_WORLD);
#endif
}

double Communicator::max(double value) const {
    max(&value, 1);
    return value;
}

void Communicator::max([[maybe_unused]] double* values, std::size_t n) const {
    if (size_ == 1 || n == 0) return;
#ifdef DPD_HAVE_MPI
    MPI_Allreduce(MPI_IN_PLACE, values, byteCount(n), MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
#endif
}

bool Communicator::all(bool value) const {
    if (size_ == 1) return value;
    int v = value ? 1 : 0;
#ifdef DPD_HAVE_MPI
    MPI_Allreduce(MPI_IN_PLACE, &v, 1, MPI_INT, MPI_LAND, MPI_COMM_WORLD);
#endif
    return v != 0;
}

void Communicator::broadcast([[maybe_unused]] std::vector<char>& bytes) const {
    if (size_ == 1) return;
#ifdef DPD_HAVE_MPI
    long n = static_cast<long>(bytes.size());
    MPI_Bcast(&n, 1, MPI_LONG, 0, MPI_COMM_WORLD);
    bytes.resize(static_cast<std::size_t>(n));
    MPI_Bcast(bytes.data(), byteCount(bytes.size()), MPI_BYTE, 0, MPI_COMM_WORLD);
#endif
}

void Communicator::abort(int status) const {
#ifdef DPD_HAVE_MPI
    if (size_ > 1) MPI_Abort(MPI_COMM_WORLD, status);
#endif
    std::exit(status);
}

const Communicator& Communicator::world() {
    static Communicator c;  // one rank until an MpiSession says otherwise (not const: it sets the ranks)
    return c;
}

}  // namespace dpd
