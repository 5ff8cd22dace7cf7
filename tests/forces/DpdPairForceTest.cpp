// The DPD pair force (forces/DpdPairForce.hpp) against values worked out by hand, and the pair loop
// through a System: zero at and beyond the cutoff, Newton's third law, sigma from fluctuation-
// dissipation.
//
// The hand computations share one geometry: r_ij = (0.3, 0.4, 0), so r = 0.5, e = (0.6, 0.8, 0) and
// with rc = 1 the weight w = 1 - r/rc = 0.5. The evaluator returns the scalar F.e / r, so that
// F_ij = forceOverR * r_ij; a force of magnitude F along e is forceOverR = F / r = 2 F.
#include "forces/DpdPairForce.hpp"
#include "system/System.hpp"
#include "SinglePrecisionPairs.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <type_traits>

using namespace dpd;

namespace {

constexpr double kR2 = 0.25;  // |(0.3, 0.4, 0)|^2
const Eigen::Vector3d kRij(0.3, 0.4, 0.0);
// Relative velocity v_ij = (1, -2, 0.5): r_ij . v_ij = 0.3 - 0.8 + 0 = -0.5, e . v_ij = -0.5 / 0.5 = -1.
const Eigen::Vector3d kVij(1.0, -2.0, 0.5);

PairForceParameters params(double dt, double s = 2.0, double cutoff = 1.0) {
    PairForceParameters p;
    p.cutoff = cutoff;
    p.weightExponent = s;
    p.kT = 1.0;
    p.dt = dt;
    return p;
}

// Relative tolerance for a few flops on O(10) numbers.
constexpr double kRoundOff = 1e-13;

}  // namespace

TEST(DpdPairForce, ConservativeOnly) {
    // a = 25, gamma = sigma = 0: F = a w e = 25 * 0.5 = 12.5 along e -> F = (7.5, 10, 0);
    // forceOverR = 12.5 / 0.5 = 25. The dissipative and random terms vanish whatever v and zeta are.
    const DpdPairEvaluator<true, true> eval(params(0.04));
    const PairCoeffs c{25.0, 0.0, 0.0, true};
    const double s = eval.forceOverR(kR2, kRij.dot(kVij), c, 0.9);
    EXPECT_NEAR(s, 25.0, 25.0 * kRoundOff);
    const Eigen::Vector3d F = s * kRij;
    EXPECT_NEAR(F.x(), 7.5, kRoundOff * 10);
    EXPECT_NEAR(F.y(), 10.0, kRoundOff * 10);
    EXPECT_EQ(F.z(), 0.0);
    // Without the conservative switch the amplitude a is ignored (scenes with a = 0 skip the term).
    const DpdPairEvaluator<false, true> noConservative(params(0.04));
    EXPECT_EQ(noConservative.forceOverR(kR2, kRij.dot(kVij), c, 0.9), 0.0);
    // Another distance: r = 0.8 along x, w = 0.2, F = 25 * 0.2 = 5, forceOverR = 5 / 0.8 = 6.25.
    EXPECT_NEAR(eval.forceOverR(0.64, 0.0, c, 0.0), 6.25, 6.25 * kRoundOff);
    // Cutoff 2 (rc != 1): r = 0.5, w = 1 - 0.25 = 0.75, F = 25 * 0.75 = 18.75, forceOverR = 37.5.
    const DpdPairEvaluator<true, true> wide(params(0.04, 2.0, 2.0));
    EXPECT_NEAR(wide.forceOverR(kR2, 0.0, c, 0.0), 37.5, 37.5 * kRoundOff);
}

