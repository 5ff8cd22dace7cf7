#pragma once
// Speed against accuracy of the integrators: for each integrator and time step, on the standard fluid,
// the kT error and the pressure (with their block standard errors), whether the run's monitor stopped
// it, and the cost of one time unit (CPU seconds per particle per time unit: the work, robust to
// other jobs on the machine); optionally the viscosity
// from a reverse-Poiseuille run of the same integrator and step (studies/ViscosityProbe). Pressure
// and viscosity errors are taken against a reference run: the integrator named by `reference` at
// referenceDeltaT, a step smaller than any studied (so no studied run is compared with itself).
// Read from system/integratorSpeedAccuracyDict:
//
//   fluid       { particles 648; density 3; a 25; gamma 4.5; kT 1; seed 2; }
//   integrators { GW065 { type GrootWarren; lambda 0.65; } VV { type DPDVV; } S1 { type Shardlow; } }
//   deltaT      (0.01 0.02 0.04 0.06 0.08 0.1);
//   reference   VV;        // the reference run's integrator for pressure and viscosity
//   referenceDeltaT 0.005; // its step, below every deltaT (default: half the smallest deltaT)
//   referenceTimeFactor 4; // it samples this many times longer than the studied runs (default 4), so
//                          // that its error is small beside theirs
//   equilibrationTime 5;  productionTime 50;  blockTime 5;  maxKTRatio 2;
//   viscosity                          // optional: no viscosity columns without it
//   {
//       lengthRatio 2;                 // box Lz / Lx (the fluid's cross-section, lengthRatio x particles)
//       g 0.05;  bins 24;  exclude 1;  // force amplitude, profile bins along z, jump layers left out
//       startNu 0.3;                   // optional: viscosity of the laminar start (default kinetic theory)
//       equilibrationTime 5;  productionTime 50;  blockTime 5;
//   }
//
// Every case starts from the same state: the fluid equilibrated from its random start by
// Groot-Warren (lambda 0.65) at dt 0.01 for 1000 steps (one such state for each box).
#include "integrators/Integrator.hpp"
#include "studies/TemperatureProbe.hpp"
#include "studies/ViscosityProbe.hpp"
#include "setup/StandardFluid.hpp"

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
    std::string reference;  // the integrator of the reference run for pressure and viscosity
    double referenceDeltaT = 0.0;  // its step, below every deltaT
    int referenceTimeFactor = 4;   // its production times (and blocks) are this many times the studied runs
    TemperatureProbeSettings probe;  // with samplePressure on
    bool viscosity = false;           // whether to run the viscosity probes
    double viscosityLengthRatio = 2.0;
    ViscosityProbeSettings viscosityProbe;
};

struct SpeedAccuracyRow {
    std::string label;
    double dt = 0.0;
    TemperatureProbeResult result;
    double secondsPerParticleTimeUnit = 0.0;  // production CPU time (all threads) / (particles x production time)
    bool hasViscosity = false;
    ViscosityProbeResult viscosity;
    bool isReference = false;  // the reference run (at referenceDeltaT), not a studied step
};

// Errors name the file, line and keyword.
SpeedAccuracySettings readSpeedAccuracySettings(const Dictionary& d);

// Runs the reference, then every integrator at every step; `progress` gets one line per case. The
// reference run is the first row.
std::vector<SpeedAccuracyRow> runSpeedAccuracyStudy(const SpeedAccuracySettings& s, std::ostream& progress);

// The table: the reference run in the header (pressure and nu with their errors), then one row per
// studied case, columns
//   integrator dt kTError kTErrorSE pressure pressureSE pressureError pressureErrorSE
//   nu nuSE nuError nuErrorSE secondsPerParticleTimeUnit unstable unstableAfter
// errors relative (kT against the set kT; pressure and nu against the reference row, their errors
// the two standard errors added in quadrature); nan where not measured.
std::string speedAccuracyTable(const std::vector<SpeedAccuracyRow>& rows, const SpeedAccuracySettings& s);

}  // namespace dpd
