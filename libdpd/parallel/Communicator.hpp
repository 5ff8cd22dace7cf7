#pragma once
// The ranks of a run and what they say to each other (docs/parallel.md). With MPI (OpenMPI) built in
// and the program started under mpirun, world() is MPI_COMM_WORLD; otherwise it is one rank and every
// call below is the identity, so the serial code path pays nothing.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace dpd {

class Communicator {
public:
    // The process's ranks: MPI_COMM_WORLD once an MpiSession has started MPI, else a single rank.
    static const Communicator& world();

    int rank() const { return rank_; }
    int size() const { return size_; }
    bool isRoot() const { return rank_ == 0; }
    bool parallel() const { return size_ > 1; }

    // With the ranks in a ring of slabs: sends `toBelow` to rank `below` and `toAbove` to rank `above`,
    // and receives what they sent this rank: `fromBelow` what `below` sent up, `fromAbove` what `above`
    // sent down (with two ranks both are the same rank; the two directions stay apart). Four messages
    // of data a rank, whatever the number of ranks (an all-to-all exchange would cost each rank P).
    void exchangeWithNeighbours(int below, int above, const std::vector<char>& toBelow, const std::vector<char>& toAbove,
                                std::vector<char>& fromBelow, std::vector<char>& fromAbove) const;
    // Every rank's bytes, concatenated in rank order, on the root only (elsewhere `all` is left empty);
    // counts[r] the bytes of rank r (on the root).
    void gather(const std::vector<char>& mine, std::vector<char>& all, std::vector<std::size_t>& counts) const;
    // Element-wise sums over the ranks, in place, the same on every rank.
    void sum(double* values, std::size_t n) const;
    void sum(long* values, std::size_t n) const;
    long sum(long value) const { sum(&value, 1); return value; }
    double sum(double value) const { sum(&value, 1); return value; }
    // The largest value over the ranks, on every rank (element-wise, in place, for an array).
    double max(double value) const;
    void max(double* values, std::size_t n) const;
    // Whether the value holds on every rank (a logical and).
    bool all(bool value) const;
    // The root's bytes on every rank.
    void broadcast(std::vector<char>& bytes) const;
    // Stops every rank (MPI_Abort) with this exit status: for an error met by one rank alone, which
    // would otherwise leave the others waiting.
    [[noreturn]] void abort(int status) const;

private:
    Communicator() = default;
    friend class MpiSession;
    int rank_ = 0;
    int size_ = 1;
};

// Whether this build can run on several ranks (MPI found when it was configured).
bool builtWithMpi();

}  // namespace dpd
