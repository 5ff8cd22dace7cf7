#pragma once
// The pairs one thread found within the cutoff in a column of cells, as a structure of arrays, in the
// order the traversal met them. Each thread keeps its own batch between calls, so a step allocates
// nothing once the buffers have grown to the largest column.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace dpd {
namespace detail {

struct PairBatch {
    std::vector<std::uint32_t> i, j;       // particle indices, i the one of the column's own cell
    std::vector<double> dx, dy, dz;        // r_i - (r_j + periodic image)
    std::vector<double> rDotV;             // (r_i - r_j) . (v_i - v_j)
    std::vector<std::uint32_t> idLo, idHi;  // the pair's ids, ordered, keying its random number
    std::vector<double> zeta;              // the pair's unit-variance random number
    std::vector<double> a, gamma, sigma;   // per-pair coefficients, when they differ between pairs
    std::vector<double> forceOverR;
    std::size_t size = 0;                  // pairs found

    // Makes room for `count` more entries beyond size (candidates are written before they are
    // tested, four at a time, so room is needed for all of them and three more).
    void reserveMore(std::size_t count);
    std::size_t capacityBytes() const;
};

// This thread's batch.
PairBatch& threadPairBatch();

}  // namespace detail
}  // namespace dpd
