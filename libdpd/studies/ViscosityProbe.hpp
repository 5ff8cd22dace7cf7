#pragma once
// The viscosity an integrator gives a fluid at a time step: periodic reverse-Poiseuille flow (docs/analysis.md
// section 5; body force +g along x in the lower half of the box along z, -g in the upper half), started
// from its laminar profile (setup/InitialFlow) so that only the error of the starting viscosity has to
// relax (time scale (Lz/2)^2 / (pi^2 nu)), then the mean velocity profile is sampled in bins along z and
// fitted by analysis/PoiseuilleFit's fitReversePoiseuille: nu with its error from the block errors of
// the profile. The run is watched as a solver's run is (studies/TemperatureProbe, kT about the
// local flow), so a blow-up is reported, not fitted.
#include "studies/TemperatureProbe.hpp"

#include <string>

namespace dpd {

class Integrator;
class System;

struct ViscosityProbeSettings {
    double g = 0.05;        // body force per unit mass along x (the flow's amplitude)
    int bins = 24;          // bins of the velocity profile along z
    double exclude = 1.0;   // distance from the planes where the force jumps left out of the fit
    double startNu = 0.0;   // viscosity of the laminar start; <= 0: the kinetic-theory estimate
    TemperatureProbeSettings run;  // equilibration, production, blocks and the monitor's checks
};

struct ViscosityProbeResult {
    bool unstable = false;  // the monitor stopped the run (then nu is not set)
    double unstableAfter = 0.0;
    std::string problem;
    double nu = 0.0, nuErr = 0.0;  // kinematic viscosity and its standard error
    double chi2PerDof = 0.0;       // of the fit, with the profile's block errors
    double kT = 0.0, kTErr = 0.0;  // kinetic temperature about the local flow during the production
};

// Runs a copy of `fluid` (a periodic one-species fluid at rest, sorted by cells, at its dt) with the
// reverse-Poiseuille force and start added. Throws std::invalid_argument when the bins leave fewer than
// four points per half for the fit.
ViscosityProbeResult probeViscosity(const System& fluid, Integrator& integrator, const ViscosityProbeSettings& s);

}  // namespace dpd
