// The tunable-slip wall (docs/walls.md 3.5; Smiatek, Allen and Schmid 2008): its force against hand
// values, fluctuation-dissipation (a gas held only by the walls takes the walls' temperature), the WCA
// wall keeping a DPD fluid out (dt up to sigma / 50), thread independence, the predicted slip length, and the
// errors of constant/dpdProperties.
#include "../support/WallRuleNamed.hpp"
#include "../support/InputErrorOf.hpp"
#include "core/Error.hpp"
#include "forces/UniformBodyForce.hpp"
#include "integrators/GrootWarrenIntegrator.hpp"
#include "io/Dictionary.hpp"
#include "case/DpdProperties.hpp"
#include "setup/InitialConditions.hpp"
#include "system/System.hpp"
#include "sampling/BlockStatistics.hpp"
#include "walls/PlanarWallDictionary.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>

using namespace dpd;

namespace {

TunableSlipParameters slip(double gammaL, double zc, double epsilon, double sigma) {
    TunableSlipParameters t;
    t.gammaL = gammaL;
    t.zc = zc;
    t.epsilon = epsilon;
    t.sigma = sigma;
    return t;
}

PlanarWallSettings tunableWall(const std::string& name, double z, double normalZ, const TunableSlipParameters& t,
                       const Eigen::Vector3d& velocity = Eigen::Vector3d::Zero()) {
    PlanarWallSettings w;
    w.name = name;
    w.point = Eigen::Vector3d(0, 0, z);
    w.normal = Eigen::Vector3d(0, 0, normalZ);
    w.velocity = velocity;
    w.rule = test::ruleNamed("specular");
    w.hasTunableSlip = true;
    w.tunableSlip = t;
    return w;
}

// Mobile particles at `density` between tunable-slip walls at z = -h and h (box z in [-h-1, h+1]);
// `pairs` false leaves them an ideal gas that only the walls act on (and a short cutoff keeps the cell
// list from visiting the many pairs that no longer interact).
System channel(const TunableSlipParameters& t, double h, double lx, double density, double kT0, double dt,
               bool pairs, const Eigen::Vector3d& upperVelocity = Eigen::Vector3d::Zero(), double g = 0.0) {
    System sys;
    sys.box.lo = Eigen::Vector3d(0, 0, -h - 1);
    sys.box.hi = Eigen::Vector3d(lx, 3, h + 1);
    sys.species.add({"fluid", false});
    sys.pairs = PairTable(1);
    sys.pairs.set(0, 0, {25.0, 4.5, 0.0, pairs});
    sys.forceParameters = {pairs ? 1.0 : 0.5, 2.0, 1.0, dt};
    sys.seed = 2008;
    if (g != 0.0) {
        sys.bodyForce = std::make_shared<UniformBodyForce>(Eigen::Vector3d(g, 0, 0));
    }
    sys.walls.addPlane(tunableWall("lower", -h, 1, t));
    sys.walls.addPlane(tunableWall("upper", h, -1, t, upperVelocity));
    const PairRandom random(sys.seed);
    // Start clear of the WCA range, so no particle begins on the steep part of the potential.
    const double margin = std::max(0.6, t.wcaRange());
    fillRandom(sys.particles, sys.box, Eigen::Vector3d(0, 0, -h + margin), Eigen::Vector3d(lx, 3, h - margin), density, 0,
               [](double, double, double) { return true; }, random, 0);
    maxwellVelocities(sys.particles, 0, sys.particles.size(), 3, kT0, random);
    sys.initialise();
    sys.sortByCell();
    sys.computeForces();
    return sys;
}

double kineticTemperature(const Particles& p, int axis) {
    const ParticleArray<double>& v = axis == 0 ? p.vx : axis == 1 ? p.vy : p.vz;
    double sum = 0.0;
    for (double x : v) sum += x * x;
    return sum / static_cast<double>(v.size());
}

std::string inputError(const std::string& wallEntries, const std::string& integrator = "") {
    const std::string text = "FoamFile { version 2.0; format ascii; class dictionary; object dpdProperties; }\n"
                             "kT 1;\nspecies { fluid { frozen no; } }\n"
                             "pairCoeffs { fluid-fluid { a 25; gamma 4.5; } }\n" + integrator +
                             "walls\n{\n    lower\n    {\n        type plane;\n        point (0 0 -3);\n"
                             "        normal (0 0 1);\n" + wallEntries + "\n    }\n}\n";
    return test::inputErrorOf([&] { readDpdModel(Dictionary::parse(text, "constant/dpdProperties")); });
}

}  // namespace

