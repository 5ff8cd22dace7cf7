#include "core/ThreadBudget.hpp"

#include <omp.h>

#include <algorithm>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace dpd {

std::size_t particlesPerThread() {
    const char* text = std::getenv("DPD_PARTICLES_PER_THREAD");
    if (text == nullptr) return kParticlesPerThread;
    const std::string value(text);
    char* end = nullptr;
    const long long n = std::strtoll(value.c_str(), &end, 10);
    if (value.empty() || *end != '\0' || n < 1)
        throw std::invalid_argument("the environment variable DPD_PARTICLES_PER_THREAD is '" + value +
                                    "': expected a positive whole number of particles per thread");
    return static_cast<std::size_t>(n);
}

int threadsForParticles(std::size_t particles, int available, std::size_t perThread) {
    const auto worth = static_cast<int>(std::min<std::size_t>(particles / perThread, 1 << 20));
    return std::max(1, std::min(available, worth));
}

ThreadUse useThreadsForParticles(std::size_t particles) {
    ThreadUse use;
    use.available = omp_get_max_threads();
    use.perThread = particlesPerThread();
    use.used = threadsForParticles(particles, use.available, use.perThread);
    omp_set_num_threads(use.used);
    return use;
}

}  // namespace dpd
