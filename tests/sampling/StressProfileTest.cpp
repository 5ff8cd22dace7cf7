// The stress profile (sampling/PairVirial.*, BinProfile): the Irving-Kirkwood shares of a pair
// segment, the binned virial against a direct sum over all pairs, the pressure of the equilibrium
// fluid against an accurate reference for its state point (Groot-Warren's equation of state printed
// beside it), and the shear stress of periodic Poiseuille flow against the exact momentum balance
// sigma_xz(z) = -rho g (z - z_c).
#include "../support/WallRuleNamed.hpp"
#include "forces/ReversePoiseuilleBodyForce.hpp"
#include "integrators/GrootWarrenIntegrator.hpp"
#include "setup/InitialConditions.hpp"
#include "setup/ChainedFluid.hpp"
#include "setup/StandardFluid.hpp"
#include "sampling/BinProfile.hpp"
#include "sampling/BlockStatistics.hpp"
#include "sampling/PairVirial.hpp"
#include "walls/PlanarWallSettings.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace dpd;

namespace {

BinLayout layout(int axis, int nBins, double lo, double hi) {
    BinLayout L;
    L.axis = axis;
    L.nBins = nBins;
    L.lo = lo;
    L.hi = hi;
    return L;
}

std::vector<double> shares(const BinLayout& L, double a, double b, double boxLo = 0.0, double boxLength = 10.0) {
    std::vector<double> s(L.nBins, 0.0);
    addSegmentShares(L, boxLo, boxLength, a, b, s);
    return s;
}

}  // namespace

TEST(StressProfile, SegmentSharesFollowTheSegment) {
    const BinLayout L = layout(2, 10, 0.0, 10.0);
    auto s = shares(L, 2.2, 2.8);
    EXPECT_DOUBLE_EQ(s[2], 1.0);
    s = shares(L, 3.5, 2.5);  // either order
    EXPECT_NEAR(s[2], 0.5, 1e-12);
    EXPECT_NEAR(s[3], 0.5, 1e-12);
    s = shares(L, 1.8, 3.3);  // 0.2 / 1.0 / 0.3 of 1.5
    EXPECT_NEAR(s[1], 0.2 / 1.5, 1e-12);
    EXPECT_NEAR(s[2], 1.0 / 1.5, 1e-12);
    EXPECT_NEAR(s[3], 0.3 / 1.5, 1e-12);
    s = shares(L, 9.6, 10.4);  // across the periodic boundary
    EXPECT_NEAR(s[9], 0.5, 1e-12);
    EXPECT_NEAR(s[0], 0.5, 1e-12);
    s = shares(L, -0.3, 0.2);
    EXPECT_NEAR(s[9], 0.6, 1e-12);
    EXPECT_NEAR(s[0], 0.4, 1e-12);
    s = shares(L, 4.5, 4.5);  // parallel to the bin planes
    EXPECT_DOUBLE_EQ(s[4], 1.0);
    // Bins covering only part of the box: what lies outside them is dropped.
    const BinLayout part = layout(2, 2, 2.0, 4.0);
    s = shares(part, 1.5, 2.5);
    EXPECT_NEAR(s[0], 0.5, 1e-12);
    EXPECT_NEAR(s[1], 0.0, 1e-12);
}

namespace {

// The virial of every pair within the cutoff, by a direct sum over all pairs (nearest images).
SymmetricTensor directPairVirial(const System& sys) {
    const Particles& p = sys.particles;
    const Eigen::Vector3d len = sys.box.length();
    SymmetricTensor direct{};
    const DpdPairEvaluator<true, true> eval(sys.forceParameters);
    for (std::size_t i = 0; i < p.size(); ++i)
        for (std::size_t j = i + 1; j < p.size(); ++j) {
            Eigen::Vector3d r(p.rx[i] - p.rx[j], p.ry[i] - p.ry[j], p.rz[i] - p.rz[j]);
            for (int a = 0; a < 3; ++a) r[a] -= len[a] * std::round(r[a] / len[a]);
            if (r.squaredNorm() >= 1.0) continue;
            const Eigen::Vector3d v(p.vx[i] - p.vx[j], p.vy[i] - p.vy[j], p.vz[i] - p.vz[j]);
            const double f = eval.forceOverR(r.squaredNorm(), r.dot(v), sys.pairs(p.species[i], p.species[j]), 0.0);
            const SymmetricTensor w{f * r.x() * r.x(), f * r.y() * r.y(), f * r.z() * r.z(),
                                    f * r.x() * r.y(), f * r.x() * r.z(), f * r.y() * r.z()};
            for (int m = 0; m < 6; ++m) direct[m] += w[m];
        }
    return direct;
}

}  // namespace