// Hand values for gamma_L = 2, z_c = 1, eps = 1, s = 0.5: -dV/dz = 24 eps (2 (s/z)^12 - (s/z)^6) / z,
// so 48 at z = s, 24 (2 (10/9)^12 - (10/9)^6) / 0.45 = 277.3192479885537 at z = 0.45, 0 from
// 2^(1/6) s = 0.561231 on; at z = 0.25 (s/z = 2): 24 (2 x 4096 - 64) / 0.25 = 780288. There w_L = 0.75,
// so with v = (1, 0, 0), xi = (0.5, -1, 2), kT = 1, dt = 0.01 the friction is -1.5 along x and the
// random force sqrt(2 x 2 x 0.75 / 0.01) xi = sqrt(300) xi.
TEST(TunableSlipWall, ForceMatchesHandValues) {
    const TunableSlipParameters t = slip(2.0, 1.0, 1.0, 0.5);
    EXPECT_DOUBLE_EQ(t.wcaForce(0.5), 48.0);
    EXPECT_NEAR(t.wcaForce(0.45), 277.3192479885537, 1e-9);
    EXPECT_EQ(t.wcaForce(0.5613), 0.0);
    EXPECT_EQ(t.wcaForce(-0.1), 0.0);  // behind the plane the reflection rule acts, not the force
    EXPECT_NEAR(t.wcaRange(), 0.5612310241546865, 1e-15);
    EXPECT_DOUBLE_EQ(t.frictionWeight(0.25), 0.75);
    EXPECT_EQ(t.frictionWeight(1.0), 0.0);
    const Eigen::Vector3d f = t.force(0.25, {0, 0, 1}, {1, 0, 0}, {0.5, -1, 2}, 1.0, 0.01);
    const double r = std::sqrt(300.0);
    EXPECT_NEAR(f.x(), -1.5 + 0.5 * r, 1e-9);
    EXPECT_NEAR(f.y(), -r, 1e-9);
    EXPECT_NEAR(f.z(), 780288.0 + 2.0 * r, 1e-6);
    // friction tangential: the same along the plane, the WCA force alone along the normal.
    TunableSlipParameters tangential = t;
    tangential.tangentialOnly = true;
    const Eigen::Vector3d g = tangential.force(0.25, {0, 0, 1}, {1, 0, 0.3}, {0.5, -1, 2}, 1.0, 0.01);
    EXPECT_NEAR(g.x(), -1.5 + 0.5 * r, 1e-9);
    EXPECT_NEAR(g.y(), -r, 1e-9);
    EXPECT_NEAR(g.z(), 780288.0, 1e-6);
}

