#include "BenchmarkTiming.hpp"

#include "forces/PairForceLoop.hpp"
#include "integrators/GrootWarrenIntegrator.hpp"
#include "parallel/Communicator.hpp"
#include "system/Monitors.hpp"

#include <omp.h>

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <fstream>
#include <limits>
#include <string>

namespace dpd {

namespace {

using Clock = std::chrono::steady_clock;

double seconds(Clock::time_point from) { return std::chrono::duration<double>(Clock::now() - from).count(); }

double processCpuSeconds() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// CPU time stolen from this virtual machine so far, summed over its CPUs, in seconds: the eighth
// number of /proc/stat's "cpu" line, in clock ticks. NaN where there is no such line.
double stolenCpuSeconds() {
    std::ifstream stat("/proc/stat");
    std::string label;
    double ticks[8];
    if (!(stat >> label) || label != "cpu") return std::numeric_limits<double>::quiet_NaN();
    for (double& t : ticks)
        if (!(stat >> t)) return std::numeric_limits<double>::quiet_NaN();
    return ticks[7] / static_cast<double>(sysconf(_SC_CLK_TCK));
}

template <class T, class Allocator>
std::size_t capacityBytes(const std::vector<T, Allocator>& v) {
    return v.capacity() * sizeof(T);
}

std::size_t particleBytes(const Particles& p) {
    std::size_t bytes = capacityBytes(p.id) + capacityBytes(p.species);
    for (const auto* a : {&p.rx, &p.ry, &p.rz, &p.vx, &p.vy, &p.vz, &p.fx, &p.fy, &p.fz}) bytes += capacityBytes(*a);
    return bytes;
}

struct Segment {
    double wall = 0.0, cpu = 0.0, sampling = 0.0, stolen = 0.0;
    StepTimes parts;
};

Segment runSegment(System& sys, GrootWarrenIntegrator& integrator, FunctionObjects& sampling, int steps) {
    Segment s;
    sys.stepTimes = &s.parts;
    const double cpu0 = processCpuSeconds();
    const double stolen0 = stolenCpuSeconds();
    const auto t0 = Clock::now();
    for (int k = 0; k < steps; ++k) {
        integrator.step(sys);
        const auto ts = Clock::now();
        sampling.execute(sys);
        s.sampling += seconds(ts);
    }
    s.wall = seconds(t0);
    s.cpu = processCpuSeconds() - cpu0;
    s.stolen = stolenCpuSeconds() - stolen0;
    sys.stepTimes = nullptr;
    return s;
}

}  // namespace

BenchmarkResult timeScene(const BenchmarkScene& scene, int threads, const BenchmarkSettings& settings) {
    omp_set_num_threads(threads);
    System sys = scene.system;
    FunctionObjects sampling = scene.sampling;
    GrootWarrenIntegrator integrator(0.65);
    for (int k = 0; k < settings.warmup; ++k) integrator.step(sys);

    // The CPU rate has its own best segment: on a shared machine the segment least descheduled (best
    // wall time) need not be the one least slowed by others' use of the caches (least CPU time).
    Segment best, worst, leastCpu;
    // On several ranks a segment takes as long as its slowest rank, and costs the CPU time of all.
    const Communicator* comm = sys.domain() ? &sys.domain()->communicator() : nullptr;
    for (int k = 0; k < settings.segments; ++k) {
        if (comm) comm->max(0.0);  // start together
        Segment s = runSegment(sys, integrator, sampling, settings.steps);
        if (comm) {
            s.wall = comm->max(s.wall);
            s.cpu = comm->sum(s.cpu);
            s.stolen = comm->max(s.stolen);  // the machine's counter, the same for every rank on it
        }
        if (k == 0 || s.wall < best.wall) best = s;
        if (k == 0 || s.wall > worst.wall) worst = s;
        if (k == 0 || s.cpu < leastCpu.cpu) leastCpu = s;
    }

    BenchmarkResult r;
    r.scene = scene.name;
    // The rate counts the particles that move, as a run's log does; frozen ones are held besides.
    r.particles = static_cast<std::size_t>(sys.sumOverRanks(static_cast<long>(sys.countMobile())));
    r.frozen = static_cast<std::size_t>(sys.sumOverRanks(static_cast<long>(sys.particles.size()))) - r.particles;
    r.threads = threads;
    r.ranks = comm ? comm->size() : 1;
    const double particleSteps = static_cast<double>(r.particles) * settings.steps;
    r.rate = particleSteps / best.wall;
    r.cpuRate = particleSteps * threads * r.ranks / leastCpu.cpu;
    r.spread = worst.wall / best.wall - 1.0;
    r.steal = best.stolen / (best.wall * threads * r.ranks);
    r.msPerStep = 1e3 * best.wall / settings.steps;
    r.pairs = best.parts.forces / best.wall;
    r.neighbours = (best.parts.wrap + best.parts.sort) / best.wall;
    r.exchange = (best.parts.migrate + best.parts.ghosts) / best.wall;
    r.walls = best.parts.walls / best.wall;
    r.sampling = best.sampling / best.wall;
    r.integration = std::max(0.0, 1.0 - r.pairs - r.neighbours - r.exchange - r.walls - r.sampling);
    // Memory: this rank's (ghosts come and go within the step).
    const std::size_t bytes = particleBytes(sys.particles) + sys.cells().memoryBytes() + integrator.memoryBytes() +
                              pairLoopScratchBytes();
    r.bytesPerParticle = static_cast<double>(bytes) / static_cast<double>(sys.particles.size());
    r.kT = monitor(sys, scene.flowAxis).kT;
    return r;
}

}  // namespace dpd
