#include "integrators/GrootWarrenIntegrator.hpp"

#include "run/System.hpp"

namespace dpd {

WallCounters GrootWarrenIntegrator::step(System& sys) {
    Particles& p = sys.particles;
    const double dt = sys.dt();
    const double halfDt = 0.5 * dt;
    const auto& frozen = sys.frozenOfSpecies();
    const long n = static_cast<long>(p.size());
    // Half kick then drift: r + dt (v + dt f / 2) is r + dt v + dt^2 f / 2. The half-kicked velocity
    // is what a wall reflects, since it is the velocity the particle carries on with.
#pragma omp parallel for schedule(static)
    for (long i = 0; i < n; ++i) {
        if (!frozen[p.species[i]]) {
            p.vx[i] += halfDt * p.fx[i];
            p.vy[i] += halfDt * p.fy[i];
            p.vz[i] += halfDt * p.fz[i];
        }
        p.rx[i] += dt * p.vx[i];
        p.ry[i] += dt * p.vy[i];
        p.rz[i] += dt * p.vz[i];
    }
    sys.advanceClock();
    // Reflect before wrapping: a particle that crossed a wall lying on a box face must be mirrored
    // back, not carried round to the far side of the box.
    const WallCounters walls = sys.applyWalls();
    sys.wrapPositions();
    sys.sortByCell();
    // Keep v + dt f / 2 aside and predict v~ = v + lambda dt f = (v + dt f / 2) + (lambda - 1/2) dt f.
    hx_.resize(n); hy_.resize(n); hz_.resize(n);
    const double predict = (lambda_ - 0.5) * dt;
#pragma omp parallel for schedule(static)
    for (long i = 0; i < n; ++i) {
        hx_[i] = p.vx[i]; hy_[i] = p.vy[i]; hz_[i] = p.vz[i];
        if (frozen[p.species[i]]) continue;
        p.vx[i] += predict * p.fx[i];
        p.vy[i] += predict * p.fy[i];
        p.vz[i] += predict * p.fz[i];
    }
    sys.computeForces();
#pragma omp parallel for schedule(static)
    for (long i = 0; i < n; ++i) {
        if (frozen[p.species[i]]) continue;  // the predictor left a frozen particle's velocity alone
        p.vx[i] = hx_[i] + halfDt * p.fx[i];
        p.vy[i] = hy_[i] + halfDt * p.fy[i];
        p.vz[i] = hz_[i] + halfDt * p.fz[i];
    }
    sys.completeWalls();
    return walls;
}

}  // namespace dpd