// The fluid behind the plane (docs/walls.md 3.5): the mean normal force a (1 - r) of a DPD fluid filling
// z' < sigma at density rho on a particle at height z. Hand values for a 25, rho 3, r_c 1, sigma 0.5:
// pi 75 / 12 = 19.634954084936208 at z <= sigma; at z = 1 (x = 0.5) 19.63... x 0.125 x 2.5 =
// 6.135923151542565; nothing from z = 1.5 on. The WCA force adds to it along the normal.
TEST(TunableSlipWall, FluidBehindForceMatchesHandValues) {
    TunableSlipParameters t = slip(2.0, 1.0, 1.0, 0.5);
    EXPECT_EQ(t.fluidBehindForce(0.7), 0.0) << "the published wall has no fluid behind it";
    EXPECT_DOUBLE_EQ(t.reach(), 1.0);
    t.behindA = 25.0;
    t.behindDensity = 3.0;
    EXPECT_NEAR(t.fluidBehindForce(0.3), 19.634954084936208, 1e-12);
    EXPECT_NEAR(t.fluidBehindForce(0.5), 19.634954084936208, 1e-12);
    EXPECT_NEAR(t.fluidBehindForce(1.0), 6.135923151542565, 1e-12);
    EXPECT_EQ(t.fluidBehindForce(1.5), 0.0);
    EXPECT_DOUBLE_EQ(t.reach(), 1.5);
    const Eigen::Vector3d f = t.force(0.45, {0, 0, 1}, {0, 0, 0}, {0, 0, 0}, 1.0, 0.01);
    EXPECT_NEAR(f.z(), 277.3192479885537 + 19.634954084936208, 1e-9);
    t.cutoff = 2.0;  // r_c^3 (1 - x)^3 (1 + 3x) with x = (z - sigma) / r_c: at z = 1.5, x = 0.5, 8 times 0.3125
    EXPECT_NEAR(t.fluidBehindForce(1.5), 19.634954084936208 * 8.0 * 0.3125, 1e-10);
}

// The formula is the mean of the pair forces of a random (Poisson) fluid behind sigma: the force on a
// particle at height z from particles scattered at density rho over the slab one cutoff deep and two
// wide, averaged over 40,000 draws (independent: the error is the sample's standard deviation over
// sqrt(draws)). Each height's standard error is first held to a budget (about 1.4 times the measured
// 0.057, 0.045, 0.020, 0.0015), then the mean to the formula within four budgets.
TEST(TunableSlipWall, FluidBehindForceIsTheMeanForceOfARandomHalfSpace) {
    TunableSlipParameters t = slip(1.0, 1.0, 1.0, 0.5);
    t.behindA = 25.0;
    t.behindDensity = 3.0;
    std::mt19937_64 rng(2026);
    std::uniform_real_distribution<double> lateral(-1.0, 1.0), depth(t.sigma - 1.0, t.sigma);
    std::poisson_distribution<int> count(t.behindDensity * 4.0);  // the slab's volume is 2 x 2 x 1
    const std::pair<double, double> heightAndBudget[] = {{0.55, 0.08}, {0.8, 0.065}, {1.1, 0.03}, {1.4, 0.002}};
    for (const auto& [z, budget] : heightAndBudget) {
        const int draws = 40000;
        double sum = 0.0, sum2 = 0.0;
        for (int d = 0; d < draws; ++d) {
            double f = 0.0;
            for (int n = count(rng); n > 0; --n) {
                const double dx = lateral(rng), dy = lateral(rng), dz = z - depth(rng);
                const double r = std::sqrt(dx * dx + dy * dy + dz * dz);
                if (r < 1.0) f += t.behindA * (1.0 - r) * dz / r;
            }
            sum += f;
            sum2 += f * f;
        }
        const double mean = sum / draws, se = std::sqrt((sum2 / draws - mean * mean) / draws);
        ASSERT_LT(se, budget) << "z " << z;  // NaN fails too
        EXPECT_NEAR(mean, t.fluidBehindForce(z), 4.0 * budget) << "z " << z << ": standard error " << se;
    }
}

