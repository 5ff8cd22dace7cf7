#include "studies/TemperatureProbe.hpp"

#include "integrators/Integrator.hpp"
#include "sampling/Pressure.hpp"
#include "system/Monitors.hpp"
#include "system/System.hpp"
#include "sampling/BlockStatistics.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <vector>

namespace dpd {

namespace {

// Means of `blocks` equal consecutive blocks of the series (a remainder at the end is dropped).
std::vector<double> blockMeans(const std::vector<double>& series, int blocks) {
    const std::size_t perBlock = series.size() / static_cast<std::size_t>(blocks);
    std::vector<double> means(blocks, 0.0);
    for (int b = 0; b < blocks; ++b) {
        for (std::size_t k = 0; k < perBlock; ++k) means[b] += series[b * perBlock + k];
        means[b] /= static_cast<double>(perBlock);
    }
    return means;
}

// Mean and standard error (divided by the block efficiency) of a sampled series from its block means.
void blockEstimate(const std::vector<double>& series, const TemperatureProbeSettings& s, double& mean, double& error) {
    const std::vector<double> means = blockMeans(series, s.blocks);
    mean = 0.0;
    for (double m : means) mean += m;
    mean /= static_cast<double>(s.blocks);
    error = standardErrorOfMean(means) / s.blockEfficiency;
}

double processCpuSeconds() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

}  // namespace

TemperatureProbeResult probeTemperature(System& sys, Integrator& integrator, const TemperatureProbeSettings& s,
                                        const std::function<void(const System&)>& onSample) {
    const double dt = sys.dt();
    const std::int64_t equilibration = std::llround(s.equilibrationTime / dt);
    const std::int64_t production = std::llround(s.productionTime / dt);
    const std::int64_t sampleEvery = std::max<std::int64_t>(1, std::llround(s.sampleInterval / dt));
    const double setKT = sys.forceParameters.kT;
    TemperatureProbeResult r;
    std::vector<double> samples, pressures;
    double stepSeconds = 0.0, stepCpuSeconds = 0.0;
    for (std::int64_t k = 1; k <= equilibration + production; ++k) {
        const auto t0 = std::chrono::steady_clock::now();
        const double c0 = processCpuSeconds();
        integrator.step(sys);
        stepCpuSeconds += processCpuSeconds() - c0;
        stepSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        ++r.steps;
        if (k == equilibration) stepSeconds = stepCpuSeconds = 0.0;  // time the production only
        const bool sample = k > equilibration && (k - equilibration) % sampleEvery == 0;
        if (!sample && k % s.checkEvery != 0) continue;
        const MonitorReport m = monitor(sys, s.flowAxis);
        if (!m.finite || m.kT > s.maxKTRatio * setKT) {
            r.unstable = true;
            r.unstableAfter = k * dt;
            r.problem = !m.finite ? "non-finite positions, velocities or forces" : "kT runaway (kT = " + std::to_string(m.kT) + ")";
            return r;
        }
        if (!sample) continue;
        samples.push_back(m.kT);
        if (s.samplePressure) pressures.push_back(instantaneousPressure(sys));
        if (onSample) onSample(sys);
    }
    r.seconds = stepSeconds;
    r.cpuSeconds = stepCpuSeconds;
    blockEstimate(samples, s, r.kT, r.standardError);
    if (s.samplePressure) blockEstimate(pressures, s, r.pressure, r.pressureStandardError);
    return r;
}

}  // namespace dpd
