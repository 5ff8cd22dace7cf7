// What each new scheme leaves in the particles' forces at the end of a step (the Integrator contract:
// the forces of the new state, as the scheme defines them):
// - DPD-VV re-evaluates the dissipative force with the final velocities, so its forces are exactly the
//   full DPD forces of the new positions and velocities (with the new step's random numbers), which
//   System::computeForces recomputes from scratch;
// - Shardlow's forces are the conservative and body forces of the new positions.
// Round-off: DPD-VV adds the dissipative correction f^D(v(t+dt) - v') to f' instead of evaluating
// f^D(v(t+dt)) directly, and the pair loop reads velocities in single precision
// (forces/PairInputs.hpp): each velocity component rounded by at most u |v|max (u = 2^-24), in the
// three loops involved (v(t+dt), v' and their difference) and in the difference of the two particles'
// velocities, and the product r.dv by at most 4 u |r| |dv|: at most ~10 u |v|max per pair (|r| < 1),
// times gamma w_D <= gamma, summed over at most ~40 pairs per particle: 400 u gamma |v|max (~1e-4
// here). Forces with the half-step velocities instead would differ by
// gamma w_D e.(dt f / 2) ~ 4.5 x 0.25 x 0.02 x 20 ~ 0.5.
#include "forces/UniformBodyForce.hpp"
#include "integrators/Integrator.hpp"
#include "setup/StandardFluid.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>
#include <cmath>

using namespace dpd;

namespace {

StandardFluidSettings fluid() {
    StandardFluidSettings s;
    s.particles = 1000;
    s.dt = 0.04;
    s.seed = 9;
    return s;
}

// Largest component-wise difference between the particles' forces and those `recompute` gives.
double largestForceDifference(System& sys, void (*recompute)(System&)) {
    const Particles before = sys.particles;
    recompute(sys);
    double worst = 0.0;
    for (std::size_t i = 0; i < before.size(); ++i) {
        worst = std::max(worst, std::abs(before.fx[i] - sys.particles.fx[i]));
        worst = std::max(worst, std::abs(before.fy[i] - sys.particles.fy[i]));
        worst = std::max(worst, std::abs(before.fz[i] - sys.particles.fz[i]));
    }
    return worst;
}

void fullForces(System& sys) { sys.computeForces(); }

void conservativeAndOtherForces(System& sys) { sys.computeForces(ForcePass::conservativeAndOthers()); }

ForcePass predictedBy(double shift) {
    ForcePass p;
    p.predictorShift = shift;
    return p;
}

std::unique_ptr<Integrator> scheme(const std::string& type) {
    IntegratorSettings s;
    s.type = type;
    return makeIntegrator(s);
}

}  // namespace

TEST(IntegratorForces, DpdVvLeavesTheFullForcesOfTheFinalVelocities) {
    System sys = makeStandardFluid(fluid());
    sys.bodyForce = std::make_shared<UniformBodyForce>(Eigen::Vector3d(0.3, 0, 0));
    sys.computeForces();
    auto dpdvv = scheme("DPDVV");
    for (int k = 0; k < 20; ++k) dpdvv->step(sys);
    double vMax = 0.0;
    for (std::size_t i = 0; i < sys.particles.size(); ++i)
        vMax = std::max({vMax, std::abs(sys.particles.vx[i]), std::abs(sys.particles.vy[i]), std::abs(sys.particles.vz[i])});
    const double gamma = sys.pairs(0, 0).gamma;
    EXPECT_LT(largestForceDifference(sys, fullForces), 400.0 * 0x1p-24 * gamma * vMax);
    // Groot-Warren leaves the forces of its predicted velocity instead: the check can tell them apart.
    auto gw = scheme("GrootWarren");
    gw->step(sys);
    EXPECT_GT(largestForceDifference(sys, fullForces), 0.01);
}

TEST(IntegratorForces, ShardlowLeavesTheConservativeAndBodyForces) {
    System sys = makeStandardFluid(fluid());
    sys.bodyForce = std::make_shared<UniformBodyForce>(Eigen::Vector3d(0.0, 0.2, 0));
    auto shardlow = scheme("Shardlow");
    for (int k = 0; k < 20; ++k) shardlow->step(sys);
    EXPECT_EQ(largestForceDifference(sys, conservativeAndOtherForces), 0.0) << "the same loop, the same bits";
    // And these are not the full DPD forces.
    EXPECT_GT(largestForceDifference(sys, fullForces), 1.0);
}