// Through System::computeForces: one particle 0.75 in front of an upper wall (normal -z) sliding at
// (0.5, 0, 0), moving at (1.5, 0.2, -0.1); w_L = 0.25, no WCA force. F = -2 x 0.25 (1, 0.2, -0.1) +
// sqrt(2 x 2 x 0.25 / 0.01) xi = (-0.5, -0.1, 0.05) + 10 xi, xi the particle's Gaussians of the wall's
// stream at this step. A particle out of reach feels nothing.
TEST(TunableSlipWall, SystemAddsTheWallForceRelativeToTheWallVelocity) {
    System sys;
    sys.box.hi = Eigen::Vector3d(10, 10, 10);
    sys.species.add({"fluid", false});
    sys.pairs = PairTable(1);
    sys.pairs.set(0, 0, {25.0, 4.5, 0.0, true});
    sys.forceParameters = {1.0, 2.0, 1.0, 0.01};
    sys.seed = 5;
    sys.step = 17;
    sys.walls.addPlane(tunableWall("upper", 8.0, -1, slip(2.0, 1.0, 1.0, 0.5), {0.5, 0, 0}));
    sys.particles.add(42, 0, 5, 5, 7.25, 1.5, 0.2, -0.1);
    sys.particles.add(43, 0, 1, 1, 2.0, 1.0, 1.0, 1.0);  // 6 from the wall, beyond the cutoff of 42
    sys.initialise();
    sys.sortByCell();
    sys.computeForces();
    const auto xi = sys.random().particleGaussians(17, 42, tunableSlipStream(0));
    for (std::size_t i = 0; i < sys.particles.size(); ++i) {
        const Eigen::Vector3d f(sys.particles.fx[i], sys.particles.fy[i], sys.particles.fz[i]);
        if (sys.particles.id[i] == 43) {
            EXPECT_EQ(f.norm(), 0.0);
            continue;
        }
        EXPECT_NEAR(f.x(), -0.5 + 10.0 * xi[0], 1e-12);
        EXPECT_NEAR(f.y(), -0.1 + 10.0 * xi[1], 1e-12);
        EXPECT_NEAR(f.z(), 0.05 + 10.0 * xi[2], 1e-12);
    }
}

// Fluctuation-dissipation: an ideal gas (no pair forces) between two tunable-slip walls has no heat
// bath but the walls, so it must take their kT = 1 from any start (here kT = 0.25). Walls 2 apart with
// z_c = 1 reach the whole gas; gamma_L = 1 relaxes its energy in ~1/(2 gamma_L <w_L>) = 1. Kinetic
// temperature sampled every 0.2 for 200 time units after 20 of relaxation (e^-20 of the start left), in
// blocks of 10 (many relaxation times each, so block means are independent). The standard error of the
// block means must be within a budget of 0.015 (measured 0.008-0.011 per axis; 20 blocks give the
// error itself to ~16 %): a noisier run fails. The bound, fixed: 4 budgets plus the discretisation bias
// of the friction step, bounded by gamma_L dt / 2 = 0.5 % (first order in gamma dt), 0.065.
// A random force off by the w_L^(1/2) (w_L instead) gives kT = <w^2>/<w> ~ 0.67, by sqrt(dt) far more.
TEST(TunableSlipWall, GasHeldOnlyByTheWallsTakesTheirTemperature) {
    const double dt = 0.01, gammaL = 1.0;
    // sigma 0.5: dt = sigma / 50, where the WCA collisions are integrable (see the test below).
    System sys = channel(slip(gammaL, 1.0, 1.0, 0.5), 1.0, 6.0, 30.0, 0.25, dt, false);
    ASSERT_GT(sys.particles.size(), 300u);
    GrootWarrenIntegrator gw(0.5);
    const int relax = static_cast<int>(20.0 / dt), sampleEvery = 20, perBlock = 50, blocks = 20;
    for (int k = 0; k < relax; ++k) gw.step(sys);
    std::vector<double> blockMeans[3];
    long crossed = 0;
    for (int b = 0; b < blocks; ++b) {
        double sum[3] = {0, 0, 0};
        for (int s = 0; s < perBlock; ++s) {
            for (int k = 0; k < sampleEvery; ++k) {
                const WallCounters c = gw.step(sys);
                for (long x : c.crossed) crossed += x;
            }
            for (int a = 0; a < 3; ++a) sum[a] += kineticTemperature(sys.particles, a);
        }
        for (int a = 0; a < 3; ++a) blockMeans[a].push_back(sum[a] / perBlock);
    }
    for (int a = 0; a < 3; ++a) {
        double mean = 0.0;
        for (double m : blockMeans[a]) mean += m / blocks;
        const double err = standardErrorOfMean(blockMeans[a]), budget = 0.015;
        const double tol = 4.0 * budget + 0.5 * gammaL * dt;
        EXPECT_TRUE(err <= budget) << "axis " << a << ": standard error " << err << " over the budget " << budget;
        EXPECT_TRUE(std::abs(mean - 1.0) <= tol) << "axis " << a << ": kT " << mean << " +- " << err;
        std::printf("tunable-slip gas, axis %d: kT = %.4f +- %.4f (tolerance %.4f)\n", a, mean, err, tol);
    }
    EXPECT_EQ(crossed, 0);
}