// Bins covering the whole box hold every pair's virial exactly once: their sum equals the direct sum
// over all pairs (minimum image, conservative + dissipative forces) to rounding.
// Also in a slab two cells thick along y (docs/scenes.md scene 6), where the stencil meets the
// other cell through both its images.
TEST(StressProfile, BinnedVirialSumsToTheDirectPairSum) {
    for (const Eigen::Vector3d& aspect : {Eigen::Vector3d(1, 1, 1), Eigen::Vector3d(1, 0.3, 1)}) {
        StandardFluidSettings s;
        s.particles = 300;
        s.dt = 0.01;
        s.aspect = aspect;
        System sys = makeStandardFluid(s);
        ASSERT_EQ(sys.cells().cellsPerAxis()[1], aspect.y() < 1 ? 2 : 4);
        GrootWarrenIntegrator gw(0.65);
        for (int k = 0; k < 20; ++k) gw.step(sys);
        const SymmetricTensor direct = directPairVirial(sys);
        for (int axis = 0; axis < 3; ++axis) {
            const auto binned = binnedPairVirial(sys, layout(axis, 7, sys.box.lo[axis], sys.box.hi[axis]));
            for (int m = 0; m < 6; ++m) {
                double sum = 0.0;
                for (const auto& b : binned) sum += b[m];
                EXPECT_NEAR(sum, direct[m], 1e-9 * std::abs(direct[0]))
                    << "aspect y " << aspect.y() << " axis " << axis << " component " << m;
            }
        }
    }
}


// Bounce-forward walls complete their crossings at the end of the step, moving those particles after
// the sort: the traversal takes them apart (by where they are now), so the binned sum is still the
// direct sum over every pair, at each of many steps with crossings (without, pairs are missed).
// In a cubic box and in a slab two cells thick along y (each moved particle's cells around then
// include the other one once, not twice).
static void checkMovedParticlesCounted(const Eigen::Vector3d& aspect) {
    SCOPED_TRACE("aspect y " + std::to_string(aspect.y()));
    StandardFluidSettings s;
    s.particles = 600;
    s.dt = 0.02;
    s.aspect = aspect;
    System sys = makeStandardFluid(s);
    for (const double side : {-1.0, 1.0}) {
        PlanarWallSettings w;
        w.name = side < 0 ? "lower" : "upper";
        w.point = Eigen::Vector3d(0, 0, side < 0 ? sys.box.lo.z() + 1.0 : sys.box.hi.z() - 1.0);
        w.normal = Eigen::Vector3d(0, 0, -side);
        w.velocity = Eigen::Vector3d(2.0 * side, 0, 0);
        w.rule = test::ruleNamed("bounceForward");
        sys.walls.addPlane(w);
    }
    sys.initialise();
    sys.sortByCell();
    sys.computeForces();
    GrootWarrenIntegrator gw(0.65);
    int stepsWithMoves = 0;
    for (int k = 0; k < 150; ++k) {
        gw.step(sys);
        if (sys.movedAfterSort().empty()) continue;
        ++stepsWithMoves;
        const SymmetricTensor direct = directPairVirial(sys);
        const auto binned = binnedPairVirial(sys, layout(2, 5, sys.box.lo.z(), sys.box.hi.z()));
        for (int m = 0; m < 6; ++m) {
            double sum = 0.0;
            for (const auto& b : binned) sum += b[m];
            ASSERT_NEAR(sum, direct[m], 1e-9 * std::abs(direct[0])) << "step " << k << " component " << m;
        }
    }
    EXPECT_GT(stepsWithMoves, 100);
}

TEST(StressProfile, BinnedVirialCountsParticlesMovedAfterTheSort) {
    checkMovedParticlesCounted(Eigen::Vector3d(1, 1, 1));
    checkMovedParticlesCounted(Eigen::Vector3d(1, 0.25, 1));
}

// With chains the springs count too: the binned sum is the direct pair sum plus, for every bond
// b = r_second - r_first, f b b with f = -H / (1 - b^2 / r_max^2) (docs/methods.md 4), to rounding.
TEST(StressProfile, BinnedVirialOfChainsAddsTheSprings) {
    ChainedFluidSettings s;
    s.fluid.particles = 600;
    s.fluid.dt = 0.01;
    s.chains = 6;
    s.length = 20;
    System sys = makeChainedFluid(s);
    GrootWarrenIntegrator gw(0.65);
    for (int k = 0; k < 20; ++k) gw.step(sys);
    const SymmetricTensor pairs = directPairVirial(sys);
    SymmetricTensor springs{};
    const Bonds& b = sys.bonds.bonds();
    ASSERT_EQ(b.size(), 6u * 19u);
    for (std::size_t k = 0; k < b.size(); ++k) {
        const Eigen::Vector3d v = b.vector(k);
        const double f = -6.0 / (1.0 - v.squaredNorm() / 9.0);
        const double w[6] = {v.x() * v.x(), v.y() * v.y(), v.z() * v.z(), v.x() * v.y(), v.x() * v.z(), v.y() * v.z()};
        for (int m = 0; m < 6; ++m) springs[m] += f * w[m];
    }
    EXPECT_LT(springs[0], 0.0);  // springs pull: tension
    for (int axis = 0; axis < 3; ++axis) {
        const auto binned = binnedPairVirial(sys, layout(axis, 7, sys.box.lo[axis], sys.box.hi[axis]));
        for (int m = 0; m < 6; ++m) {
            double sum = 0.0;
            for (const auto& bin : binned) sum += bin[m];
            EXPECT_NEAR(sum, pairs[m] + springs[m], 1e-9 * std::abs(pairs[0])) << "axis " << axis << " component " << m;
        }
    }
}

