#include "forces/PairBatch.hpp"

#include "forces/PairForceSums.hpp"
#include "forces/PairInputs.hpp"
#include "forces/PairForceLoop.hpp"

#include <algorithm>
#include <atomic>
#include <cstring>
#include <type_traits>

namespace dpd {
namespace detail {

namespace {
// Bytes held by all threads' batches, for the memory report.
std::atomic<std::size_t> totalBatchBytes{0};

// Each array's share of the allocation, in doubles: whole pages, then a 256-byte stagger per array.
constexpr std::size_t kStaggerDoubles = 256 / sizeof(double);
std::size_t arrayDoubles(std::size_t capacity) {
    const std::size_t page = 4096 / sizeof(double);
    return (capacity + page - 1) / page * page + kStaggerDoubles;
}
}  // namespace

void PairBatch::allocate(std::size_t capacity) {
    const std::size_t before = capacityBytes();
    const std::size_t stride = arrayDoubles(capacity);
    constexpr std::size_t kArrays = 13;
    std::vector<double> storage(kArrays * stride);
    // Array m starts at m strides: whole pages plus m staggers. The entries found so far move along.
    const auto place = [&](auto*& array, int m) {
        using T = std::remove_pointer_t<std::remove_reference_t<decltype(array)>>;
        T* fresh = reinterpret_cast<T*>(storage.data() + m * stride);
        if (array && size > 0) std::memcpy(fresh, array, size * sizeof(T));
        array = fresh;
    };
    place(i, 0); place(j, 1); place(dx, 2); place(dy, 3); place(dz, 4); place(rDotV, 5); place(idLo, 6);
    place(idHi, 7); place(zeta, 8); place(a, 9); place(gamma, 10); place(sigma, 11); place(forceOverR, 12);
    storage_.swap(storage);
    capacity_ = capacity;
    totalBatchBytes += capacityBytes() - before;
}

void PairBatch::reserveMore(std::size_t count) {
    const std::size_t need = size + count;
    if (need <= capacity_) return;
    allocate(std::max(need, 2 * capacity_));
}

PairBatch& threadPairBatch() {
    thread_local PairBatch batch;
    return batch;
}

}  // namespace detail

std::size_t pairLoopScratchBytes() {
    return detail::totalBatchBytes.load() + sharedPairInputs().capacityBytes() + sharedPairForceSums().capacityBytes();
}

}  // namespace dpd
