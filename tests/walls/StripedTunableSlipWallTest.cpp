// The striped tunable-slip wall (docs/walls.md 3.6): the friction follows the stripes; with the same
// friction in every sector it is the plain tunable-slip wall to the bit; at rest the fluid in front of
// gas and no-slip sectors has the same temperature and density (the wall's random force matches its
// friction in every sector, so the stripes are a heat bath at kT everywhere); a box that does not hold
// whole periods is refused.
#include "../support/WallRuleNamed.hpp"
#include "case/DpdProperties.hpp"
#include "core/Error.hpp"
#include "integrators/GrootWarrenIntegrator.hpp"
#include "io/Dictionary.hpp"
#include "sampling/BlockStatistics.hpp"
#include "setup/InitialConditions.hpp"
#include "system/System.hpp"
#include "walls/PlanarWallDictionary.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace dpd;

namespace {

PlanarWallSettings stripedWall(const std::string& name, double z, double normalZ, double gammaL, double gammaGas, double period) {
    PlanarWallSettings w;
    w.name = name;
    w.point = Eigen::Vector3d(0, 0, z);
    w.normal = Eigen::Vector3d(0, 0, normalZ);
    w.rule = test::ruleNamed("specular");
    w.hasTunableSlip = true;
    w.tunableSlip.gammaL = gammaL;
    w.tunableSlip.zc = 1.0;
    w.tunableSlip.epsilon = 1.0;
    w.tunableSlip.sigma = 0.5;
    if (period > 0.0) {
        w.hasStripes = true;
        w.stripes.axis = 0;
        w.stripes.period = period;
        w.stripes.gasFraction = 0.5;
        w.stripes.gammaGas = gammaGas;
    }
    return w;
}

// A channel 10 x 3 between walls at z = -h and h: rho 3, a 25, gamma 4.5, dt 0.01.
System channel(double h, double kT, double gammaL, double gammaGas, double period, std::uint64_t seed = 2010) {
    System sys;
    sys.box.lo = Eigen::Vector3d(0, 0, -h - 1);
    sys.box.hi = Eigen::Vector3d(10, 3, h + 1);
    sys.species.add({"fluid", false});
    sys.pairs = PairTable(1);
    sys.pairs.set(0, 0, {25.0, 4.5, 0.0, true});
    sys.forceParameters = {1.0, 2.0, kT, 0.01};
    sys.seed = seed;
    sys.walls.addPlane(stripedWall("lower", -h, 1, gammaL, gammaGas, period));
    sys.walls.addPlane(stripedWall("upper", h, -1, gammaL, gammaGas, period));
    const PairRandom random(sys.seed);
    fillRandom(sys.particles, sys.box, Eigen::Vector3d(0, 0, -h + 0.6), Eigen::Vector3d(10, 3, h - 0.6), 3.0, 0,
               [](double, double, double) { return true; }, random, 0);
    maxwellVelocities(sys.particles, 0, sys.particles.size(), 3, kT, random);
    sys.initialise();
    sys.sortByCell();
    sys.computeForces();
    return sys;
}

}  // namespace

TEST(StripedTunableSlipWall, FrictionFollowsTheStripes) {
    // Two particles 0.8 in front of the lower wall (w_L = 0.2), far apart, moving at 1 along x; no
    // pair force (a = gamma = 0) and kT 0 (no random force): F_x = -gamma_L(x) x 0.2.
    System sys;
    sys.box.lo = Eigen::Vector3d(0, 0, -4);
    sys.box.hi = Eigen::Vector3d(8, 3, 4);
    sys.species.add({"fluid", false});
    sys.pairs = PairTable(1);
    sys.pairs.set(0, 0, {0.0, 0.0, 0.0, true});
    sys.forceParameters = {1.0, 2.0, 0.0, 0.01};
    sys.walls.addPlane(stripedWall("lower", -3, 1, 4.0, 0.5, 4.0));  // gas sectors: 0 <= x mod 4 < 2
    sys.particles.add(0, 0, 1.0, 1.5, -2.2, 1.0, 0.0, 0.0);
    sys.particles.add(1, 0, 7.0, 1.5, -2.2, 1.0, 0.0, 0.0);
    sys.initialise();
    sys.sortByCell();
    sys.computeForces();
    for (std::size_t i = 0; i < 2; ++i) {
        const double gamma = sys.particles.id[i] == 0 ? 0.5 : 4.0;
        EXPECT_NEAR(sys.particles.fx[i], -gamma * 0.2, 1e-12) << "particle " << sys.particles.id[i];
    }
}

