// Bond forces (docs/methods.md section 4): the FENE spring is minus the gradient of its energy; a bond
// is followed through the periodic boundary even when longer than half the box; an overstretched bond
// is reported, never turned into a NaN; bonds conserve momentum; the result does not depend on the
// number of threads; a rank of a decomposed run takes its own particles' bonds only; bondedPairs takes
// back exactly the part of the DPD pair force it leaves out.
#include "ChainTestSystems.hpp"
#include "forces/BondForceLoop.hpp"
#include "integrators/GrootWarrenIntegrator.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>

using namespace dpd;

namespace {

// Two particles joined by one bond in a box 10 x 3 x 10 (the published channel is 3 thick).
struct Dimer {
    Particles p;
    Box box;
    ChainBonds bonds;
    Dimer(const Eigen::Vector3d& r0, const Eigen::Vector3d& r1, const Eigen::Vector3d& vector) {
        box.lo = {-5, -1.5, -5};
        box.hi = {5, 1.5, 5};
        p.add(0, 0, r0.x(), r0.y(), r0.z());
        p.add(1, 0, r1.x(), r1.y(), r1.z());
        Bonds b;
        b.add(0, 1, 0, vector);
        bonds = ChainBonds(b);
        bonds.locate(p);
    }
};

}  // namespace

TEST(FeneBond, ForceIsMinusTheGradientOfItsEnergy) {
    const FeneBond fene(6.0, 3.0);
    for (double r : {0.1, 0.5, 1.0, 2.0, 2.9}) {
        const double h = 1e-6;
        const double numeric = -(fene.energy(r + h) - fene.energy(r - h)) / (2 * h);
        const double force = fene.forceOverR(r * r) * r;  // along the bond, on the second particle
        EXPECT_NEAR(force, numeric, 1e-6 * std::abs(numeric)) << "r = " << r;
    }
    // The closed form at one point: F = -H r / (1 - (r/rMax)^2).
    EXPECT_DOUBLE_EQ(fene.forceOverR(4.0) * 2.0, -6.0 * 2.0 / (1.0 - 4.0 / 9.0));
}

TEST(BondPass, FollowsABondLongerThanHalfTheBoxThroughTheBoundary) {
    // y: -1 and +1 are 2 apart along the bond; the minimum image would say -1.
    Dimer d({0, -1.0, 0}, {0, 1.0, 0}, {0, 2.0, 0});
    const FeneBond fene(6.0, 3.0);
    BondPassResult r = fene.addForces(d.bonds, d.p, d.box);
    ASSERT_TRUE(r.ok());
    EXPECT_DOUBLE_EQ(d.bonds.bonds().by[0], 2.0);
    const double f = 6.0 * 2.0 / (1.0 - 4.0 / 9.0);
    EXPECT_DOUBLE_EQ(d.p.fy[0], f);   // pulled towards +y, where its partner is along the bond
    EXPECT_DOUBLE_EQ(d.p.fy[1], -f);
    // The second particle moves on by 0.8 and is wrapped to -1.2: the bond is 2.8 long, not -0.2.
    d.p.ry[1] = -1.2;
    d.p.clearForces();
    r = fene.addForces(d.bonds, d.p, d.box);
    ASSERT_TRUE(r.ok());
    EXPECT_NEAR(d.bonds.bonds().by[0], 2.8, 1e-12);
    EXPECT_NEAR(std::sqrt(r.longest2), 2.8, 1e-12);
    EXPECT_GT(d.p.fy[0], 0.0);
}

TEST(BondPass, ReportsAnOverstretchedBondInsteadOfANaN) {
    Dimer d({0, 0, -1.5}, {0, 0, 1.6}, {0, 0, 3.1});
    const FeneBond fene(6.0, 3.0);
    const BondPassResult r = fene.addForces(d.bonds, d.p, d.box);
    EXPECT_EQ(r.broken, 0);
    EXPECT_NEAR(r.brokenLength, 3.1, 1e-12);
    for (std::size_t i = 0; i < 2; ++i) EXPECT_EQ(d.p.fz[i], 0.0);  // no force from a broken bond
    // A NaN position is a broken bond too.
    Dimer n({0, 0, 0}, {0, 0, NAN}, {0, 0, 1.0});
    EXPECT_EQ(fene.addForces(n.bonds, n.p, n.box).broken, 0);
}

