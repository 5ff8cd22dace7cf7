// The bounce-layer and modified bounce-forward rules (docs/walls.md 3.2 steps 5-6 and 3.3), moving walls
// carrying their frozen particles, and each rule's signature on a gas or a DPD fluid: specular walls
// slip, bounce-back walls drag the fluid, Maxwellian walls hold the wall temperature, a bounce layer
// far too thin lets particles through and the crossings are counted.
#include "../support/WallRuleNamed.hpp"
#include "forces/UniformBodyForce.hpp"
#include "integrators/GrootWarrenIntegrator.hpp"
#include "setup/InitialConditions.hpp"
#include "system/System.hpp"
#include "setup/FrozenLattice.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>

using namespace dpd;

namespace {

PlanarWallSettings makeWall(const std::string& name, double z, double normalZ, const std::string& rule,
                    const Eigen::Vector3d& velocity = Eigen::Vector3d::Zero(), double layer = 0.0) {
    PlanarWallSettings w;
    w.name = name;
    w.point = Eigen::Vector3d(0, 0, z);
    w.normal = Eigen::Vector3d(0, 0, normalZ);
    w.rule = test::ruleNamed(rule, layer);
    w.velocity = velocity;
    return w;
}

// One mobile particle in a 10^3 box, alone (no pair forces), with an optional uniform body force.
System lonely(const PlanarWallSettings& w, const Eigen::Vector3d& r, const Eigen::Vector3d& v, double dt,
              const Eigen::Vector3d& g = Eigen::Vector3d::Zero()) {
    System sys;
    sys.box.hi = Eigen::Vector3d(10, 10, 10);
    sys.species.add({"fluid", false});
    sys.pairs = PairTable(1);
    sys.pairs.set(0, 0, {25.0, 4.5, 0.0, true});
    sys.forceParameters = {1.0, 2.0, 1.0, dt};
    sys.seed = 11;
    if (g.squaredNorm() > 0.0) {
        sys.bodyForce = std::make_shared<UniformBodyForce>(g);
    }
    sys.walls.addPlane(w);
    sys.particles.add(7, 0, r.x(), r.y(), r.z(), v.x(), v.y(), v.z());
    sys.initialise();
    sys.sortByCell();
    sys.computeForces();
    return sys;
}

Eigen::Vector3d pos(const System& s) { return {s.particles.rx[0], s.particles.ry[0], s.particles.rz[0]}; }
Eigen::Vector3d vel(const System& s) { return {s.particles.vx[0], s.particles.vy[0], s.particles.vz[0]}; }

constexpr double kTol = 1e-12;

void expectNear(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const char* what) {
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(a[k], b[k], kTol) << what << " component " << k;
}

}  // namespace

// Wall z = 2 (normal +z) sliding at u_w = (0.3, 0.2, 0); body force g = (0.5, 0, -3); dt = 0.01. From
// z = 2.05 with v = (1, 0, -10), Groot-Warren: half kick h = v + dt g / 2 = (1.0025, 0, -10.015), drift to
// z = 2.05 - 0.10015 = 1.94985 (0.05015 behind the plane), full kick v + dt g = (1.005, 0, -10.03).
//   bounce-forward: the step is finished at the penetrated position, then the particle is mirrored to
//     z = 2.05015 and that velocity is reversed relative to the wall: 2 u_w - (v + dt g) = (-0.405, 0.4, 10.03);
//   bounce-back reverses the half-kicked velocity instead: 2 u_w - h + dt g / 2 = (-0.4, 0.4, 10.0).
TEST(WallRules, BounceForwardReversesTheVelocityAfterTheStep) {
    const Eigen::Vector3d uw(0.3, 0.2, 0.0), g(0.5, 0.0, -3.0);
    GrootWarrenIntegrator gw(0.65);
    System forward = lonely(makeWall("w", 2, 1, "bounceForward", uw), {5, 5, 2.05}, {1, 0, -10}, 0.01, g);
    const WallCounters c = gw.step(forward);
    expectNear(pos(forward), {5.010025, 5.0, 2.05015}, "bounceForward position");
    expectNear(vel(forward), {-0.405, 0.4, 10.03}, "bounceForward velocity");
    EXPECT_EQ(c.returned[0], 1);
    EXPECT_EQ(c.crossed[0], 1);
    EXPECT_EQ(c.insideAfter, 0);  // deferred, not left inside
    System back = lonely(makeWall("w", 2, 1, "bounceBack", uw), {5, 5, 2.05}, {1, 0, -10}, 0.01, g);
    gw.step(back);
    expectNear(pos(back), {5.010025, 5.0, 2.05015}, "bounceBack position");
    expectNear(vel(back), {-0.4, 0.4, 10.0}, "bounceBack velocity");
    // reverseFrame lab: the same step, the velocity reversed itself, -(v + dt g) = (-1.005, 0, 10.03).
    PlanarWallSettings lab = makeWall("w", 2, 1, "bounceForward", uw);
    lab.rule = test::ruleNamed("bounceForward", 0.0, true);
    System labFrame = lonely(lab, {5, 5, 2.05}, {1, 0, -10}, 0.01, g);
    gw.step(labFrame);
    expectNear(pos(labFrame), {5.010025, 5.0, 2.05015}, "bounceForward (lab frame) position");
    expectNear(vel(labFrame), {-1.005, 0.0, 10.03}, "bounceForward (lab frame) velocity");
}

