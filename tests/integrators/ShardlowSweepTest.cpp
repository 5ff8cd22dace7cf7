// Shardlow's pair update (integrators/ShardlowSweep.*) against the exact solution of one pair's
// Ornstein-Uhlenbeck process: u = e . (v_i - v_j) relaxes as u e^(-kappa dt) plus a Gaussian of
// variance (kT / mu)(1 - e^(-2 kappa dt)), kappa = gamma w_D / mu, mu the reduced mass (1/2 for two
// fluid particles, 1 for a fluid particle against a frozen one); momentum and the velocity components
// normal to e are untouched.
#include "integrators/ShardlowSweep.hpp"
#include "system/System.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace dpd;

namespace {

// Two particles 0.5 apart along x (w_D = 0.25) in a 4 x 4 x 4 box, a = 0, gamma 4.5, dt 0.1; the
// second is frozen when `frozenPartner`.
System pair(double kT, bool frozenPartner, const Eigen::Vector3d& vi, const Eigen::Vector3d& vj) {
    System sys;
    sys.box.lo = Eigen::Vector3d(0, 0, 0);
    sys.box.hi = Eigen::Vector3d(4, 4, 4);
    sys.species.add({"fluid", false});
    sys.species.add({"wall", true});
    sys.pairs = PairTable(2);
    for (int a = 0; a < 2; ++a)
        for (int b = a; b < 2; ++b) sys.pairs.set(a, b, {0.0, 4.5, 0.0, true});
    sys.forceParameters = {1.0, 2.0, kT, 0.1};
    sys.seed = 17;
    sys.particles.add(1, 0, 2.25, 2.0, 2.0, vi.x(), vi.y(), vi.z());
    sys.particles.add(2, frozenPartner ? 1 : 0, 1.75, 2.0, 2.0, vj.x(), vj.y(), vj.z());
    sys.initialise();
    sys.sortByCell();
    return sys;
}

Eigen::Vector3d velocityOf(const System& sys, std::uint64_t id) {
    const Particles& p = sys.particles;
    for (std::size_t i = 0; i < p.size(); ++i)
        if (p.id[i] == id) return {p.vx[i], p.vy[i], p.vz[i]};
    ADD_FAILURE() << "no particle " << id;
    return {0, 0, 0};
}

constexpr double kGamma = 4.5, kWD = 0.25, kDt = 0.1;

}  // namespace

TEST(ShardlowSweep, FluidPairRelaxesExactlyWithoutNoise) {
    // kT = 0: sigma = 0, the update is the deterministic decay. u = e.(v_1 - v_2) = 1 - (-1) = 2,
    // mu = 1/2: u' = 2 exp(-gamma w_D dt / mu) = 2 exp(-0.225).
    const Eigen::Vector3d v1(1.0, 0.3, 0.0), v2(-1.0, 0.2, 0.5);
    System sys = pair(0.0, false, v1, v2);
    shardlowSweep(sys, kDt, 0);
    const Eigen::Vector3d w1 = velocityOf(sys, 1), w2 = velocityOf(sys, 2);
    EXPECT_NEAR(w1.x() - w2.x(), 2.0 * std::exp(-kGamma * kWD * kDt / 0.5), 1e-14);
    EXPECT_NEAR(w1.x() + w2.x(), v1.x() + v2.x(), 1e-15) << "the pair's momentum";
    EXPECT_EQ(w1.y(), v1.y());
    EXPECT_EQ(w1.z(), v1.z());
    EXPECT_EQ(w2.y(), v2.y());
    EXPECT_EQ(w2.z(), v2.z());
}

TEST(ShardlowSweep, FrozenPartnerTakesNothingAndTheFluidRelaxesWithItsOwnMass) {
    // Against a frozen (infinitely heavy) particle moving at 0.5: mu = 1, u = 2 - 0.5 = 1.5,
    // u' = 1.5 exp(-gamma w_D dt); the frozen particle keeps its velocity bit for bit.
    const Eigen::Vector3d v1(2.0, -0.4, 0.1), wall(0.5, 0.0, 0.0);
    System sys = pair(0.0, true, v1, wall);
    shardlowSweep(sys, kDt, 0);
    const Eigen::Vector3d w1 = velocityOf(sys, 1);
    EXPECT_NEAR(w1.x(), 0.5 + 1.5 * std::exp(-kGamma * kWD * kDt), 1e-14);
    EXPECT_EQ(w1.y(), v1.y());
    EXPECT_EQ(w1.z(), v1.z());
    EXPECT_EQ(velocityOf(sys, 2), wall);
}

namespace {

struct Moments {
    double mean = 0.0, variance = 0.0, kurtosis = 0.0;
};

// The change of u in one sweep from u = 0, over `samples` steps (each step its own random numbers).
Moments kicksFromRest(bool frozenPartner, int samples, std::vector<double>* momentumChange = nullptr) {
    std::vector<double> du;
    for (int k = 0; k < samples; ++k) {
        System sys = pair(1.0, frozenPartner, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero());
        sys.step = k;
        shardlowSweep(sys, kDt, 0);
        const Eigen::Vector3d w1 = velocityOf(sys, 1), w2 = velocityOf(sys, 2);
        du.push_back(w1.x() - w2.x());
        if (momentumChange) momentumChange->push_back(w1.x() + w2.x());
    }
    Moments m;
    for (double x : du) m.mean += x;
    m.mean /= samples;
    double m4 = 0.0;
    for (double x : du) {
        m.variance += (x - m.mean) * (x - m.mean);
        m4 += std::pow(x - m.mean, 4);
    }
    m.variance /= samples - 1;
    m.kurtosis = m4 / samples / (m.variance * m.variance);
    return m;
}

}  // namespace

TEST(ShardlowSweep, NoiseHasTheVarianceOfTheExactSolution) {
    // Statistics: M = 40,000 independent draws of a Gaussian. The sample mean has SE sqrt(var / M),
    // the sample variance a relative SE sqrt(2 / M) = 0.7 %, the kurtosis an SE sqrt(24 / M) = 0.024;
    // each is held to 4 SE. A unit-variance uniform instead of a Gaussian would give kurtosis 1.8,
    // 50 SE away.
    const int samples = 40000;
    for (const bool frozenPartner : {false, true}) {
        SCOPED_TRACE(frozenPartner ? "frozen partner" : "fluid pair");
        const double mu = frozenPartner ? 1.0 : 0.5;
        const double expected = (1.0 / mu) * (1.0 - std::exp(-2.0 * kGamma * kWD * kDt / mu));
        std::vector<double> momentum;
        const Moments m = kicksFromRest(frozenPartner, samples, &momentum);
        EXPECT_LT(std::abs(m.mean), 4.0 * std::sqrt(expected / samples));
        EXPECT_LT(std::abs(m.variance / expected - 1.0), 4.0 * std::sqrt(2.0 / samples))
            << "variance " << m.variance << ", exact " << expected;
        EXPECT_LT(std::abs(m.kurtosis - 3.0), 4.0 * std::sqrt(24.0 / samples)) << "kurtosis " << m.kurtosis;
        if (!frozenPartner)
            for (double p : momentum) ASSERT_NEAR(p, 0.0, 1e-15) << "the pair's momentum";
    }
}

TEST(ShardlowSweep, SweepsOfOneStepDrawDifferentNumbers) {
    System a = pair(1.0, false, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero());
    System b = pair(1.0, false, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero());
    shardlowSweep(a, kDt, 0);
    shardlowSweep(b, kDt, 1);
    EXPECT_NE(velocityOf(a, 1).x(), velocityOf(b, 1).x());
}
