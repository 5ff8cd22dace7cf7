#pragma once
// The least and greatest sort key of each block of consecutive particles, so that a pass looking for
// the keys of one range steps over the blocks that hold none of them.
//
// The parallel counting sort (CellList.cpp) gives each thread a range of keys to count and place;
// reading every particle's key in every thread would not get faster with more threads. Particles stay
// nearly in cell order from one sort to the next, so a block's keys span a plane of cells or two and a
// thread reads about its own share of the keys (measurements: dpdBenchmark's README). What a pass
// visits, and in which order, is what a plain scan visits: a block passed over holds none of its keys.
#include <algorithm>
#include <cstdint>
#include <vector>

namespace dpd {

class SortKeyBlocks {
public:
    static constexpr std::uint32_t kBlock = 256;

    // Room for the bounds of n keys' blocks.
    void resize(std::uint32_t n) {
        const std::size_t blocks = (static_cast<std::size_t>(n) + kBlock - 1) / kBlock;
        least_.resize(blocks);
        greatest_.resize(blocks);
    }
    // The bounds of the block that starts at particle `first` (a multiple of kBlock), whose `count`
    // keys start at `key`. Blocks may be recorded by different threads.
    void record(std::uint32_t first, const std::uint32_t* key, std::uint32_t count) {
        std::uint32_t lo = key[0], hi = key[0];
        for (std::uint32_t i = 1; i < count; ++i) {
            lo = std::min(lo, key[i]);
            hi = std::max(hi, key[i]);
        }
        least_[first / kBlock] = lo;
        greatest_[first / kBlock] = hi;
    }
    // Every block may hold any key: for a sort on one thread, which reads every key anyway and so
    // need not pay for the bounds.
    void coverEveryKey() {
        std::fill(least_.begin(), least_.end(), 0u);
        std::fill(greatest_.begin(), greatest_.end(), ~0u);
    }
    // Particle i's key was changed to k after its block was recorded.
    void widen(std::uint32_t i, std::uint32_t k) {
        least_[i / kBlock] = std::min(least_[i / kBlock], k);
        greatest_[i / kBlock] = std::max(greatest_[i / kBlock], k);
    }
    // visit(i) for every i in [first, end), in increasing order, whose key lies in [kBegin, kBegin + width).
    template <class Visit>
    void forEachKeyIn(const std::uint32_t* key, std::uint32_t first, std::uint32_t end, std::uint32_t kBegin,
                      std::uint32_t width, Visit&& visit) const {
        std::uint32_t i = first;
        while (i < end) {
            const std::uint32_t b = i / kBlock;
            const std::uint32_t blockEnd = std::min(end, (b + 1) * kBlock);
            // The block's keys [least, greatest] meet [kBegin, kBegin + width) (the sum is a key
            // count, within 32 bits).
            if (greatest_[b] >= kBegin && least_[b] < kBegin + width) {
                for (; i < blockEnd; ++i)
                    if (key[i] - kBegin < width) visit(i);
            }
            i = blockEnd;
        }
    }

private:
    std::vector<std::uint32_t> least_, greatest_;
};

}  // namespace dpd
