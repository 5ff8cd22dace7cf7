#pragma once
// Timing one scene on one thread count: warm-up steps, then several timed segments of steps, of which
// the best counts (the machine may be shared: the best segment is the one least disturbed, and the
// spread between best and worst says how noisy the measurement was). The time per step is split by
// phase with System's step timer and the sampling call; memory is counted from the capacities of the
// arrays the run holds.
#include "BenchmarkScenes.hpp"

#include <cstddef>
#include <string>

namespace dpd {

struct BenchmarkSettings {
    int warmup = 10;
    int steps = 100;    // per segment
    int segments = 3;   // timed segments; the best counts
};

struct BenchmarkResult {
    std::string scene;
    std::size_t particles = 0;  // mobile: the rates count these
    std::size_t frozen = 0;     // frozen particles held besides (walls, grains)
    int threads = 1;          // per rank
    int ranks = 1;            // MPI ranks (mpirun -np); particles are those of every rank together
    double rate = 0.0;        // particle-steps per second, best segment, wall clock
    double cpuRate = 0.0;     // particle-steps per second of CPU time x threads, segment of least CPU time
    double spread = 0.0;      // worst segment time / best segment time - 1
    // Of the best segment's wall time x threads, the share the hypervisor gave to other guests while
    // this machine's CPUs wanted it ("steal" in /proc/stat, all CPUs): a shared virtual machine's
    // figures are low by about that much, and more (other guests share the caches and memory too).
    // NaN where the kernel does not say.
    double steal = 0.0;
    double msPerStep = 0.0;   // best segment
    // Fractions of the best segment's time.
    double pairs = 0.0, neighbours = 0.0, walls = 0.0, integration = 0.0, sampling = 0.0;
    double exchange = 0.0;    // particles between ranks: migration and ghosts (first rank's share)
    double bytesPerParticle = 0.0;
    double kT = 0.0;          // at the end, as a check that the run stayed sane
};

// Runs a copy of the scene's system on `threads` OpenMP threads.
BenchmarkResult timeScene(const BenchmarkScene& scene, int threads, const BenchmarkSettings& settings);

}  // namespace dpd
