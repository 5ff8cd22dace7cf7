// Trajectories are a function of the state and the seed alone: bit-identical on one thread and on two
// (the slab-coloured pair loop fixes the summation order; the random numbers are keyed by seed, step
// and ids), identical for the same seed, different for different seeds.
#include "../support/WallRuleNamed.hpp"
#include "forces/UniformBodyForce.hpp"
#include "integrators/EulerIntegrator.hpp"
#include "integrators/GrootWarrenIntegrator.hpp"
#include "setup/InitialConditions.hpp"
#include "setup/StandardFluid.hpp"
#include "system/System.hpp"
#include "setup/FrozenLattice.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <cstring>
#include <functional>

using namespace dpd;

namespace {

// Restores the OpenMP thread count when a test ends, whatever happens.
class ThreadCount {
public:
    ThreadCount() : saved_(omp_get_max_threads()) {}
    ~ThreadCount() { omp_set_num_threads(saved_); }

private:
    int saved_;
};

template <class T, class Allocator>
bool sameBits(const std::vector<T, Allocator>& a, const std::vector<T, Allocator>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

void expectIdentical(const Particles& a, const Particles& b) {
    EXPECT_TRUE(sameBits(a.id, b.id)) << "ids (the cell order)";
    EXPECT_TRUE(sameBits(a.species, b.species));
    EXPECT_TRUE(sameBits(a.rx, b.rx)) << "x";
    EXPECT_TRUE(sameBits(a.ry, b.ry)) << "y";
    EXPECT_TRUE(sameBits(a.rz, b.rz)) << "z";
    EXPECT_TRUE(sameBits(a.vx, b.vx)) << "vx";
    EXPECT_TRUE(sameBits(a.vy, b.vy)) << "vy";
    EXPECT_TRUE(sameBits(a.vz, b.vz)) << "vz";
    EXPECT_TRUE(sameBits(a.fx, b.fx)) << "fx";
    EXPECT_TRUE(sameBits(a.fy, b.fy)) << "fy";
    EXPECT_TRUE(sameBits(a.fz, b.fz)) << "fz";
}

// 3-D: 2700 particles at density 3, a cube of side cbrt(900) = 9.65: 9 cells per axis (odd, so the pair
// loop's third colour is used).
StandardFluidSettings fluid3D(std::uint64_t seed) {
    StandardFluidSettings s;
    s.particles = 2700;
    s.dimension = 3;
    s.dt = 0.04;
    s.seed = seed;
    return s;
}

// 2-D: 1400 particles at density 3, a square of side sqrt(466.7) = 21.6: 21 cells per axis.
StandardFluidSettings fluid2D(std::uint64_t seed) {
    StandardFluidSettings s = fluid3D(seed);
    s.particles = 1400;
    s.dimension = 2;
    return s;
}

// A channel: fcc frozen walls behind z = 1 (maxwellian reflection, at rest) and z = 10 (bounce-back,
// sliding at 0.5 along x), fluid between, a body force along x. 9 x 5 x 11 cells. Exercises frozen
// particles (kept after the mobile ones in each cell, frozen-frozen pairs never visited), reflections
// with random draws, and the body force. With fluidWallA other than 25 the pair coefficients differ
// between pairs, and the pair loop takes them per pair (another path through it).
System channel(std::uint64_t seed, double fluidWallA = 25.0) {
    System sys;
    sys.box.lo = Eigen::Vector3d(0, 0, 0);
    sys.box.hi = Eigen::Vector3d(9.5, 5.2, 11.0);
    sys.species.add({"fluid", false});
    sys.species.add({"wall", true});
    sys.pairs = PairTable(2);
    sys.pairs.set(0, 0, {25.0, 4.5, 0.0, true});
    sys.pairs.set(0, 1, {fluidWallA, 4.5, 0.0, true});
    sys.pairs.set(1, 1, {25.0, 4.5, 0.0, true});
    sys.forceParameters = {1.0, 2.0, 1.0, 0.04};
    sys.seed = seed;
    PlanarWallSettings lower;
    lower.name = "lower";
    lower.point = Eigen::Vector3d(0, 0, 1.0);
    lower.normal = Eigen::Vector3d(0, 0, 1);
    lower.rule = test::ruleNamed("maxwellian");
    PlanarWallSettings upper;
    upper.name = "upper";
    upper.point = Eigen::Vector3d(0, 0, 10.0);
    upper.normal = Eigen::Vector3d(0, 0, -1);
    upper.velocity = Eigen::Vector3d(0.5, 0, 0);
    upper.rule = test::ruleNamed("bounceBack");
    sys.walls.addPlane(lower);
    sys.walls.addPlane(upper);
    sys.bodyForce = std::make_shared<UniformBodyForce>(Eigen::Vector3d(0.2, 0, 0));
    const PairRandom random(seed);
    fillRandom(sys.particles, sys.box, Eigen::Vector3d(0, 0, 1.0), Eigen::Vector3d(9.5, 5.2, 10.0), 3.0, 0,
               [](double, double, double) { return true; }, random, 0);
    maxwellVelocities(sys.particles, 0, sys.particles.size(), 3, 1.0, random);
    FrozenLatticeSettings lattice;
    lattice.lattice = "fcc";
    lattice.density = 3.0;
    lattice.thickness = 1.0;
    std::uint64_t id = 1000000;
    for (const PlanarWallSettings& w : {lower, upper})
        for (const Eigen::Vector3d& r : frozenLattice(sys.box, w, lattice))
            sys.particles.add(id++, 1, r.x(), r.y(), r.z(), w.velocity.x(), w.velocity.y(), w.velocity.z());
    sys.initialise();
    sys.sortByCell();
    sys.computeForces();
    return sys;
}

Particles run(const std::function<System()>& make, const std::string& scheme, int threads, int steps,
              long* reflections = nullptr) {
    omp_set_num_threads(threads);
    System sys = make();
    IntegratorSettings s;
    s.type = scheme;
    auto integrator = makeIntegrator(s);
    long returned = 0;
    for (int k = 0; k < steps; ++k)
        for (long r : integrator->step(sys).returned) returned += r;
    if (reflections) *reflections = returned;
    return sys.particles;
}

}  // namespace

TEST(Determinism, OneAndTwoThreadsGiveIdenticalTrajectories3D) {
    ThreadCount restore;
    const auto make = [] { return makeStandardFluid(fluid3D(5)); };
    EXPECT_EQ(make().cells().cellsPerAxis()[0], 9);
    for (const std::string& scheme : integratorTypes()) {
        SCOPED_TRACE(scheme);
        const Particles one = run(make, scheme, 1, 50);
        const Particles two = run(make, scheme, 2, 50);
        expectIdentical(one, two);
    }
}

TEST(Determinism, OneAndTwoThreadsGiveIdenticalTrajectories2D) {
    ThreadCount restore;
    const auto make = [] { return makeStandardFluid(fluid2D(5)); };
    EXPECT_EQ(make().cells().cellsPerAxis()[0], 21);
    for (const std::string& scheme : integratorTypes()) {
        SCOPED_TRACE(scheme);
        const Particles one = run(make, scheme, 1, 50);
        const Particles two = run(make, scheme, 2, 50);
        expectIdentical(one, two);
    }
}

TEST(Determinism, OneAndTwoThreadsGiveIdenticalTrajectoriesInAChannel) {
    ThreadCount restore;
    const auto make = [] { return channel(5); };
    EXPECT_EQ(make().cells().cellsPerAxis()[0], 9);
    for (const std::string& scheme : integratorTypes()) {
        SCOPED_TRACE(scheme);
        long reflections = 0;
        const Particles one = run(make, scheme, 1, 50, &reflections);
        EXPECT_GT(reflections, 0) << "the walls must have returned something for the test to mean much";
        const Particles two = run(make, scheme, 2, 50);
        expectIdentical(one, two);
    }
}

TEST(Determinism, OneAndTwoThreadsGiveIdenticalTrajectoriesInAChannelWithOwnWallCoefficients) {
    ThreadCount restore;
    const auto make = [] { return channel(5, 35.0); };
    const Particles one = run(make, "GrootWarren", 1, 50);
    const Particles two = run(make, "GrootWarren", 2, 50);
    expectIdentical(one, two);
    // The wall coefficients matter: the trajectory differs from the common-coefficient channel's.
    EXPECT_FALSE(sameBits(one.vx, run([] { return channel(5); }, "GrootWarren", 2, 50).vx));
}

TEST(Determinism, SameSeedSameTrajectoryDifferentSeedDifferent) {
    ThreadCount restore;
    const Particles a = run([] { return makeStandardFluid(fluid3D(5)); }, "GrootWarren", 2, 50);
    const Particles b = run([] { return makeStandardFluid(fluid3D(5)); }, "GrootWarren", 2, 50);
    expectIdentical(a, b);
    const Particles c = run([] { return makeStandardFluid(fluid3D(6)); }, "GrootWarren", 2, 50);
    EXPECT_FALSE(sameBits(a.rx, c.rx));
    EXPECT_FALSE(sameBits(a.vx, c.vx));

    // The same initial state with another seed for the pair noise only: the trajectories part at once.
    const auto reseeded = [] {
        System sys = makeStandardFluid(fluid3D(5));
        sys.seed = 6;
        sys.initialise();
        sys.sortByCell();
        sys.computeForces();
        return sys;
    };
    const Particles d = run(reseeded, "GrootWarren", 2, 1);
    const Particles e = run([] { return makeStandardFluid(fluid3D(5)); }, "GrootWarren", 2, 1);
    EXPECT_FALSE(sameBits(d.vx, e.vx)) << "a different seed must give different pair noise";
    // Channel (walls with random reflection draws, frozen particles): the same seed repeats exactly.
    const Particles f = run([] { return channel(5); }, "GrootWarren", 2, 50);
    const Particles g = run([] { return channel(5); }, "GrootWarren", 2, 50);
    expectIdentical(f, g);
}
