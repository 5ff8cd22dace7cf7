#pragma once
// The pairs one thread found within the cutoff in a row of cells, as a structure of arrays, in the
// order the search met them. Each thread keeps its own batch between calls, so a step allocates
// nothing once the buffers have grown to the largest row.
//
// The arrays share one allocation, each starting 256 bytes further into its page than the one before:
// the search appends to five of them at the same index at once, and arrays whose same entries fall
// in the same L1 cache set (which separate large allocations, all page-aligned, do) evicted each
// other (measured: a search appending to nine such arrays ran 1.8 times slower).
#include <cstddef>
#include <cstdint>
#include <vector>

namespace dpd {
namespace detail {

struct PairBatch {
    std::uint32_t* i = nullptr;      // particle indices, i the one of the home cell
    std::uint32_t* j = nullptr;
    float* dx = nullptr;             // r_i - (r_j + periodic image), single precision (PairInputs.hpp)
    float* dy = nullptr;
    float* dz = nullptr;
    float* rDotV = nullptr;          // (r_i - r_j) . (v_i - v_j)
    std::uint32_t* idLo = nullptr;   // the pair's ids (low 32 bits), ordered, keying its random number
    std::uint32_t* idHi = nullptr;
    double* zeta = nullptr;          // the pair's unit-variance random number
    double* a = nullptr;             // per-pair coefficients, when they differ between pairs
    double* gamma = nullptr;
    double* sigma = nullptr;
    double* forceOverR = nullptr;
    std::size_t size = 0;            // pairs found

    // Makes room for `count` more entries beyond size, keeping the first `size`.
    void reserveMore(std::size_t count);
    std::size_t capacity() const { return capacity_; }
    std::size_t capacityBytes() const { return storage_.capacity() * sizeof(double); }

private:
    void allocate(std::size_t capacity);
    std::vector<double> storage_;
    std::size_t capacity_ = 0;
};

// This thread's batch.
PairBatch& threadPairBatch();

}  // namespace detail
}  // namespace dpd