TEST(DpdPairForce, DissipativeOnly) {
    // gamma = 4.5, a = sigma = 0: F^D = -gamma w^2 (e.v) e = -4.5 * 0.25 * (-1) e = 1.125 e
    // = (0.675, 0.9, 0); forceOverR = 1.125 / 0.5 = 2.25. Approaching particles (e.v < 0) repel.
    const DpdPairEvaluator<true, true> eval(params(0.04));
    const PairCoeffs c{0.0, 4.5, 0.0, true};
    const double s = eval.forceOverR(kR2, kRij.dot(kVij), c, 0.9);
    EXPECT_NEAR(s, 2.25, 2.25 * kRoundOff);
    EXPECT_NEAR(s * kRij.x(), 0.675, kRoundOff);
    EXPECT_NEAR(s * kRij.y(), 0.9, kRoundOff);
    // Receding with the opposite velocity: the force reverses. Sliding (v perpendicular to e): zero.
    EXPECT_NEAR(eval.forceOverR(kR2, -kRij.dot(kVij), c, 0.0), -2.25, 2.25 * kRoundOff);
    EXPECT_EQ(eval.forceOverR(kR2, kRij.dot(Eigen::Vector3d(-0.8, 0.6, 3.0)), c, 0.0), 0.0);
}

TEST(DpdPairForce, RandomTermScalesWithSigmaWeightZetaOverSqrtDt) {
    // sigma = 3, zeta = 0.7, dt = 0.04: F^R = sigma w zeta / sqrt(dt) = 3 * 0.5 * 0.7 / 0.2 = 5.25;
    // forceOverR = 10.5.
    const DpdPairEvaluator<true, true> eval(params(0.04));
    const PairCoeffs c{0.0, 0.0, 3.0, true};
    EXPECT_NEAR(eval.forceOverR(kR2, kRij.dot(kVij), c, 0.7), 10.5, 10.5 * kRoundOff);
    // Linear in zeta and sigma, 1/sqrt(dt): dt = 0.01 doubles it (sqrt(0.04 / 0.01) = 2).
    EXPECT_NEAR(eval.forceOverR(kR2, 0.0, c, -1.4), -21.0, 21.0 * kRoundOff);
    const DpdPairEvaluator<true, true> smallDt(params(0.01));
    EXPECT_NEAR(smallDt.forceOverR(kR2, 0.0, c, 0.7), 21.0, 21.0 * kRoundOff);
    const PairCoeffs c2{0.0, 0.0, 1.5, true};
    EXPECT_NEAR(eval.forceOverR(kR2, 0.0, c2, 0.7), 5.25, 5.25 * kRoundOff);
}

TEST(DpdPairForce, AllTermsAdd) {
    // a = 25, gamma = 4.5, sigma = 3, zeta = 0.7, dt = 0.04: 12.5 + 1.125 + 5.25 = 18.875 along e,
    // forceOverR = 37.75.
    const DpdPairEvaluator<true, true> eval(params(0.04));
    const PairCoeffs c{25.0, 4.5, 3.0, true};
    EXPECT_NEAR(eval.forceOverR(kR2, kRij.dot(kVij), c, 0.7), 37.75, 37.75 * kRoundOff);
}

TEST(DpdPairForce, GeneralisedWeightExponent) {
    const PairCoeffs c{25.0, 4.5, 3.0, true};
    // s = 2 through the pow() branch equals the standard-weight branch to round-off.
    const DpdPairEvaluator<true, false> generalTwo(params(0.04, 2.0));
    const DpdPairEvaluator<true, true> standard(params(0.04));
    for (double r : {0.05, 0.3, 0.5, 0.77, 0.999}) {
        const double a = generalTwo.forceOverR(r * r, -0.3 * r, c, 0.4);
        const double b = standard.forceOverR(r * r, -0.3 * r, c, 0.4);
        EXPECT_NEAR(a, b, std::abs(b) * kRoundOff) << "r = " << r;
    }
    // s = 1: w_D = w^1 = 0.5, w_R = sqrt(w) = 0.70710678. Conservative still a w = 12.5 (the exponent
    // belongs to the thermostat weights only). Dissipative -4.5 * 0.5 * (-1) = 2.25. Random
    // 3 * 0.70710678 * 0.7 / 0.2 = 7.42462120. Sum 22.17462120 along e, forceOverR = 44.34924240.
    const DpdPairEvaluator<true, false> one(params(0.04, 1.0));
    // The code against the hand value above (44.34924240, written out: no arithmetic of the test's own).
    EXPECT_NEAR(one.forceOverR(kR2, kRij.dot(kVij), c, 0.7), 44.3492424049, 1e-9);
    // s = 1/2: w_D = 0.5^0.5 = 0.70710678, w_R = 0.5^0.25 = 0.84089642; dissipative 4.5 * 0.70710678
    // = 3.18198052, random 3 * 0.84089642 * 0.7 / 0.2 = 8.82941242.
    const DpdPairEvaluator<true, false> half(params(0.04, 0.5));
    const double expectedHalf = 2.0 * (12.5 + 4.5 * std::sqrt(0.5) + 3.0 * std::pow(0.5, 0.25) * 0.7 / 0.2);
    EXPECT_NEAR(half.forceOverR(kR2, kRij.dot(kVij), c, 0.7), expectedHalf, expectedHalf * kRoundOff);
    // Fluctuation-dissipation holds in the weights for every s: w_D = w_R^2. Check through the two
    // terms separately at r = 0.5: dissipative-only with e.v = -1 gives gamma w_D / r, random-only with
    // zeta = sqrt(dt) gives sigma w_R / r.
    const PairCoeffs dOnly{0.0, 1.0, 0.0, true}, rOnly{0.0, 0.0, 1.0, true};
    for (double s : {0.5, 1.0, 1.5, 2.0}) {
        const DpdPairEvaluator<false, false> e(params(0.04, s));
        const double wD = e.forceOverR(kR2, -0.5, dOnly, 0.0) * 0.5;
        const double wR = e.forceOverR(kR2, 0.0, rOnly, 0.2) * 0.5;
        EXPECT_NEAR(wD, std::pow(0.5, s), 1e-14) << "s = " << s;
        EXPECT_NEAR(wD, wR * wR, 1e-14) << "s = " << s;
    }
}

