#include "integrators/EulerIntegrator.hpp"

#include "run/System.hpp"

namespace dpd {

WallCounters EulerIntegrator::step(System& sys) {
    Particles& p = sys.particles;
    const double dt = sys.dt();
    const auto& frozen = sys.frozenOfSpecies();
    const long n = static_cast<long>(p.size());
#pragma omp parallel for schedule(static)
    for (long i = 0; i < n; ++i) {
        p.rx[i] += dt * p.vx[i];
        p.ry[i] += dt * p.vy[i];
        p.rz[i] += dt * p.vz[i];
        if (frozen[p.species[i]]) continue;  // frozen particles keep their (wall) velocity
        p.vx[i] += dt * p.fx[i];
        p.vy[i] += dt * p.fy[i];
        p.vz[i] += dt * p.fz[i];
    }
    sys.advanceClock();
    // Reflect before wrapping: a particle that crossed a wall lying on a box face must be mirrored
    // back, not carried round to the far side of the box.
    const WallCounters walls = sys.applyWalls();
    sys.wrapPositions();
    sys.sortByCell();
    sys.computeForces();
    sys.completeWalls();
    return walls;
}

}  // namespace dpd
