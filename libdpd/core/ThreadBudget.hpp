#pragma once
// How many OpenMP threads a run of n particles uses. A step has about twenty parallel regions, each
// ending in a barrier, so a small system on two threads lives on how fast a waiting thread gets its
// partner back. Measured (dpdBenchmark, standard fluid, 2 cores): on an idle machine with the default
// wait policy two threads beat one from 2000 particles (5.6e6 against 3.1e6 particle-steps/s); with
// any other process running they lose badly below a few thousand (2000: 0.8e6 against 2.4e6; a 2-D
// tutorial of 1500 particles ran at 1.5e5 under load, 2.7e6 on one thread), and with
// OMP_WAIT_POLICY=passive they lose up to ~30000 even on an idle machine. One thread per 4000
// particles gives up at most ~1.7x on tiny systems on an idle machine (which run in seconds) for
// runs that do not collapse when the machine is shared. Results do not depend on the thread count
// (counter-based random numbers, fixed reduction order), so the choice costs nothing but time.
// OMP_NUM_THREADS still sets how many are available; DPD_PARTICLES_PER_THREAD replaces the 4000, for a
// test that must run several threads on a small system.
#include <cstddef>

namespace dpd {

// The fewest particles per thread worth another thread (benchmark: dpdBenchmark -n 2000,4000,...).
constexpr std::size_t kParticlesPerThread = 4000;

// kParticlesPerThread, or the environment's DPD_PARTICLES_PER_THREAD (a positive integer). Throws
// std::invalid_argument naming the variable for any other value.
std::size_t particlesPerThread();

// min(available, max(1, particles / perThread)).
int threadsForParticles(std::size_t particles, int available, std::size_t perThread = kParticlesPerThread);

struct ThreadUse {
    int available = 1;   // OpenMP's maximum before the call
    int used = 1;        // what the run uses
    std::size_t perThread = kParticlesPerThread;  // the particles a thread was worth
};

// Sets the OpenMP thread count for a run of that many particles. It only ever lowers the count (what
// is available is the current maximum): call it once per run, as the tools do.
ThreadUse useThreadsForParticles(std::size_t particles);

}  // namespace dpd
