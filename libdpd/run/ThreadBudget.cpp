#include "run/ThreadBudget.hpp"

#include <omp.h>

#include <algorithm>

namespace dpd {

int threadsForParticles(std::size_t particles, int available) {
    const auto worth = static_cast<int>(std::min<std::size_t>(particles / kParticlesPerThread, 1 << 20));
    return std::max(1, std::min(available, worth));
}

int useThreadsForParticles(std::size_t particles) {
    const int threads = threadsForParticles(particles, omp_get_max_threads());
    omp_set_num_threads(threads);
    return threads;
}

}  // namespace dpd