namespace {

// A chain 0-1-2 in the Dimer's box, and which of its particles a rank holds, in the order given.
struct HeldTrimer {
    Box box;
    Bonds b;
    Particles all;
    HeldTrimer() {
        box.lo = {-5, -1.5, -5};
        box.hi = {5, 1.5, 5};
        all.add(0, 0, 0.0, 0.0, 0.0);
        all.add(1, 0, 1.0, 0.2, 0.0);
        all.add(2, 0, 1.5, 0.7, 0.4);
        b.add(0, 1, 0, {1.0, 0.2, 0.0});
        b.add(1, 2, 0, {0.5, 0.5, 0.4});
    }
    Particles held(std::initializer_list<std::uint64_t> ids) const {
        Particles p;
        for (const std::uint64_t id : ids) p.add(id, 0, all.rx[id], all.ry[id], all.rz[id]);
        return p;
    }
    // Bonds as a rank holds them: located once with every particle, then with the held ones.
    ChainBonds onRank(const Particles& p, std::size_t ownFirst, std::size_t ownEnd) const {
        ChainBonds c(b);
        c.locate(all);
        c.holdPartOnly();
        c.locate(p);
        c.setOwned(ownFirst, ownEnd);
        return c;
    }
};

}  // namespace

// A rank of a decomposed run takes the bonds of its own particles only: its own particle gets the
// force one process gives it (to the bit); a bond between two ghosts is left alone, vector and
// forces; one whose other particle the rank does not hold is broken, of unseen length.
TEST(BondPass, OnARankTakesOnlyTheBondsOfItsOwnParticles) {
    const HeldTrimer t;
    const FeneBond fene(6.0, 3.0);
    Particles whole = t.all;
    ChainBonds serial(t.b);
    serial.locate(whole);
    ASSERT_TRUE(fene.addForces(serial, whole, t.box).ok());

    // Particle 1 owned, both neighbours ghosts (stored after it).
    Particles middle = t.held({1, 2, 0});
    ChainBonds onMiddle = t.onRank(middle, 0, 1);
    ASSERT_TRUE(fene.addForces(onMiddle, middle, t.box).ok());
    EXPECT_EQ(middle.fx[0], whole.fx[1]);
    EXPECT_EQ(middle.fy[0], whole.fy[1]);
    EXPECT_EQ(middle.fz[0], whole.fz[1]);

    // Particle 0 owned: its bond is taken; bond 1-2 joins two ghosts and is left as it was.
    Particles end = t.held({1, 0, 2});
    ChainBonds onEnd = t.onRank(end, 1, 2);
    onEnd.bonds().bx[1] = 9.0;  // a stale vector, which only the ranks of 1 and 2 follow
    ASSERT_TRUE(fene.addForces(onEnd, end, t.box).ok());
    EXPECT_EQ(end.fx[1], whole.fx[0]);
    EXPECT_EQ(end.fy[1], whole.fy[0]);
    EXPECT_EQ(onEnd.bonds().bx[1], 9.0);
    EXPECT_EQ(end.fx[2], 0.0);
    EXPECT_EQ(onEnd.bonds().bx[0], serial.bonds().bx[0]);

    // Particle 1 alone: both of its bonds reach beyond what the rank holds; the first is reported.
    Particles alone = t.held({1});
    ChainBonds onAlone = t.onRank(alone, 0, 1);
    const BondPassResult r = fene.addForces(onAlone, alone, t.box);
    EXPECT_EQ(r.broken, 0);
    EXPECT_EQ(r.brokenLength, kUnseenBondLength);
    EXPECT_EQ(alone.fx[0], 0.0);

    // A particle's bonds, for its vectors to travel with it.
    const auto [first, last] = onAlone.bondsOf(1);
    EXPECT_EQ(std::vector<std::uint32_t>(first, last), (std::vector<std::uint32_t>{0, 1}));
    const auto [headFirst, headLast] = onAlone.bondsOf(0);
    EXPECT_EQ(std::vector<std::uint32_t>(headFirst, headLast), std::vector<std::uint32_t>{0});
}

