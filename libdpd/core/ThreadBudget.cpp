#include "core/ThreadBudget.hpp"

#include <omp.h>

#include <algorithm>

namespace dpd {

int threadsForParticles(std::size_t particles, int available) {
    const auto worth = static_cast<int>(std::min<std::size_t>(particles / kParticlesPerThread, 1 << 20));
    return std::max(1, std::min(available, worth));
}

ThreadUse useThreadsForParticles(std::size_t particles) {
    ThreadUse use;
    use.available = omp_get_max_threads();
    use.used = threadsForParticles(particles, use.available);
    omp_set_num_threads(use.used);
    return use;
}

}  // namespace dpd