namespace {

// Two fluid particles in a 5 x 5 x 5 periodic box, initialised, with forces computed.
System twoParticles(const Eigen::Vector3d& r0, const Eigen::Vector3d& r1, const Eigen::Vector3d& v0,
                    const Eigen::Vector3d& v1, double a, double gamma, double weightExponent = 2.0) {
    System sys;
    sys.box.lo = Eigen::Vector3d(0, 0, 0);
    sys.box.hi = Eigen::Vector3d(5, 5, 5);
    sys.species.add({"fluid", false});
    sys.pairs = PairTable(1);
    sys.pairs.set(0, 0, {a, gamma, 0.0, true});
    sys.forceParameters = {1.0, weightExponent, 1.0, 0.04};
    sys.seed = 7;
    sys.particles.add(10, 0, r0.x(), r0.y(), r0.z(), v0.x(), v0.y(), v0.z());
    sys.particles.add(11, 0, r1.x(), r1.y(), r1.z(), v1.x(), v1.y(), v1.z());
    sys.initialise();
    sys.sortByCell();
    sys.computeForces();
    return sys;
}

Eigen::Vector3d forceOn(const System& sys, std::uint64_t id) {
    for (std::size_t i = 0; i < sys.particles.size(); ++i)
        if (sys.particles.id[i] == id)
            return Eigen::Vector3d(sys.particles.fx[i], sys.particles.fy[i], sys.particles.fz[i]);
    ADD_FAILURE() << "no particle " << id;
    return Eigen::Vector3d::Zero();
}

}  // namespace

TEST(DpdPairForce, SystemMatchesHandValueWithSigmaFromFluctuationDissipation) {
    // Particle 10 at (2.3, 2.4, 2), particle 11 at (2, 2, 2): r_ij = (0.3, 0.4, 0) as above, v_ij =
    // (1, -2, 0.5). System::initialise sets sigma = sqrt(2 gamma kT) = sqrt(9) = 3, so with zeta from
    // the System's own generator: F.e = 12.5 + 1.125 + 3 * 0.5 * zeta / 0.2 = 13.625 + 7.5 zeta.
    const System sys = twoParticles({2.3, 2.4, 2.0}, {2.0, 2.0, 2.0}, kVij, Eigen::Vector3d::Zero(), 25.0, 4.5);
    EXPECT_EQ(sys.pairs(0, 0).sigma, 3.0);
    const double zeta = sys.random().pairUniform(0, 10, 11);
    const Eigen::Vector3d expected = (13.625 + 7.5 * zeta) * Eigen::Vector3d(0.6, 0.8, 0.0);
    const Eigen::Vector3d f = forceOn(sys, 10);
    // The loop's separations are single precision (cells of 1 in this box): within what that allows.
    const DpdPairEvaluator<true, true> eval(sys.forceParameters);
    const double tolerance = test::pairForceError(eval, Eigen::Vector3d(0.3, 0.4, 0.0), kVij, sys.pairs(0, 0), zeta,
                                                  test::separationComponentError(1.0));
    EXPECT_LT(tolerance, 1e-4 * expected.norm());  // small against the force all the same
    EXPECT_NEAR(f.x(), expected.x(), tolerance);
    EXPECT_NEAR(f.y(), expected.y(), tolerance);
    EXPECT_NEAR(f.z(), expected.z(), tolerance);
}

