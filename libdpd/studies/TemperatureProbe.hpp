#pragma once
// How well an integrator holds the temperature: runs a system with it, watches it as a run's monitor
// does (kT runaway, NaN), and measures the mean kinetic temperature with a block standard error; on
// request also the pressure (sampling/Pressure.hpp) from the same samples. Used by the integrator
// stability tests and the speed-accuracy benchmark.
#include <cstdint>
#include <functional>
#include <string>

namespace dpd {

class Integrator;
class System;

struct TemperatureProbeSettings {
    double equilibrationTime = 5.0;   // time units run before sampling
    double productionTime = 100.0;    // time units sampled
    double sampleInterval = 0.05;     // time between kT samples (at least one step)
    int blocks = 10;                  // equal blocks for the standard error
    // Fraction of the true standard error that blocks of this length capture (1 when each block is
    // much longer than the slowest relaxation of kT); the block error is divided by it.
    double blockEfficiency = 1.0;
    double maxKTRatio = 2.0;          // the runaway check of a run (stability { maxKTRatio })
    int checkEvery = 10;              // steps between checks of the monitor
    bool samplePressure = false;      // also the mean pressure, with its block standard error
    int flowAxis = -1;                // the monitor's flow axis (kT about the local flow); -1: none
};

struct TemperatureProbeResult {
    double kT = 0.0;             // mean over the production
    double standardError = 0.0;  // block standard error / blockEfficiency
    bool unstable = false;       // the monitor's checks failed (kT runaway or NaN); kT is then not set
    double unstableAfter = 0.0;  // time units from the start of the probe to the failed check
    std::string problem;
    std::int64_t steps = 0;      // steps made
    double seconds = 0.0;        // wall time of the production (steps only, no sampling)
    // CPU time of the process (all threads) over the same steps: the work done, which unlike the wall
    // time does not grow when other jobs share the machine's cores.
    double cpuSeconds = 0.0;
    double pressure = 0.0;       // mean pressure (samplePressure only)
    double pressureStandardError = 0.0;  // block standard error / blockEfficiency
};

// Runs sys with the integrator for equilibrationTime + productionTime at sys.dt(). `onSample`, when
// given, is called at every sample of the production (after the monitor's check), for other samplers.
TemperatureProbeResult probeTemperature(System& sys, Integrator& integrator, const TemperatureProbeSettings& s,
                                        const std::function<void(const System&)>& onSample = {});

}  // namespace dpd