// Groot-Warren's predictor folded into the pair loop (ForcePass::predictorShift): the forces are
// those of the velocities v + shift f, computed by writing them into v first, and v is left alone.
// Both round the same double v + shift f to single precision in the pair loop, so they agree to the
// bit unless the compiler contracts one of the two multiply-adds into an FMA and not the other: then
// a velocity may differ by one float ulp, u |v|max, within the DPD-VV bound above (400 u gamma |v|max).
TEST(IntegratorForces, PredictorInThePairLoopSeesThePredictedVelocities) {
    System explicitPrediction = makeStandardFluid(fluid());
    auto gw = scheme("GrootWarren");
    for (int k = 0; k < 5; ++k) gw->step(explicitPrediction);  // forces of a moving fluid
    System folded = explicitPrediction;
    const Particles start = folded.particles;
    const double shift = 0.15 * folded.dt();
    Particles& e = explicitPrediction.particles;
    double vMax = 0.0;
    for (std::size_t i = 0; i < e.size(); ++i) {
        e.vx[i] += shift * e.fx[i];
        e.vy[i] += shift * e.fy[i];
        e.vz[i] += shift * e.fz[i];
        vMax = std::max({vMax, std::abs(e.vx[i]), std::abs(e.vy[i]), std::abs(e.vz[i])});
    }
    explicitPrediction.computeForces();
    folded.computeForces(predictedBy(shift));
    double worst = 0.0, unpredicted = 0.0;
    for (std::size_t i = 0; i < e.size(); ++i) {
        ASSERT_EQ(folded.particles.vx[i], start.vx[i]);
        ASSERT_EQ(folded.particles.vz[i], start.vz[i]);
        worst = std::max({worst, std::abs(folded.particles.fx[i] - e.fx[i]), std::abs(folded.particles.fy[i] - e.fy[i]),
                          std::abs(folded.particles.fz[i] - e.fz[i])});
    }
    EXPECT_LT(worst, 400.0 * 0x1p-24 * folded.pairs(0, 0).gamma * vMax);
    // The forces of the unpredicted velocities are told apart (shift dt |f| ~ 0.1 in v).
    folded.computeForces();
    for (std::size_t i = 0; i < e.size(); ++i) unpredicted = std::max(unpredicted, std::abs(folded.particles.fx[i] - e.fx[i]));
    EXPECT_GT(unpredicted, 0.01);
}


TEST(IntegratorForces, ForcesASortLeftBehindAreFoundByThePredictor) {
    // A moving fluid, its particles displaced so that the sort really permutes; sorted with the forces
    // moved, or left behind for the predictor to read through the sort's order: the same forces to
    // the bit (what lets Groot-Warren's, DPD-VV's and Euler's steps skip moving forces they never read).
    System moved = makeStandardFluid(fluid());
    auto gw = scheme("GrootWarren");
    for (int k = 0; k < 5; ++k) gw->step(moved);
    Particles& p = moved.particles;
    for (std::size_t i = 0; i < p.size(); ++i) { p.rx[i] += 0.3 * p.vx[i]; p.rz[i] -= 0.3 * p.vy[i]; }
    System left = moved;
    const double shift = 0.15 * moved.dt();
    moved.sortByCell(SortForces::Move);
    left.sortByCell(SortForces::Leave);
    moved.computeForces(predictedBy(shift));
    left.computeForces(predictedBy(shift));
    ASSERT_EQ(left.particles.id, moved.particles.id);
    EXPECT_EQ(left.particles.fx, moved.particles.fx);
    EXPECT_EQ(left.particles.fy, moved.particles.fy);
    EXPECT_EQ(left.particles.fz, moved.particles.fz);
    // The forces are its own again: a further sort may leave them behind; two in a row may not (the
    // second would lose track of them).
    left.sortByCell(SortForces::Leave);
    EXPECT_THROW(left.sortByCell(SortForces::Leave), std::logic_error);
}