// One particle (no pair forces, gamma_L = 0: the WCA force alone) thrown at the wall with a normal
// kinetic energy E = 15 kT, the hardest collision a channel meets in practice (e^-15 of the thermal
// flux), started at 50 phases of the step relative to the wall: it must come back (never reach the
// plane) with its energy. The WCA wall is scale-free, so what matters is dt / sigma: velocity Verlet
// (Groot-Warren with position forces only) loses at most 4.2 % of E at dt / sigma = 0.02 (worst phase,
// computed beforehand), 10 times E at dt / sigma = 0.04. So dt 0.02 needs sigma >= 1, dt 0.01 sigma >= 0.5.
TEST(TunableSlipWall, WcaCollisionIsIntegrableWhenDtIsAFiftiethOfSigma) {
    const auto worstEnergyError = [](double sigma, double dt) {
        GrootWarrenIntegrator gw(0.65);
        double worst = 0.0;
        for (int phase = 0; phase < 50; ++phase) {
            const double speed = std::sqrt(30.0);
            PlanarWallSettings w = tunableWall("lower", 0.0, 1, slip(0.0, 1.0, 1.0, sigma));
            System sys;
            sys.box.lo = Eigen::Vector3d(0, 0, -2);
            sys.box.hi = Eigen::Vector3d(5, 5, 8);
            sys.species.add({"fluid", false});
            sys.pairs = PairTable(1);
            sys.pairs.set(0, 0, {0.0, 0.0, 0.0, false});
            sys.forceParameters = {1.0, 2.0, 1.0, dt};
            sys.walls.addPlane(w);
            sys.particles.add(1, 0, 2.5, 2.5, w.tunableSlip.wcaRange() + phase / 50.0 * speed * dt, 0, 0, -speed);
            sys.initialise();
            sys.sortByCell();
            sys.computeForces();
            long crossed = 0;
            for (int k = 0; k < 400 && sys.particles.rz[0] < 2.0 * sigma; ++k)
                for (long x : gw.step(sys).crossed) crossed += x;
            EXPECT_EQ(crossed, 0) << "sigma " << sigma << " dt " << dt << " phase " << phase;
            EXPECT_GT(sys.particles.vz[0], 0.0);
            worst = std::max(worst, std::abs(0.5 * sys.particles.vz[0] * sys.particles.vz[0] / 15.0 - 1.0));
        }
        return worst;
    };
    EXPECT_LT(worstEnergyError(0.5, 0.01), 0.05);
    EXPECT_LT(worstEnergyError(1.0, 0.02), 0.05);
    EXPECT_GT(worstEnergyError(0.5, 0.02), 1.0);  // the limit is real: sigma 0.5 at dt 0.02 is not integrable
}