// Bounce layer 0.1 thick in front of z = 2 (wall at rest), dt = 0.001 so a particle moves 0.002 at most.
TEST(WallRules, BounceLayerTurnsApproachingParticlesRound) {
    GrootWarrenIntegrator gw(0.65);
    const PlanarWallSettings w = makeWall("w", 2, 1, "bounceLayer", Eigen::Vector3d::Zero(), 0.1);
    // In the layer, approaching: tangential velocity reversed, normal drawn from the wall (> 0), no mirror.
    System in = lonely(w, {5, 5, 2.03}, {1, 0.5, -2}, 0.001);
    WallCounters c = gw.step(in);
    EXPECT_NEAR(vel(in).x(), -1.0, kTol);
    EXPECT_NEAR(vel(in).y(), -0.5, kTol);
    EXPECT_GT(vel(in).z(), 0.0);
    EXPECT_NEAR(pos(in).z(), 2.028, kTol);
    EXPECT_EQ(c.returned[0], 1);
    EXPECT_EQ(c.crossed[0], 0);
    // In the layer, leaving: untouched. Outside the layer, approaching: untouched.
    System leaving = lonely(w, {5, 5, 2.03}, {1, 0.5, 2}, 0.001);
    c = gw.step(leaving);
    expectNear(vel(leaving), {1, 0.5, 2}, "leaving");
    EXPECT_EQ(c.returned[0], 0);
    System outside = lonely(w, {5, 5, 2.2}, {1, 0.5, -2}, 0.001);
    c = gw.step(outside);
    expectNear(vel(outside), {1, 0.5, -2}, "outside");
    // A layer far too thin (1e-4) for a step of 0.1: the particle crosses the plane, is mirrored back,
    // turned round, and the crossing is counted.
    const PlanarWallSettings thin = makeWall("w", 2, 1, "bounceLayer", Eigen::Vector3d::Zero(), 1e-4);
    System through = lonely(thin, {5, 5, 2.05}, {0, 0, -10}, 0.01);
    c = gw.step(through);
    EXPECT_NEAR(pos(through).z(), 2.05, kTol);
    EXPECT_GT(vel(through).z(), 0.0);
    EXPECT_EQ(c.crossed[0], 1);
    EXPECT_EQ(c.returned[0], 1);
    EXPECT_EQ(c.insideAfter, 0);
}

