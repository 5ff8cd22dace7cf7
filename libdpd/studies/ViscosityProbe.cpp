#include "studies/ViscosityProbe.hpp"

#include "analysis/PoiseuilleFit.hpp"
#include "forces/ReversePoiseuilleBodyForce.hpp"
#include "setup/InitialFlow.hpp"
#include "system/System.hpp"
#include "sampling/BinAccumulator.hpp"
#include "sampling/BinProfile.hpp"

#include <algorithm>
#include <cmath>

namespace dpd {

namespace {

constexpr int kGradientAxis = 2;  // z; the flow is along x

// The force and the laminar start of the flow on the fluid.
void startReversePoiseuille(System& sys, const ViscosityProbeSettings& s) {
    sys.bodyForce = std::make_shared<ReversePoiseuilleBodyForce>(Eigen::Vector3d(s.g, 0.0, 0.0), kGradientAxis);
    InitialFlow flow;
    flow.type = InitialFlow::Type::reversePoiseuille;
    flow.axis = kGradientAxis;
    flow.lower = sys.box.lo[kGradientAxis];
    flow.upper = sys.box.hi[kGradientAxis];
    flow.g = sys.bodyForce->value();
    const double density = static_cast<double>(sys.particles.size()) / sys.box.volume();
    flow.nu = s.startNu > 0.0 ? s.startNu
                              : kineticTheoryViscosity(sys.forceParameters.kT, sys.pairs(0, 0).gamma, density,
                                                       sys.forceParameters.cutoff);
    addInitialFlow(sys.particles, 0, sys.particles.size(), flow);
    sys.computeForces();
}

}  // namespace

ViscosityProbeResult probeViscosity(const System& fluid, Integrator& integrator, const ViscosityProbeSettings& s) {
    System sys = fluid;
    startReversePoiseuille(sys, s);
    const double dt = sys.dt();
    BinLayout layout;
    layout.axis = kGradientAxis;
    layout.nBins = s.bins;
    layout.lo = sys.box.lo[kGradientAxis];
    layout.hi = sys.box.hi[kGradientAxis];
    // Samples as the probe takes them, cut into its number of blocks.
    const std::int64_t sampleEvery = std::max<std::int64_t>(1, std::llround(s.run.sampleInterval / dt));
    const std::int64_t samples = std::llround(s.run.productionTime / dt) / sampleEvery;
    BinAccumulator profile(layout, std::vector<std::uint8_t>(sys.species.size(), 1),
                           std::max<long>(1, static_cast<long>(samples / s.run.blocks)));
    TemperatureProbeSettings run = s.run;
    run.flowAxis = kGradientAxis;
    const TemperatureProbeResult t =
        probeTemperature(sys, integrator, run, [&](const System& now) { profile.sample(now.particles); });
    ViscosityProbeResult r;
    r.unstable = t.unstable;
    r.unstableAfter = t.unstableAfter;
    r.problem = t.problem;
    if (t.unstable) return r;
    r.kT = t.kT;
    r.kTErr = t.standardError;
    const Eigen::Vector3d len = sys.box.length();
    const double crossSection = sys.box.dimension == 3 ? len.x() * len.y() : len.x();
    const BinProfile p = computeProfile(profile, crossSection, sys.box.dimension);
    // The blocks too when there are enough (4) for errors from them: the bins move together.
    std::vector<std::vector<double>> blocks = blockVelocities(profile, 0);
    if (blocks.size() < 4) blocks.clear();
    const ReversePoiseuilleResult fit =
        fitReversePoiseuille(Profile1D{p.centre, p.ux, p.uxErr, blocks}, s.g, layout.lo, len[kGradientAxis], s.exclude);
    r.nu = fit.nu;
    r.nuErr = fit.nuErr;
    r.chi2PerDof = fit.chi2PerDof;
    return r;
}

}  // namespace dpd