TEST(DpdPairForce, ZeroAtAndBeyondCutoffInThePairLoop) {
    const Eigen::Vector3d vRel(-3.0, 1.0, 2.0);  // approaching: the dissipative term would not vanish
    // Exactly at the cutoff (2 and 3 are exact in binary): zero, with the standard and a generalised
    // weight (pow(0, s/2) = 0).
    for (double s : {2.0, 1.0}) {
        const System at = twoParticles({3.0, 2.0, 2.0}, {2.0, 2.0, 2.0}, vRel, Eigen::Vector3d::Zero(), 25.0, 4.5, s);
        EXPECT_EQ(forceOn(at, 10), Eigen::Vector3d::Zero()) << "s = " << s;
        EXPECT_EQ(forceOn(at, 11), Eigen::Vector3d::Zero()) << "s = " << s;
    }
    // Beyond the cutoff, where 1 - r/rc < 0 would give a non-zero (attractive) conservative force and
    // NaN for the generalised weight: zero. Along an axis, diagonally, and across the periodic boundary
    // (x = 0.2 and x = 4.1 are 1.1 apart through the boundary).
    const Eigen::Vector3d beyond[][2] = {{{3.05, 2.0, 2.0}, {2.0, 2.0, 2.0}},
                                         {{2.0, 2.0, 2.0}, {2.6, 2.6, 2.6}},  // r = 1.039
                                         {{0.2, 2.0, 2.0}, {4.1, 2.0, 2.0}},
                                         {{2.0, 2.0, 3.0 + 1e-12}, {2.0, 2.0, 2.0}}};
    for (double s : {2.0, 1.0})
        for (const auto& pair : beyond) {
            const System sys = twoParticles(pair[0], pair[1], vRel, Eigen::Vector3d::Zero(), 25.0, 4.5, s);
            EXPECT_EQ(forceOn(sys, 10), Eigen::Vector3d::Zero()) << pair[0].transpose() << " s = " << s;
            EXPECT_EQ(forceOn(sys, 11), Eigen::Vector3d::Zero()) << pair[0].transpose() << " s = " << s;
        }
    // So that the zeros above mean something: just inside the cutoff, and 0.3 apart across the periodic
    // boundary (x = 0.2 and 4.9), the force is not zero. gamma = 0 (hence sigma = 0) leaves the
    // conservative term alone: 25 (1 - 0.999) = 0.025 and 25 (1 - 0.3) = 17.5, to the single-precision
    // separation's error times the force's slope, 25.
    const double tolerance = 25.0 * test::separationComponentError(1.0);
    const System inside = twoParticles({2.999, 2.0, 2.0}, {2.0, 2.0, 2.0}, vRel, Eigen::Vector3d::Zero(), 25.0, 0.0);
    EXPECT_NEAR(forceOn(inside, 10).x(), 25.0 * 0.001, tolerance);
    const System periodic = twoParticles({0.2, 2.0, 2.0}, {4.9, 2.0, 2.0}, vRel, Eigen::Vector3d::Zero(), 25.0, 0.0);
    // r_ij = 0.2 - (4.9 - 5) = 0.3 along +x: repelled towards +x with 25 * 0.7 = 17.5.
    EXPECT_NEAR(forceOn(periodic, 10).x(), 17.5, tolerance);
    EXPECT_NEAR(forceOn(periodic, 11).x(), -17.5, tolerance);
}