namespace {

// An ideal gas (no pair forces) between walls at z = 1 and z = 5 of a 4 x 4 x 6 box: kGasParticles
// particles with Maxwellian velocities at kTGas; the walls' temperature is kTWall.
constexpr int kGasParticles = 600;

System gas(const std::string& rule, double layer, double kTGas, double kTWall, double dt) {
    System sys;
    sys.box.hi = Eigen::Vector3d(4, 4, 6);
    sys.species.add({"gas", false});
    sys.pairs = PairTable(1);
    sys.pairs.set(0, 0, {0.0, 0.0, 0.0, false});
    sys.forceParameters = {1.0, 2.0, kTWall, dt};
    sys.seed = 5;
    sys.walls.addPlane(makeWall("lower", 1, 1, rule, Eigen::Vector3d::Zero(), layer));
    sys.walls.addPlane(makeWall("upper", 5, -1, rule, Eigen::Vector3d::Zero(), layer));
    const PairRandom random(17);
    fillRandom(sys.particles, sys.box, Eigen::Vector3d(0, 0, 1.2), Eigen::Vector3d(4, 4, 4.8),
               kGasParticles / (4.0 * 4.0 * 3.6), 0, [](double, double, double) { return true; }, random, 0);
    maxwellVelocities(sys.particles, 0, sys.particles.size(), 3, kTGas, random);
    sys.initialise();
    sys.sortByCell();
    sys.computeForces();
    return sys;
}

double kineticTemperature(const System& sys, int component = -1) {
    const Particles& p = sys.particles;
    double sum = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const double v2[3] = {p.vx[i] * p.vx[i], p.vy[i] * p.vy[i], p.vz[i] * p.vz[i]};
        sum += component < 0 ? (v2[0] + v2[1] + v2[2]) / 3.0 : v2[component];
    }
    return sum / p.size();
}

WallCounters run(System& sys, int steps) {
    GrootWarrenIntegrator gw(0.65);
    WallCounters total;
    for (int k = 0; k < steps; ++k) total.accumulate(gw.step(sys));
    return total;
}

}  // namespace

// A gas at kT = 2 between walls at kT = 1, 4 apart. In t = 40 a particle crosses the channel about
// 40 x 0.9 / 4 ~ 9 times (mean |v_z| = sqrt(2 kT / pi) ~ 0.8 to 1.1), so all but ~ exp(-9) of them
// have been re-emitted by a wall. A Maxwellian wall emits the flux-weighted Maxwellian at its
// temperature, whose steady state in the gas is the Maxwellian at kT = 1; bounce-back conserves
// energy and keeps kT = 2 exactly. The temperature of N = 600 independent particles has standard
// error kT sqrt(2 / (3N)) = 0.033; the mean of 5 snapshots has at most that: accept within 4 of it.
// (No pair forces: the drift is exact, so a large step dt = 0.05 is fine.)
TEST(WallRules, MaxwellianWallsHoldTheWallTemperature) {
    System maxwell = gas("maxwellian", 0.0, 2.0, 1.0, 0.05);
    run(maxwell, 800);
    double kT = 0.0;
    for (int k = 0; k < 5; ++k) {
        run(maxwell, 100);
        kT += kineticTemperature(maxwell) / 5.0;
    }
    std::printf("    Maxwellian walls at kT = 1, gas started at 2: kT = %.4f\n", kT);
    EXPECT_NEAR(kT, 1.0, 4.0 * std::sqrt(2.0 / (3.0 * kGasParticles)));
    System bounce = gas("bounceBack", 0.0, 2.0, 1.0, 0.05);
    const double before = kineticTemperature(bounce);
    run(bounce, 800);
    EXPECT_NEAR(kineticTemperature(bounce), before, 1e-9 * before) << "bounce-back conserves the gas's energy";
}