TEST(BondPass, ConservesMomentumAndDoesNotDependOnTheThreads) {
    test::ChainScene scene;
    scene.fluid.particles = 3000;
    scene.fluid.a = 25.0;
    scene.fluid.dt = 0.02;
    scene.chains = 30;
    scene.length = 10;
    const int threads = omp_get_max_threads();
    std::vector<System> runs;
    for (int t : {1, 2}) {
        omp_set_num_threads(t);
        System sys = test::makeChainedFluid(scene);
        ASSERT_EQ(sys.bonds.size(), 30u * 9u);
        Eigen::Vector3d p0(0, 0, 0);
        for (std::size_t i = 0; i < sys.particles.size(); ++i) p0 += Eigen::Vector3d(sys.particles.vx[i], sys.particles.vy[i], sys.particles.vz[i]);
        GrootWarrenIntegrator gw(0.65);
        for (int k = 0; k < 300; ++k) gw.step(sys);
        ASSERT_TRUE(sys.bondPass().ok());
        Eigen::Vector3d p1(0, 0, 0);
        for (std::size_t i = 0; i < sys.particles.size(); ++i) p1 += Eigen::Vector3d(sys.particles.vx[i], sys.particles.vy[i], sys.particles.vz[i]);
        // Round-off: ~1e-16 relative per force term, 3000 particles x 300 steps of forces ~ 100.
        EXPECT_LT((p1 - p0).norm(), 1e-9) << t << " thread(s)";
        runs.push_back(std::move(sys));
    }
    omp_set_num_threads(threads);
    const Particles& a = runs[0].particles;
    const Particles& b = runs[1].particles;
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        ASSERT_EQ(a.id[i], b.id[i]);
        ASSERT_EQ(a.rx[i], b.rx[i]);
        ASSERT_EQ(a.vz[i], b.vz[i]);
    }
    for (std::size_t k = 0; k < runs[0].bonds.size(); ++k) ASSERT_EQ(runs[0].bonds.bonds().bz[k], runs[1].bonds.bonds().bz[k]);
}

// A lone dimer 0.6 apart: with bondedPairs the pair feels FENE plus the part of the DPD force it keeps.
class BondedPairsTest : public ::testing::Test {
protected:
    System dimer(BondedPairs rule) {
        System sys;
        sys.box.lo = {0, 0, 0};
        sys.box.hi = {5, 5, 5};
        sys.species.add({"polymer", false});
        sys.pairs = PairTable(1);
        sys.pairs.set(0, 0, {25.0, 4.5, 0.0, true});
        sys.forceParameters = {1.0, 2.0, 1.0, 0.01};
        sys.seed = 9;
        sys.particles.add(3, 0, 2.0, 2.5, 2.5, 0.3, -0.2, 0.1);
        sys.particles.add(8, 0, 2.6, 2.5, 2.5, -0.4, 0.5, 0.0);
        Bonds b;
        b.add(3, 8, 0, {0.6, 0, 0});
        sys.bonds = ChainBonds(b);
        sys.bondPotential = std::make_shared<FeneBond>(6.0, 3.0);
        sys.bondedPairs = rule;
        sys.step = 17;
        sys.initialise();
        sys.sortByCell();
        sys.computeForces();
        return sys;
    }
    // The force on particle id 3 along x.
    static double forceOnFirst(const System& sys) {
        for (std::size_t i = 0; i < sys.particles.size(); ++i)
            if (sys.particles.id[i] == 3) return sys.particles.fx[i];
        return NAN;
    }
};

TEST_F(BondedPairsTest, TakesBackTheLeftOutTermsOfTheDpdForce) {
    const double fene = -(FeneBond(6.0, 3.0).forceOverR(0.36) * 0.6);  // on the first particle, along +x
    // The DPD terms on the first particle, evaluated here from the formula (docs/methods.md 1):
    // r_ij = -0.6 x, e_ij = -x, v_ij = (0.7, -0.7, 0.1), w = 0.4.
    const PairRandom random(9);
    const double zeta = random.pairUniform(17, 3, 8);
    const double w = 0.4, eDotV = -0.7;
    const double conservative = 25.0 * w, dissipative = -4.5 * w * w * eDotV, randomTerm = 3.0 * w * zeta / std::sqrt(0.01);
    const double all = -(conservative + dissipative + randomTerm);  // along e_ij = -x
    const double tolerance = 1e-5 * (std::abs(all) + std::abs(fene));  // the pair loop's float separations
    EXPECT_NEAR(forceOnFirst(dimer({})), fene + all, tolerance);
    BondedPairs none;
    none.mode = BondedPairs::Mode::none;
    EXPECT_NEAR(forceOnFirst(dimer(none)), fene, tolerance);
    BondedPairs weighted;
    weighted.mode = BondedPairs::Mode::weighted;
    weighted.weight = 0.25;
    EXPECT_NEAR(forceOnFirst(dimer(weighted)), fene - (conservative + 0.25 * dissipative + 0.5 * randomTerm), tolerance);
}