// A stiff wall's bath under Groot-Warren lambda 0.65 (docs/walls.md 3.5): the walls' friction reads the
// half-kicked velocity v + dt f / 2, for which the step's Ornstein-Uhlenbeck part leaves kT exact at any
// gamma dt; read through lambda's predictor it would cool the gas by (lambda - 1/2) gamma_L <w_L> dt to
// first order, up to 0.15 x 80 x 0.5 x 0.01 = 6 % here (the gas fills |z| < 1, w_L = |z| on average
// 1/2, less the WCA's zones; measured 2.7 % with the friction reading v~, shown to fail the bound).
// gamma_L 80 relaxes the energy in ~0.0125 time units, so samples 0.2 apart are independent: kT
// sampled 500 times over 100 time units (1080 particles, 2/N per axis per sample) has a standard error
// near 0.002 per axis, checked within a budget of 0.004. Bound: 4 standard errors of the mean over the
// three axes, plus a twentieth of the first-order cooling (0.003) for what the WCA and the friction's
// change over one step leave.
TEST(TunableSlipWall, StiffWallHoldsTheGasAtKTUnderGrootWarrenLambda065) {
    const double dt = 0.01, gammaL = 80.0, lambda = 0.65;
    System sys = channel(slip(gammaL, 1.0, 1.0, 0.5), 1.0, 6.0, 30.0, 1.0, dt, false);
    GrootWarrenIntegrator gw(lambda);
    for (int k = 0; k < static_cast<int>(2.0 / dt); ++k) gw.step(sys);
    const int samples = 500, sampleEvery = 20;
    std::vector<double> perSample[3];
    for (int s = 0; s < samples; ++s) {
        for (int k = 0; k < sampleEvery; ++k) gw.step(sys);
        for (int a = 0; a < 3; ++a) perSample[a].push_back(kineticTemperature(sys.particles, a));
    }
    double mean = 0.0, err2 = 0.0;
    for (int a = 0; a < 3; ++a) {
        double m = 0.0;
        for (double x : perSample[a]) m += x / samples;
        const double err = standardErrorOfMean(perSample[a]);
        EXPECT_TRUE(err <= 0.004) << "axis " << a << ": standard error " << err << " over the budget 0.004";
        std::printf("stiff tunable-slip gas (gamma_L 80, lambda 0.65), axis %d: kT = %.4f +- %.4f\n", a, m, err);
        mean += m / 3.0;
        err2 += err * err / 9.0;
    }
    const double firstOrderCooling = (lambda - 0.5) * gammaL * 0.5 * dt;
    const double tol = 4.0 * std::sqrt(err2) + firstOrderCooling / 20.0;
    EXPECT_NEAR(mean, 1.0, tol) << "the predictor's friction would give about " << 1.0 - firstOrderCooling;
}

// The WCA wall keeps a driven DPD fluid (rho 3, a 25, gamma 4.5) out: not one crossing of the plane in
// 2000 steps at dt 0.02 with sigma 1 (zc 2, so the friction layer reaches past the repulsion), nor at
// dt 0.01 with sigma 0.5 (the specular rule behind the wall counts any crossing). The counter itself is
// shown to work by a wall with almost no repulsion (eps 1e-4, sigma 0.01), which lets many through.
TEST(TunableSlipWall, WcaWallKeepsTheFluidOut) {
    GrootWarrenIntegrator gw(0.65);
    const auto crossings = [&](const TunableSlipParameters& t, double dt, double& closest) {
        System sys = channel(t, 3.0, 8.0, 3.0, 1.0, dt, true, Eigen::Vector3d::Zero(), 0.05);
        long crossed = 0;
        closest = 1e9;
        for (int k = 0; k < 2000; ++k) {
            const WallCounters c = gw.step(sys);
            for (long x : c.crossed) crossed += x;
            for (std::size_t i = 0; i < sys.particles.size(); ++i)
                closest = std::min(closest, 3.0 - std::abs(sys.particles.rz[i]));
        }
        return crossed;
    };
    double closest = 0.0;
    EXPECT_EQ(crossings(slip(1.0, 2.0, 1.0, 1.0), 0.02, closest), 0);
    std::printf("closest approach to a WCA wall, sigma 1 at dt 0.02: %.3f\n", closest);
    EXPECT_GT(closest, 0.5);
    EXPECT_EQ(crossings(slip(1.0, 1.0, 1.0, 0.5), 0.01, closest), 0);
    std::printf("closest approach to a WCA wall, sigma 0.5 at dt 0.01: %.3f\n", closest);
    EXPECT_GT(closest, 0.25);
    EXPECT_GT(crossings(slip(1.0, 1.0, 1e-4, 0.01), 0.01, closest), 100);
}