// The bounce layer draws the normal velocity at the wall temperature and reverses the tangential
// one: the normal temperature of the gas goes to the wall's (1), the tangential stays at 2 (standard
// error per component sqrt(2 / N) kT = 0.058 kT for N = 600; accept 4 of them). A layer of 0.1 with
// dt = 0.01: crossing it needs |v_z| > 10, a chance of about exp(-50 / kT) per particle: none. A
// layer of 1e-4: most particles reaching the wall jump it (v_z dt ~ 0.01), and each is counted.
TEST(WallRules, BounceLayerThermalisesTheNormalVelocityAndCountsItsFailures) {
    System good = gas("bounceLayer", 0.1, 2.0, 1.0, 0.01);
    const WallCounters c = run(good, 2500);
    double kz = 0.0, kx = 0.0;
    for (int k = 0; k < 5; ++k) {
        run(good, 300);
        kz += kineticTemperature(good, 2) / 5.0;
        kx += 0.5 * (kineticTemperature(good, 0) + kineticTemperature(good, 1)) / 5.0;
    }
    std::printf("    bounce layer 0.1: normal kT %.4f (wall 1), tangential kT %.4f (gas 2), returned %ld, crossed %ld\n",
                kz, kx, c.returned[0] + c.returned[1], c.crossed[0] + c.crossed[1]);
    EXPECT_NEAR(kz, 1.0, 4.0 * std::sqrt(2.0 / kGasParticles));
    EXPECT_NEAR(kx, 2.0, 4.0 * 2.0 * std::sqrt(2.0 / (2.0 * kGasParticles)));
    EXPECT_GT(c.returned[0], kGasParticles);
    EXPECT_EQ(c.crossed[0] + c.crossed[1], 0);
    EXPECT_EQ(c.insideAfter, 0);

    System thin = gas("bounceLayer", 1e-4, 1.0, 1.0, 0.01);
    const WallCounters t = run(thin, 500);
    std::printf("    bounce layer 1e-4: returned %ld, crossed %ld\n", t.returned[0] + t.returned[1],
                t.crossed[0] + t.crossed[1]);
    EXPECT_GT(t.crossed[0] + t.crossed[1], (t.returned[0] + t.returned[1]) / 2);
    EXPECT_EQ(t.insideAfter, 0) << "crossings are mirrored back";
}

namespace {

// Couette between reflecting walls at z = 1 and 7 (no frozen particles) sliding at -U and +U; a DPD
// fluid rho = 3, a = 25, gamma = 4.5, 5 x 5 between the walls, dt = 0.02.
System couette(const std::string& rule, double U) {
    System sys;
    sys.box.hi = Eigen::Vector3d(5, 5, 8);
    sys.species.add({"fluid", false});
    sys.pairs = PairTable(1);
    sys.pairs.set(0, 0, {25.0, 4.5, 0.0, true});
    sys.forceParameters = {1.0, 2.0, 1.0, 0.02};
    sys.seed = 23;
    sys.walls.addPlane(makeWall("lower", 1, 1, rule, Eigen::Vector3d(-U, 0, 0)));
    sys.walls.addPlane(makeWall("upper", 7, -1, rule, Eigen::Vector3d(U, 0, 0)));
    const PairRandom random(29);
    fillRandom(sys.particles, sys.box, Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(5, 5, 7), 3.0, 0,
               [](double, double, double) { return true; }, random, 0);
    maxwellVelocities(sys.particles, 0, sys.particles.size(), 3, 1.0, random);
    sys.initialise();
    sys.sortByCell();
    sys.computeForces();
    return sys;
}

// Mean vx of the fluid within 1.5 of the upper wall, sampled every 10 steps over `steps` steps.
double nearUpperWallVelocity(System& sys, int steps) {
    double sum = 0.0;
    long n = 0;
    GrootWarrenIntegrator gw(0.65);
    for (int k = 1; k <= steps; ++k) {
        gw.step(sys);
        if (k % 10) continue;
        for (std::size_t i = 0; i < sys.particles.size(); ++i)
            if (sys.particles.rz[i] > 5.5) { sum += sys.particles.vx[i]; ++n; }
    }
    return sum / n;
}

}  // namespace

// Specular walls exert no tangential force: the fluid's x momentum stays exactly what it was (zero,
// up to rounding) however fast the walls slide. Bounce-back walls drag the fluid: after 2000 steps
// (t = 40, three times the slowest relaxation time d^2 / (pi^2 nu) ~ 36 / (9.9 x 0.29) = 13) the
// fluid next to the upper wall moves with it. Its mean velocity, averaged over ~ 200 particles x 200
// samples, has a standard error below 0.02 (thermal sqrt(kT) = 1 over at least ~2500 independent
// values); a linear Couette profile puts it at 0.6-0.9 U for slip lengths between 0 and 1, so
// accepting > 0.5 U tells a no-slip wall from a slipping one (specular: 0).
TEST(WallRules, SpecularWallsSlipBounceBackWallsDrag) {
    const double U = 1.0;
    System specular = couette("specular", U);
    const double uSpecular = nearUpperWallVelocity(specular, 1000);
    double px = 0.0;
    for (double v : specular.particles.vx) px += v;
    std::printf("    specular: fluid x momentum %.3g, near-wall velocity %.4f\n", px, uSpecular);
    EXPECT_NEAR(px, 0.0, 1e-9 * specular.particles.size());
    System bounce = couette("bounceBack", U);
    nearUpperWallVelocity(bounce, 2000);
    const double uBounce = nearUpperWallVelocity(bounce, 2000);
    std::printf("    bounce-back: near-wall velocity %.4f (wall %.1f)\n", uBounce, U);
    EXPECT_GT(uBounce, 0.5 * U);
    EXPECT_LT(uBounce, U + 0.1);
}