namespace {

// Runs `steps` steps sampling every `interval` into the accumulator (with the virial).
void sampleRun(System& sys, BinAccumulator& acc, int steps, int interval) {
    GrootWarrenIntegrator gw(0.65);
    for (int k = 1; k <= steps; ++k) {
        gw.step(sys);
        if (k % interval) continue;
        acc.sample(sys.particles);
        acc.addVirial(binnedPairVirial(sys, acc.layout()));
    }
}

// The mean over bins of a profile quantity, block by block, and its standard error.
struct Estimate {
    double mean = 0.0, error = 0.0;
};

Estimate blockMeanOverBins(const BinAccumulator& acc, double crossSection, double (*pick)(const BinProfile&, int)) {
    std::vector<double> perBlock;
    for (std::size_t k = 0; k < acc.blocks().size(); ++k) {
        if (acc.samplesPerBlock()[k] != acc.blockSamples()) continue;
        BinAccumulator one = BinAccumulator::fromBlocks(acc.layout(), acc.speciesMask(), acc.blockSamples(),
                                                        {acc.blocks()[k]}, {acc.samplesPerBlock()[k]});
        one.setStressFlowAxis(acc.stressFlowAxis());
        const BinProfile p = computeProfile(one, crossSection, 3);
        double m = 0.0;
        for (int b = 0; b < acc.layout().nBins; ++b) m += pick(p, b) / acc.layout().nBins;
        perBlock.push_back(m);
    }
    Estimate e;
    for (double v : perBlock) e.mean += v / perBlock.size();
    e.error = standardErrorOfMean(perBlock);
    return e;
}

}  // namespace

// Equilibrium fluid rho = 3, a = 25, gamma = 4.5, kT = 1, dt = 0.01 (Groot-Warren, whose kT bias at
// this step is below 0.001: tests/system/EquilibriumTest.cpp). The pressure, kinetic plus virial,
// averaged over the bins, against the accurate reference p = 23.636 +- 0.002 for this state point
// (Allen & Tildesley's DPD examples, Lowe and Shardlow thermostats, which have no time-step bias in kT:
// 23.637(2) and 23.635(2); the improved equation of state of Liyana-Arachchi et al. 2015 gives 23.59).
// The measured kT differs from 1 by the integrator's small bias; the kinetic part rho (kT - 1) is
// added to the reference, and as much again allowed for the virial's weaker temperature dependence.
// The standard error (10 blocks of 300 steps, each much longer than the pressure's correlation time of
// a few tens of steps; measured 0.016) must be within a budget of 0.025; then the pressure must lie
// within 4 budgets (0.1, 0.4 %) of the reference plus those allowances. A conservative force 10 %
// too strong moves the pressure by ~2.2 (its virial part).
// Groot and Warren's p = rho kT + 0.101 a rho^2 is printed beside it: a fit meant for rho > 2 that,
// at rho = 3, is 9 % above the accurate value (it tends to the data only at higher density).
TEST(StressProfile, EquilibriumPressureMatchesTheReferenceEquationOfState) {
    StandardFluidSettings s;
    s.particles = 500;
    s.dt = 0.01;
    s.seed = 31;
    System sys = makeStandardFluid(s);
    GrootWarrenIntegrator gw(0.65);
    for (int k = 0; k < 800; ++k) gw.step(sys);
    const double rho = sys.particles.size() / sys.box.volume();
    BinAccumulator acc(layout(2, 4, sys.box.lo.z(), sys.box.hi.z()), {1}, 30);
    acc.setStressFlowAxis(0);
    sampleRun(sys, acc, 3000, 10);
    const double crossSection = sys.box.volume() / sys.box.length().z();
    const Estimate p = blockMeanOverBins(acc, crossSection, [](const BinProfile& q, int b) { return q.stress[b].pressure; });
    const Estimate kT = blockMeanOverBins(acc, crossSection, [](const BinProfile& q, int b) { return q.kT[b]; });
    const double reference = 23.636 + rho * (kT.mean - 1.0);
    const double grootWarren = rho * kT.mean + 0.101 * 25.0 * rho * rho;
    std::printf("    rho %.4f, kT %.4f: pressure %.4f +- %.4f; reference %.4f; Groot-Warren alpha = 0.101: %.4f\n", rho,
                kT.mean, p.mean, p.error, reference, grootWarren);
    EXPECT_GT(p.error, 0.0);
    EXPECT_TRUE(p.error <= 0.025) << "too noisy to decide: " << p.error;
    EXPECT_TRUE(std::abs(p.mean - reference) <= 4.0 * 0.025 + 0.002 + rho * std::abs(kT.mean - 1.0)) << p.mean;
}

