#include "integrators/DpdVvIntegrator.hpp"

#include "integrators/ForEachParticle.hpp"
#include "integrators/StepParts.hpp"
#include "system/System.hpp"

namespace dpd {

std::unique_ptr<Integrator> DpdVvIntegrator::New(const Dictionary& coeffs) {
    coeffs.checkKeys({"type"});
    return std::make_unique<DpdVvIntegrator>();
}

WallCounters DpdVvIntegrator::step(System& sys) {
    Particles& p = sys.particles;
    const double halfDt = 0.5 * sys.dt();
    halfKickAndDrift(sys);
    const WallCounters walls = sys.afterMove(SortForces::Leave);  // the forces are computed anew
    // The dissipative loop below reads the ghosts' velocity changes, made from their whole forces.
    ForcePass whole;
    whole.ghostsHoldOwnersForces = true;
    sys.computeForces(whole);
    const long n = static_cast<long>(p.size());  // a decomposed run's count changes in the sort
    // Second half kick; keep v(t+dt) and f' aside, and put the velocity change dt f' / 2 in the
    // particles' velocities (zero for frozen particles, whose velocity never changes) so that one
    // dissipative pair loop gives f^D(v(t+dt) - v').
    vx_.resize(n); vy_.resize(n); vz_.resize(n);
    fx_.resize(n); fy_.resize(n); fz_.resize(n);
    forEachParticle(sys, [&](long i, auto mobile) {
        fx_[i] = p.fx[i]; fy_[i] = p.fy[i]; fz_[i] = p.fz[i];
        const double h = mobileFactor(mobile) * halfDt;
        const double kx = h * p.fx[i], ky = h * p.fy[i], kz = h * p.fz[i];
        vx_[i] = p.vx[i] + kx; vy_[i] = p.vy[i] + ky; vz_[i] = p.vz[i] + kz;
        p.vx[i] = kx; p.vy[i] = ky; p.vz[i] = kz;
    });
    p.clearForces();
    sys.computeForces(ForcePass::dissipativeAdded());
#pragma omp parallel for schedule(static)
    for (long i = 0; i < n; ++i) {
        p.fx[i] += fx_[i]; p.fy[i] += fy_[i]; p.fz[i] += fz_[i];
        p.vx[i] = vx_[i]; p.vy[i] = vy_[i]; p.vz[i] = vz_[i];
    }
    sys.endStep();
    return walls;
}

}  // namespace dpd
