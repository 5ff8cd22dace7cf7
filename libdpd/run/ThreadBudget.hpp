#pragma once
// How many OpenMP threads a run of n particles uses. A step has about twenty parallel regions, each
// ending in a barrier; waking a sleeping thread for one costs microseconds, so below a few thousand
// particles per thread the threads spend longer waiting for each other than they save, and a small
// system runs several times slower on two threads than on one (the test-size tutorials). Results do
// not depend on the thread count (counter-based random numbers, fixed reduction order), so the
// choice costs nothing but time. OMP_NUM_THREADS still sets how many are available.
#include <cstddef>

namespace dpd {

// The fewest particles per thread worth another thread (benchmark: dpdBenchmark -n 2000,4000,...).
constexpr std::size_t kParticlesPerThread = 4000;

// min(available, max(1, particles / kParticlesPerThread)).
int threadsForParticles(std::size_t particles, int available);

// Sets the OpenMP thread count for a run of that many particles and returns it. It only ever lowers
// the count (what is available is the current maximum): call it once per run, as the tools do.
int useThreadsForParticles(std::size_t particles);

}  // namespace dpd