// Same seed, same trajectory on 1 and 2 threads, with a sliding wall and the random wall forces.
TEST(TunableSlipWall, OneAndTwoThreadsGiveIdenticalTrajectories) {
    const int saved = omp_get_max_threads();
    const auto run = [](int threads) {
        omp_set_num_threads(threads);
        System sys = channel(slip(2.0, 1.0, 1.0, 0.5), 3.0, 8.0, 3.0, 1.0, 0.01, true, {0.5, 0, 0}, 0.02);
        GrootWarrenIntegrator gw(0.65);
        for (int k = 0; k < 100; ++k) gw.step(sys);
        return sys.particles;
    };
    const Particles a = run(1), b = run(2);
    omp_set_num_threads(saved);
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        ASSERT_EQ(a.id[i], b.id[i]);
        ASSERT_EQ(a.rx[i], b.rx[i]);
        ASSERT_EQ(a.rz[i], b.rz[i]);
        ASSERT_EQ(a.vx[i], b.vx[i]);
        ASSERT_EQ(a.vy[i], b.vy[i]);
        ASSERT_EQ(a.vz[i], b.vz[i]);
    }
}

// b / z_c = 2/alpha - 7/15 - 19 alpha / 1800: alpha = 2 gives 1 - 7/15 - 38/1800 = 0.5122222...;
// gamma_L = 2, z_c = 1, rho = 3, eta = 3 is alpha 2; z_c = 0.5, gamma_L = 4, rho = 4, eta = 2 too, at half
// the length; alpha = 0.5 (gamma_L 0.5, rho 3, eta 3) gives 4 - 7/15 - 9.5/1800 = 3.5280555...
TEST(TunableSlipWall, PredictedSlipLengthMatchesHandValues) {
    EXPECT_DOUBLE_EQ(tunableSlipAlpha(2.0, 1.0, 3.0, 3.0), 2.0);
    EXPECT_NEAR(predictedTunableSlipLength(2.0, 1.0, 3.0, 3.0), 0.5122222222222222, 1e-14);
    EXPECT_NEAR(predictedTunableSlipLength(4.0, 0.5, 4.0, 2.0), 0.2561111111111111, 1e-14);
    EXPECT_NEAR(predictedTunableSlipLength(0.5, 1.0, 3.0, 3.0), 3.5280555555555555, 1e-13);
    EXPECT_THROW(predictedTunableSlipLength(0.0, 1.0, 3.0, 3.0), std::invalid_argument);
    EXPECT_THROW(predictedTunableSlipLength(1.0, 1.0, 3.0, -1.0), std::invalid_argument);
}

TEST(TunableSlipWall, DictionaryEntriesAreRead) {
    const std::string text = "FoamFile { version 2.0; format ascii; class dictionary; object dpdProperties; }\n"
                             "kT 1;\nspecies { fluid { frozen no; } }\npairCoeffs { fluid-fluid { a 25; gamma 4.5; } }\n"
                             "walls { lower { type plane; point (0 0 -3); normal (0 0 1); velocity (0.1 0 0);\n"
                             "  tunableSlip { gammaL 2; zc 1.5; epsilon 0.8; sigma 0.4; fluidBehind { a 20; density 4; } } }\n"
                             "  upper { type plane; point (0 0 3); normal (0 0 -1); } }\n";
    const DpdModel m = readDpdModel(Dictionary::parse(text, "constant/dpdProperties"));
    ASSERT_EQ(m.planes().size(), 2u);
    const PlanarWallSettings& w = *m.planes()[0];
    ASSERT_TRUE(w.hasTunableSlip);
    EXPECT_TRUE(m.walls[0].actsWithForces()) << "a plane with tunableSlip is a tunable-slip wall";
    EXPECT_EQ(w.tunableSlip.gammaL, 2.0);
    EXPECT_EQ(w.tunableSlip.zc, 1.5);
    EXPECT_EQ(w.tunableSlip.epsilon, 0.8);
    EXPECT_EQ(w.tunableSlip.sigma, 0.4);
    EXPECT_FALSE(w.tunableSlip.tangentialOnly) << "the published wall's friction acts on every component";
    EXPECT_EQ(w.tunableSlip.behindA, 20.0);
    EXPECT_EQ(w.tunableSlip.behindDensity, 4.0);
    EXPECT_EQ(w.tunableSlip.cutoff, 1.0) << "the fluid behind reaches as far as the case's cutoff";
    EXPECT_EQ(w.rule->description(), "specular");  // the safety net's default behind a tunable-slip wall
    EXPECT_FALSE(m.planes()[1]->hasTunableSlip);
    EXPECT_FALSE(m.walls[1].actsWithForces());
    EXPECT_EQ(m.planes()[1]->rule->description(), "bounceBack");
}

