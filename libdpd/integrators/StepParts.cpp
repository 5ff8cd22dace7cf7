#include "integrators/StepParts.hpp"

#include "run/System.hpp"

namespace dpd {

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

void drift(System& sys) {
    Particles& p = sys.particles;
    const double dt = sys.dt();
    const long n = static_cast<long>(p.size());
#pragma omp parallel for schedule(static)
    for (long i = 0; i < n; ++i) {
        p.rx[i] += dt * p.vx[i];
        p.ry[i] += dt * p.vy[i];
        p.rz[i] += dt * p.vz[i];
    }
}

void halfKickAndDrift(System& sys) {
    Particles& p = sys.particles;
    const double dt = sys.dt();
    const double halfDt = 0.5 * dt;
    const auto& frozen = sys.frozenOfSpecies();
    const long n = static_cast<long>(p.size());
    // One pass: r + dt (v + dt f / 2) is r + dt v + dt^2 f / 2. The half-kicked velocity is what a
    // wall reflects, since it is the velocity the particle carries on with.
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
}

WallCounters endMove(System& sys) {
    sys.advanceClock();
    // Reflect before wrapping: a particle that crossed a wall lying on a box face must be mirrored
    // back, not carried round to the far side of the box.
    const WallCounters walls = sys.applyWalls();
    sys.wrapPositions();
    sys.sortByCell();
    return walls;
}

}  // namespace dpd
