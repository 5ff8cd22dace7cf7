#include "integrators/ShardlowIntegrator.hpp"

#include "integrators/ShardlowSweep.hpp"
#include "integrators/StepParts.hpp"
#include "system/System.hpp"

namespace dpd {

std::unique_ptr<Integrator> ShardlowIntegrator::New(const Dictionary& coeffs) {
    coeffs.checkKeys({"type"});
    return std::make_unique<ShardlowIntegrator>();
}

Capabilities ShardlowIntegrator::capabilities() const {
    return {{},
            {{{Feature::severalRanks}, "cannot run on several ranks yet (its sweep updates one pair after another)", ""},
             {{Feature::velocityForce}, "does not run forces besides the pair force that read the velocities yet (its sweep "
                                        "updates the velocities pair by pair)", ""}}};
}

WallCounters ShardlowIntegrator::step(System& sys) {
    if (forcesStep_ != sys.step) sys.computeForces(ForcePass::conservativeAndOthers());
    const double dt = sys.dt();
    shardlowSweep(sys, dt, 0);
    halfKickAndDrift(sys);
    // Its conservative forces are cleared and made again, not written over: the sort moves them.
    const WallCounters walls = sys.afterMove(SortForces::Move);
    sys.computeForces(ForcePass::conservativeAndOthers());
    kick(sys, 0.5 * dt);
    forcesStep_ = sys.step;
    sys.endStep();
    return walls;
}

}  // namespace dpd