// Frozen particles behind a sliding wall take its velocity when the system is initialised, drift with
// it, wrap round the periodic box, and keep the velocity whatever the fluid does to them.
TEST(WallRules, MovingWallsCarryTheirFrozenParticlesAndWrap) {
    System sys;
    sys.box.hi = Eigen::Vector3d(4, 4, 8);
    sys.species.add({"fluid", false});
    sys.species.add({"wall", true});
    sys.pairs = PairTable(2);
    sys.pairs.set(0, 0, {25.0, 4.5, 0.0, true});
    sys.pairs.set(0, 1, {25.0, 4.5, 0.0, true});
    sys.forceParameters = {1.0, 2.0, 1.0, 0.02};
    const Eigen::Vector3d uLow(-3, 0, 0), uHigh(3, 0.5, 0);
    const PlanarWallSettings planes[2] = {makeWall("lower", 1.5, 1, "bounceForward", uLow),
                                          makeWall("upper", 6.5, -1, "bounceForward", uHigh)};
    for (const PlanarWallSettings& w : planes) sys.walls.addPlane(w);
    const PairRandom random(3);
    fillRandom(sys.particles, sys.box, Eigen::Vector3d(0, 0, 1.5), Eigen::Vector3d(4, 4, 6.5), 3.0, 0,
               [](double, double, double) { return true; }, random, 0);
    maxwellVelocities(sys.particles, 0, sys.particles.size(), 3, 1.0, random);
    FrozenLatticeSettings lattice;
    lattice.density = 3.0;
    std::uint64_t id = 100000;
    std::map<std::uint64_t, Eigen::Vector3d> start;
    for (const PlanarWallSettings& w : planes)
        for (const Eigen::Vector3d& r : frozenLattice(sys.box, w, lattice)) {
            sys.particles.add(id, 1, r.x(), r.y(), r.z());  // at rest: the system gives them the wall's velocity
            start[id++] = r;
        }
    sys.initialise();
    ASSERT_EQ(sys.frozenPerWall().size(), 2u);
    EXPECT_EQ(sys.frozenPerWall()[0] + sys.frozenPerWall()[1], static_cast<long>(start.size()));
    EXPECT_GT(sys.frozenPerWall()[0], 0);
    sys.sortByCell();
    sys.computeForces();
    GrootWarrenIntegrator gw(0.65);
    const int steps = 150;  // t = 3: the lower wall moves 9 = more than two box lengths along x
    WallCounters total;
    for (int k = 0; k < steps; ++k) total.accumulate(gw.step(sys));
    const double t = steps * 0.02;
    for (std::size_t i = 0; i < sys.particles.size(); ++i) {
        if (!sys.isFrozen(i)) continue;
        const Eigen::Vector3d r0 = start.at(sys.particles.id[i]);
        const Eigen::Vector3d u = r0.z() < 4 ? uLow : uHigh;
        EXPECT_EQ(sys.particles.vx[i], u.x());
        EXPECT_EQ(sys.particles.vy[i], u.y());
        const Eigen::Vector3d expected(sys.box.wrap(r0.x() + u.x() * t, 0), sys.box.wrap(r0.y() + u.y() * t, 1), r0.z());
        EXPECT_NEAR(sys.particles.rx[i], expected.x(), 1e-9);
        EXPECT_NEAR(sys.particles.ry[i], expected.y(), 1e-9);
        EXPECT_EQ(sys.particles.rz[i], r0.z());
        ASSERT_GE(sys.particles.rx[i], 0.0);
        ASSERT_LT(sys.particles.rx[i], 4.0);
    }
    EXPECT_EQ(total.insideAfter, 0);
}
