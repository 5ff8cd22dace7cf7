#pragma once
// Speed against accuracy of the integrators: for each integrator and time step, the kT error of the
// standard fluid (with its block standard error), whether the run's monitor stopped it, and the cost
// of one time unit (seconds per particle per time unit). Read from system/integratorSpeedAccuracyDict:
//
//   fluid       { particles 648; density 3; a 25; gamma 4.5; kT 1; seed 2; }
//   integrators { GW065 { type GrootWarren; lambda 0.65; } VV { type DPDVV; } S1 { type Shardlow; } }
//   deltaT      (0.01 0.02 0.04 0.06 0.08 0.1);
//   equilibrationTime 5;  productionTime 50;  blockTime 5;  maxKTRatio 2;
//
// Every case starts from the same state: the fluid equilibrated from its random start by
// Groot-Warren (lambda 0.65) at dt 0.01 for 1000 steps.
#include "integrators/Integrator.hpp"
#include "integrators/TemperatureProbe.hpp"
#include "run/StandardFluid.hpp"

#include <string>
#include <vector>

namespace dpd {

class Dictionary;

struct SpeedAccuracyCase {
    std::string label;  // the name given in `integrators`
    IntegratorSettings integrator;
};

struct SpeedAccuracySettings {
    StandardFluidSettings fluid;
    std::vector<SpeedAccuracyCase> integrators;
    std::vector<double> deltaT;
    TemperatureProbeSettings probe;
};

struct SpeedAccuracyRow {
    std::string label;
    double dt = 0.0;
    TemperatureProbeResult result;
    double secondsPerParticleTimeUnit = 0.0;  // production wall time / (particles x production time)
};

// Errors name the file, line and keyword.
SpeedAccuracySettings readSpeedAccuracySettings(const Dictionary& d);

// Runs every integrator at every step; `progress` gets one line per case.
std::vector<SpeedAccuracyRow> runSpeedAccuracyStudy(const SpeedAccuracySettings& s, std::ostream& progress);

// The table: one row per case, columns
//   integrator dt kTError kTErrorSE secondsPerParticleTimeUnit unstable unstableAfter
std::string speedAccuracyTable(const std::vector<SpeedAccuracyRow>& rows);

}  // namespace dpd