// Each bad entry names the file, the line (the tunableSlip block is on line 12 of the text) and the keyword.
TEST(TunableSlipWall, BadEntriesNameFileLineAndKeyword) {
    const auto expectError = [](const std::string& entries, const std::string& keyword, const std::string& integrator = "") {
        const std::string e = inputError(entries, integrator);
        EXPECT_NE(e.find("constant/dpdProperties:"), std::string::npos) << e;
        EXPECT_NE(e.find(keyword), std::string::npos) << e;
        return e;
    };
    const std::string ok = "gammaL 2; zc 1; epsilon 1; sigma 0.5;";
    EXPECT_EQ(inputError("        tunableSlip { " + ok + " }"), "");
    EXPECT_NE(expectError("        tunableSlip { gammaL -1; zc 1; epsilon 1; sigma 0.5; }", "gammaL").find(":12"),
              std::string::npos);
    expectError("        tunableSlip { gammaL 2; zc 0; epsilon 1; sigma 0.5; }", "zc");
    expectError("        tunableSlip { gammaL 2; zc -1; epsilon 1; sigma 0.5; }", "zc");
    expectError("        tunableSlip { gammaL 2; zc 1; epsilon 0; sigma 0.5; }", "epsilon");
    expectError("        tunableSlip { gammaL 2; zc 1; epsilon 1; sigma -0.5; }", "sigma");
    expectError("        tunableSlip { gammaL 2; zc 1; epsilon 1; }", "sigma");
    expectError("        tunableSlip { gamaL 2; zc 1; epsilon 1; sigma 0.5; }", "gamaL");
    expectError("        tunableSlip { " + ok + " friction normal; }", "friction");
    EXPECT_EQ(inputError("        tunableSlip { " + ok + " friction tangential; }"), "");
    EXPECT_EQ(inputError("        tunableSlip { " + ok + " fluidBehind { a 25; density 3; } }"), "");
    expectError("        tunableSlip { " + ok + " fluidBehind { a 25; } }", "density");
    expectError("        tunableSlip { " + ok + " fluidBehind { a 25; density -3; } }", "density");
    EXPECT_EQ(inputError("        tunableSlip { " + ok + " fluidBehind { a 25; density 0; } }"), "") << "no fluid behind";
    expectError("        tunableSlip { " + ok + " fluidBehind { a 0; density 3; } }", "keyword 'a'");
    expectError("        tunableSlip { " + ok + " fluidBehind { a 25; density 3; rho 3; } }", "rho");
    expectError("        tunableSlip { " + ok + " fluidBehind 25; }", "fluidBehind");
    expectError("        tunableSlip { " + ok + " fluidBehind { a 25; density 3; } }", "fluidBehind", "dimension 2;\n");
    expectError("        tunableSlip 2;", "tunableSlip");
    expectError("        tunableSlip { " + ok + " }", "Shardlow", "integrator { type Shardlow; }\n");
}
