#include "integrators/StepParts.hpp"

#include "integrators/ForEachParticle.hpp"

namespace dpd {

namespace {

// v += h f for one particle, through the arrays' own pointers (the pass's lambdas copy them, so the
// loop vectorises); a frozen particle's h is 0 (forEachParticle's mobile factor), and v + 0 f is its v.
struct VelocityKick {
    double *vx, *vy, *vz;
    const double *fx, *fy, *fz;
    explicit VelocityKick(Particles& p)
        : vx(p.vx.data()), vy(p.vy.data()), vz(p.vz.data()), fx(p.fx.data()), fy(p.fy.data()), fz(p.fz.data()) {}
    void operator()(long i, double h) const {
        vx[i] += h * fx[i];
        vy[i] += h * fy[i];
        vz[i] += h * fz[i];
    }
};

}  // namespace

void kick(System& sys, double h) {
    const VelocityKick kickOne(sys.particles);
    forEachParticle(sys, [=](long i, auto mobile) { kickOne(i, mobileFactor(mobile) * h); });
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
    // One pass: r + dt (v + dt f / 2) is r + dt v + dt^2 f / 2. The half-kicked velocity is what a
    // wall reflects, since it is the velocity the particle carries on with.
    double *rx = p.rx.data(), *ry = p.ry.data(), *rz = p.rz.data();
    const double *vx = p.vx.data(), *vy = p.vy.data(), *vz = p.vz.data();
    const VelocityKick kickOne(p);
    forEachParticle(sys, [=](long i, auto mobile) {
        kickOne(i, mobileFactor(mobile) * halfDt);
        rx[i] += dt * vx[i];
        ry[i] += dt * vy[i];
        rz[i] += dt * vz[i];
    });
}

}  // namespace dpd