TEST(StripedTunableSlipWall, WithTheSameFrictionEverywhereItIsThePlainWallToTheBit) {
    System plain = channel(3.0, 1.0, 2.0, 0.0, 0.0);
    System striped = channel(3.0, 1.0, 2.0, 2.0, 5.0);
    GrootWarrenIntegrator gw(0.65);
    for (int k = 0; k < 200; ++k) {
        gw.step(plain);
        gw.step(striped);
    }
    ASSERT_EQ(plain.particles.size(), striped.particles.size());
    for (std::size_t i = 0; i < plain.particles.size(); ++i) {
        ASSERT_EQ(plain.particles.rx[i], striped.particles.rx[i]);
        ASSERT_EQ(plain.particles.vz[i], striped.particles.vz[i]);
    }
}

// Statistics: within zc = 1 of the two walls, gas (gamma_L 0.1) and no-slip (4) sectors of period 5
// each hold ~60 particles; kT and density per sector are sampled every 20 steps for 8000 steps after
// 1000, SE from 8 blocks of 1000 steps. Derived: one sample's kT of 60 particles has sd sqrt(2/180) =
// 0.105, the near-wall fluid renews within ~0.5 time units (50 steps), so ~160 independent samples
// give SE ~ 0.008 per sector and ~0.012 for the difference; density: Poisson sd sqrt(60)/60 per
// sample, SE of the relative difference ~0.016. Budgets 0.02 and 0.03; bounds 4 budgets.
TEST(StripedTunableSlipWall, AtRestTheFluidIsTheSameInFrontOfEverySector) {
    System sys = channel(3.0, 1.0, 4.0, 0.1, 5.0);
    GrootWarrenIntegrator gw(0.65);
    for (int k = 0; k < 1000; ++k) gw.step(sys);
    std::vector<double> kTDifference, densityRatio;
    for (int k = 1; k <= 8000; ++k) {
        gw.step(sys);
        if (k % 20) continue;
        double v2[2] = {0, 0}, n[2] = {0, 0};
        const Particles& p = sys.particles;
        for (std::size_t i = 0; i < p.size(); ++i) {
            if (std::abs(p.rz[i]) < 2.0) continue;  // within zc of a wall
            const int gas = stripedWall("lower", -3.0, 1, 4.0, 0.1, 5.0).stripes.isGas(p.rx[i]) ? 1 : 0;
            v2[gas] += p.vx[i] * p.vx[i] + p.vy[i] * p.vy[i] + p.vz[i] * p.vz[i];
            n[gas] += 1;
        }
        kTDifference.push_back(v2[1] / (3 * n[1]) - v2[0] / (3 * n[0]));
        densityRatio.push_back(n[1] / n[0] - 1.0);
    }
    const auto blockMeans = [](const std::vector<double>& x) {
        std::vector<double> m(8, 0.0);
        for (std::size_t k = 0; k < x.size(); ++k) m[k * 8 / x.size()] += x[k] * 8.0 / x.size();
        return m;
    };
    const std::vector<double> dk = blockMeans(kTDifference), dr = blockMeans(densityRatio);
    double meanK = 0, meanR = 0;
    for (int b = 0; b < 8; ++b) { meanK += dk[b] / 8; meanR += dr[b] / 8; }
    const double seK = standardErrorOfMean(dk), seR = standardErrorOfMean(dr);
    std::printf("    kT(gas) - kT(no slip) %.4f +- %.4f; density gas / no slip - 1: %.4f +- %.4f\n", meanK, seK, meanR, seR);
    EXPECT_TRUE(seK <= 0.02) << "too noisy to decide: " << seK;
    EXPECT_TRUE(std::abs(meanK) <= 0.08) << meanK;
    EXPECT_TRUE(seR <= 0.03) << "too noisy to decide: " << seR;
    EXPECT_TRUE(std::abs(meanR) <= 0.12) << meanR;
}

TEST(StripedTunableSlipWall, ABoxWithoutWholePeriodsIsRefused) {
    const PlanarWallSettings w = stripedWall("lower", -3, 1, 4.0, 0.1, 3.0);
    const std::unique_ptr<Wall> striped = makePlanarWall(w, 0);
    const Wall& wall = *striped;
    Box box;
    box.lo = Eigen::Vector3d(0, 0, -4);
    box.hi = Eigen::Vector3d(10, 3, 4);
    EXPECT_NE(wall.unfitFor(box).find("not a whole number of stripe periods 3"), std::string::npos) << wall.unfitFor(box);
    box.hi.x() = 9;
    EXPECT_EQ(wall.unfitFor(box), "");
}
