#include "integrators/ShardlowIntegrator.hpp"

#include "integrators/PartialPairForces.hpp"
#include "integrators/ShardlowSweep.hpp"
#include "run/System.hpp"

namespace dpd {

namespace {

// v += h f for mobile particles.
void kick(System& sys, double h) {
    Particles& p = sys.particles;
    const auto& frozen = sys.frozenOfSpecies();
    const long n = static_cast<long>(p.size());
#pragma omp parallel for schedule(static)
    for (long i = 0; i < n; ++i) {
        if (frozen[p.species[i]]) continue;
        p.vx[i] += h * p.fx[i];
        p.vy[i] += h * p.fy[i];
        p.vz[i] += h * p.fz[i];
    }
}

}  // namespace

WallCounters ShardlowIntegrator::step(System& sys) {
    if (forcesStep_ != sys.step) computeConservativeForces(sys);
    const double dt = sys.dt();
    shardlowSweep(sys, dt, 0);
    kick(sys, 0.5 * dt);
    Particles& p = sys.particles;
    const long n = static_cast<long>(p.size());
#pragma omp parallel for schedule(static)
    for (long i = 0; i < n; ++i) {
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
    computeConservativeForces(sys);
    kick(sys, 0.5 * dt);
    forcesStep_ = sys.step;
    return walls;
}

}  // namespace dpd
