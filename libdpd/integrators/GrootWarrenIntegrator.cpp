#include "integrators/GrootWarrenIntegrator.hpp"

#include "integrators/ForEachParticle.hpp"
#include "integrators/StepParts.hpp"
#include "run/System.hpp"

namespace dpd {

WallCounters GrootWarrenIntegrator::step(System& sys) {
    Particles& p = sys.particles;
    const double dt = sys.dt();
    const double halfDt = 0.5 * dt;
    const long n = static_cast<long>(p.size());
    halfKickAndDrift(sys);
    const WallCounters walls = endMove(sys);
    // v~ = v + lambda dt f = (v + dt f / 2) + (lambda - 1/2) dt f.
    const double predict = (lambda_ - 0.5) * dt;
    if (!sys.hasVelocityDependentNonPairForces()) {
        sys.computeForces(predict);
        kick(sys, halfDt);
        sys.completeWalls();
        return walls;
    }
    // Keep v + dt f / 2 aside and write v~ into v for every force that reads it.
    hx_.resize(n); hy_.resize(n); hz_.resize(n);
    forEachParticle(sys, [&](long i, auto mobile) {
        hx_[i] = p.vx[i]; hy_[i] = p.vy[i]; hz_[i] = p.vz[i];
        if (!mobile) return;
        p.vx[i] += predict * p.fx[i];
        p.vy[i] += predict * p.fy[i];
        p.vz[i] += predict * p.fz[i];
    });
    sys.computeForces();
    forEachParticle(sys, [&](long i, auto mobile) {
        if (!mobile) return;  // the predictor left a frozen particle's velocity alone
        p.vx[i] = hx_[i] + halfDt * p.fx[i];
        p.vy[i] = hy_[i] + halfDt * p.fy[i];
        p.vz[i] = hz_[i] + halfDt * p.fz[i];
    });
    sys.completeWalls();
    return walls;
}

}  // namespace dpd