TEST(DpdPairForce, NewtonsThirdLawInASystem) {
    // Two particles with all three terms, at several separations (some across the periodic boundary):
    // equal and opposite forces. The loop adds s r_ij to one and subtracts the same product from the
    // other, so the sum is zero to round-off (exactly zero here: one pair, one product).
    const Eigen::Vector3d cases[][2] = {{{2.3, 2.4, 2.0}, {2.0, 2.0, 2.0}},
                                        {{0.1, 4.8, 2.5}, {4.7, 0.2, 2.9}},
                                        {{1.0, 1.0, 0.05}, {1.2, 0.7, 4.6}}};
    for (const auto& c : cases) {
        const System sys = twoParticles(c[0], c[1], {0.3, -1.2, 0.8}, {-0.5, 0.4, 1.1}, 25.0, 4.5);
        const Eigen::Vector3d f0 = forceOn(sys, 10), f1 = forceOn(sys, 11);
        EXPECT_GT(f0.norm(), 1.0) << c[0].transpose();  // they do interact
        EXPECT_LE((f0 + f1).norm(), 1e-14 * f0.norm()) << c[0].transpose();
    }
}

// DPD-VV evaluates the force in parts (conservative, then dissipative) and the virial without the
// random term: each part is the whole force's term, so the parts add up to the whole to round-off,
// for the standard and a generalised weight, and the weight's values are those the sweep uses.
template <class Weight>
void expectPartsAddUpToTheWhole(double s) {
    const PairForceParameters p = params(0.04, s);
    const DpdPairTerms<kConservativeTerm | kDissipativeTerm | kRandomTerm, Weight> whole(p);
    const DpdPairTerms<kConservativeTerm, Weight> conservative(p);
    const DpdPairTerms<kDissipativeTerm, Weight> dissipative(p);
    const DpdPairTerms<kRandomTerm, Weight> random(p);
    const DpdPairTerms<kConservativeTerm | kDissipativeTerm, Weight> deterministic(p);
    const PairCoeffs c{25.0, 4.5, 3.0, true};
    for (double r : {0.05, 0.3, 0.5, 0.77, 0.999})
        for (double rDotV : {-0.7 * r, 0.4 * r})
            for (double zeta : {-1.3, 0.6}) {
                const double sum = conservative.forceOverR(r * r, rDotV, c, zeta) +
                                   dissipative.forceOverR(r * r, rDotV, c, zeta) + random.forceOverR(r * r, rDotV, c, zeta);
                const double all = whole.forceOverR(r * r, rDotV, c, zeta);
                // Each term is O(100) at most (a w / r at r = 0.05 is 475): a few ulps of the largest.
                EXPECT_NEAR(sum, all, 1e-12 * 500.0) << "s = " << s << ", r = " << r;
                EXPECT_NEAR(deterministic.forceOverR(r * r, rDotV, c, zeta) + random.forceOverR(r * r, rDotV, c, zeta), all,
                            1e-12 * 500.0);
                // A term the evaluator does not have is not computed: zeta and v do not reach the conservative part.
                EXPECT_EQ(conservative.forceOverR(r * r, rDotV, c, zeta), conservative.forceOverR(r * r, 0.0, c, 0.0));
            }
    EXPECT_FALSE(decltype(conservative)::kUsesRandom || decltype(conservative)::kUsesVelocity);
    EXPECT_FALSE(decltype(deterministic)::kUsesRandom);
    EXPECT_TRUE(decltype(whole)::kUsesRandom && decltype(whole)::kUsesVelocity);
    const Weight weight(p);
    EXPECT_NEAR(weight.at(0.5).wD, std::pow(0.5, s), 1e-14);
}

TEST(DpdPairForce, ThePartsAddUpToTheWhole) {
    expectPartsAddUpToTheWhole<DpdWeight<true>>(2.0);
    expectPartsAddUpToTheWhole<DpdWeight<false>>(1.0);
    expectPartsAddUpToTheWhole<DpdWeight<false>>(0.5);
}

TEST(DpdPairForce, TheWeightIsChosenByTheExponent) {
    EXPECT_TRUE(withDpdWeight(params(0.04, 2.0), [](auto w) { return std::is_same_v<decltype(w), DpdWeight<true>>; }));
    EXPECT_TRUE(withDpdWeight(params(0.04, 1.5), [](auto w) { return std::is_same_v<decltype(w), DpdWeight<false>>; }));
}