// Periodic (reverse) Poiseuille flow in a 5 x 5 x 10 box, rho = 3, body force +g x on z in [0, 5) and
// -g x on [5, 10), g = 0.05, dt = 0.02. In the steady state momentum balance is exact:
// d sigma_xz / dz = -rho g(z), sigma_xz = 0 where the velocity peaks (the middle of each half), so
//   sigma_xz = -rho g (z - 2.5) on the first half and +rho g (z - 7.5) on the second.
// 20 bins of 0.5 put the force jumps on bin edges, so each bin's mean is the line at its centre.
// Equilibration 3000 steps (t = 60, seven times the slowest relaxation time (L / 2 pi)^2 / nu = 8.7);
// sampling every 5 steps for 6000 steps in 12 blocks of 500 steps (each several relaxation times of
// the stress). Accept: chi^2 of the 20 bins against the exact line below 20 + 4 sqrt(40) = 45; the
// amplitude k of the best fit sigma = k sigma_exact has a standard error within a budget of 0.02
// (measured 0.0147: bins' errors too large to decide fail here, they would pass the chi^2), and lies
// within 4 budgets of 1 (measured 0.969). A halved body force halves k.
TEST(StressProfile, PeriodicPoiseuilleShearStressBalancesTheBodyForce) {
    System channel;
    channel.box.hi = Eigen::Vector3d(5, 5, 10);
    channel.species.add({"fluid", false});
    channel.pairs = PairTable(1);
    channel.pairs.set(0, 0, {25.0, 4.5, 0.0, true});
    channel.forceParameters = {1.0, 2.0, 1.0, 0.02};
    channel.seed = 37;
    channel.bodyForce = std::make_shared<ReversePoiseuilleBodyForce>(Eigen::Vector3d(0.05, 0, 0), 2);
    const PairRandom random(41);
    fillRandom(channel.particles, channel.box, channel.box.lo, channel.box.hi, 3.0, 0,
               [](double, double, double) { return true; }, random, 0);
    maxwellVelocities(channel.particles, 0, channel.particles.size(), 3, 1.0, random);
    channel.initialise();
    channel.sortByCell();
    channel.computeForces();
    GrootWarrenIntegrator gw(0.65);
    for (int k = 0; k < 3000; ++k) gw.step(channel);
    BinAccumulator acc(layout(2, 20, 0.0, 10.0), {1}, 100);
    acc.setStressFlowAxis(0);
    sampleRun(channel, acc, 6000, 5);
    const BinProfile p = computeProfile(acc, 25.0, 3);
    ASSERT_TRUE(p.hasStress);
    EXPECT_EQ(p.stressName, "sigmaxz");
    const double rho = channel.particles.size() / channel.box.volume(), g = 0.05;
    double chi2 = 0.0, sxy = 0.0, sxx = 0.0;
    for (int b = 0; b < 20; ++b) {
        const double z = p.centre[b];
        const double exact = z < 5.0 ? -rho * g * (z - 2.5) : rho * g * (z - 7.5);
        const double err = p.stress[b].shearErr;
        ASSERT_GT(err, 0.0);
        chi2 += std::pow((p.stress[b].shear - exact) / err, 2);
        sxy += p.stress[b].shear * exact / (err * err);
        sxx += exact * exact / (err * err);
        std::printf("    z %5.2f  sigma_xz %8.4f +- %.4f (kinetic %8.4f, virial %8.4f)  exact %8.4f\n", z,
                    p.stress[b].shear, err, p.stress[b].shearKinetic, p.stress[b].shearVirial, exact);
    }
    const double k = sxy / sxx, kErr = 1.0 / std::sqrt(sxx);
    std::printf("    chi2 %.2f over 20 bins; amplitude %.4f +- %.4f of the exact one\n", chi2, k, kErr);
    EXPECT_TRUE(chi2 < 20.0 + 4.0 * std::sqrt(40.0)) << chi2;
    EXPECT_TRUE(kErr <= 0.02) << "too noisy to decide: " << kErr;
    EXPECT_TRUE(std::abs(k - 1.0) <= 4.0 * 0.02) << k;
}
