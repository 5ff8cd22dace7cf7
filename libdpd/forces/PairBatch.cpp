#include "forces/PairBatch.hpp"

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
    double* base = storage.data();
    // Array m starts at m strides: whole pages plus m staggers.
    const auto at = [&](int m) { return base + m * stride; };
    const auto move = [&](auto*& array, int m, std::size_t elementBytes) {
        using T = std::remove_pointer_t<std::remove_reference_t<decltype(array)>>;
        T* fresh = reinterpret_cast<T*>(at(m));
        if (array && size > 0) std::memcpy(fresh, array, size * elementBytes);
        array = fresh;
    };
    move(i, 0, 4); move(j, 1, 4); move(dx, 2, 4); move(dy, 3, 4); move(dz, 4, 4); move(rDotV, 5, 4);
    move(idLo, 6, 4); move(idHi, 7, 4); move(zeta, 8, 8); move(a, 9, 8); move(gamma, 10, 8); move(sigma, 11, 8);
    move(forceOverR, 12, 8);
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

std::size_t pairLoopScratchBytes() { return detail::totalBatchBytes.load() + sharedPairInputs().capacityBytes(); }

}  // namespace dpd
