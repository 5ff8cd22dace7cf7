#include "forces/PairBatch.hpp"

#include "forces/PairForceLoop.hpp"

#include <atomic>

namespace dpd {
namespace detail {

namespace {
// Bytes held by all threads' batches, for the memory report.
std::atomic<std::size_t> totalBatchBytes{0};
}  // namespace

void PairBatch::reserveMore(std::size_t count) {
    const std::size_t need = size + count;
    if (need <= i.size()) return;
    const std::size_t before = capacityBytes();
    const std::size_t grown = std::max(need, 2 * i.size());
    for (auto* v : {&i, &j, &idLo, &idHi}) v->resize(grown);
    for (auto* v : {&dx, &dy, &dz, &rDotV, &zeta, &a, &gamma, &sigma, &forceOverR}) v->resize(grown);
    totalBatchBytes += capacityBytes() - before;
}

std::size_t PairBatch::capacityBytes() const {
    std::size_t bytes = 0;
    for (const auto* v : {&i, &j, &idLo, &idHi}) bytes += v->capacity() * sizeof(std::uint32_t);
    for (const auto* v : {&dx, &dy, &dz, &rDotV, &zeta, &a, &gamma, &sigma, &forceOverR}) bytes += v->capacity() * sizeof(double);
    return bytes;
}

PairBatch& threadPairBatch() {
    thread_local PairBatch batch;
    return batch;
}

}  // namespace detail

std::size_t pairLoopScratchBytes() { return detail::totalBatchBytes.load(); }

}  // namespace dpd
