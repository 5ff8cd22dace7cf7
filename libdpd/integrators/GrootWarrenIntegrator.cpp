#include "integrators/GrootWarrenIntegrator.hpp"

#include "integrators/ForEachParticle.hpp"
#include "integrators/StepParts.hpp"
#include "system/System.hpp"

#include <sstream>

namespace dpd {

std::unique_ptr<Integrator> GrootWarrenIntegrator::New(const Dictionary& coeffs) {
    coeffs.checkKeys({"type", "lambda"});
    const double lambda = coeffs.getOrDefault<double>("lambda", 0.65);
    if (!(lambda >= 0.0 && lambda <= 1.0)) coeffs.fail("lambda", "must lie in [0, 1]");
    return std::make_unique<GrootWarrenIntegrator>(lambda);
}

std::string GrootWarrenIntegrator::description() const {
    std::ostringstream words;
    words.precision(12);
    words << name() << " lambda " << lambda_;
    return words.str();
}

WallCounters GrootWarrenIntegrator::step(System& sys) {
    Particles& p = sys.particles;
    const double dt = sys.dt();
    const double halfDt = 0.5 * dt;
    halfKickAndDrift(sys);
    // Where the pair loop makes the predicted velocities, it reads the old forces through the sort's
    // order, and nothing else reads them: the sort need not move them.
    const bool predictInPairLoop = !sys.hasVelocityDependentNonPairForces();
    const WallCounters walls = sys.afterMove(predictInPairLoop ? SortForces::Leave : SortForces::Move);
    // v~ = v + lambda dt f = (v + dt f / 2) + (lambda - 1/2) dt f.
    const double predict = (lambda_ - 0.5) * dt;
    if (predictInPairLoop) {
        ForcePass predicted;
        predicted.predictorShift = predict;
        sys.computeForces(predicted);
        kick(sys, halfDt);
        sys.endStep();
        return walls;
    }
    // Keep v + dt f / 2 aside and write v~ into v for every other force that reads it (the sort may
    // have changed the count: a decomposed run's particles came and went, and ghosts joined). The
    // walls' friction reads v + dt f / 2: with it this step leaves an Ornstein-Uhlenbeck bath at kT
    // exactly for any gamma dt, where lambda's predictor cools it by (lambda - 1/2) gamma dt
    // (docs/walls.md 3.5).
    const long n = static_cast<long>(p.size());
    hx_.resize(n); hy_.resize(n); hz_.resize(n);
    forEachParticle(sys, [&](long i, auto mobile) {
        hx_[i] = p.vx[i]; hy_[i] = p.vy[i]; hz_[i] = p.vz[i];
        const double s = mobileFactor(mobile) * predict;  // a frozen particle keeps its wall's velocity
        p.vx[i] += s * p.fx[i];
        p.vy[i] += s * p.fy[i];
        p.vz[i] += s * p.fz[i];
    });
    ForcePass frictionOfTheHalfKick;
    frictionOfTheHalfKick.wallFriction = VelocityColumns{hx_.data(), hy_.data(), hz_.data()};
    sys.computeForces(frictionOfTheHalfKick);
    forEachParticle(sys, [&](long i, auto mobile) {
        // A frozen particle gets back the velocity the predictor left alone.
        const double h = mobileFactor(mobile) * halfDt;
        p.vx[i] = hx_[i] + h * p.fx[i];
        p.vy[i] = hy_[i] + h * p.fy[i];
        p.vz[i] = hz_[i] + h * p.fz[i];
    });
    sys.endStep();
    return walls;
}

}  // namespace dpd
