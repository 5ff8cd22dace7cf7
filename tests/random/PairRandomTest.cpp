// Statistical and structural tests of the counter-based random numbers (random/PairRandom.hpp).
//
// Tolerances. Every moment test compares a sample mean of N independent draws of some quantity q
// with its exact expectation and accepts |mean - E q| < 4 sqrt(Var q / N): four standard errors, a
// two-sided false-alarm probability of 6e-5 for a correct generator (the seeds are fixed, so a run is
// reproducible; the bound is what a correct generator passes with near certainty, not a fitted
// margin). The variances used are exact for the distribution in question and are derived next to
// each test.
#include "random/PairRandom.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <set>
#include <vector>

using dpd::PairRandom;

namespace {

constexpr double kSqrt3 = 1.7320508075688772935;

// Mean and the bound for a sample of N draws of a quantity with known variance.
struct MomentCheck {
    double sum = 0.0;
    long n = 0;
    void add(double q) { sum += q; ++n; }
    double mean() const { return sum / static_cast<double>(n); }
    double bound(double variance) const { return 4.0 * std::sqrt(variance / static_cast<double>(n)); }
};

}  // namespace

TEST(PairRandom, SymmetricInTheTwoIds) {
    const PairRandom r(12345);
    for (std::uint64_t step = 0; step < 50; ++step)
        for (std::uint64_t a = 0; a < 40; ++a)
            for (std::uint64_t b = 0; b < 40; ++b) {
                const double ab = r.pairUniform(step, a, b), ba = r.pairUniform(step, b, a);
                ASSERT_EQ(ab, ba) << "step " << step << " ids " << a << " " << b;
            }
    // Large ids and steps above 2^32 too.
    const std::uint64_t bigStep = (std::uint64_t{1} << 40) + 17;
    EXPECT_EQ(r.pairUniform(bigStep, 4000000000u, 7), r.pairUniform(bigStep, 7, 4000000000u));
}

TEST(PairRandom, DiffersForDifferentStepsPairsAndSeeds) {
    const PairRandom r1(1), r2(2), rHigh((std::uint64_t{1} << 32) + 1);  // seeds differing only in the high word
    const double base = r1.pairUniform(100, 3, 8);
    EXPECT_NE(base, r1.pairUniform(101, 3, 8));                               // next step
    EXPECT_NE(base, r1.pairUniform(100 + (std::uint64_t{1} << 32), 3, 8));   // step's high word
    EXPECT_NE(base, r1.pairUniform(100, 3, 9));                               // another pair
    EXPECT_NE(base, r1.pairUniform(100, 4, 8));
    EXPECT_NE(base, r2.pairUniform(100, 3, 8));                               // another seed
    EXPECT_NE(r1.pairUniform(100, 3, 8), rHigh.pairUniform(100, 3, 8));

    // Many keys at once: all the pairs of 200 ids at 5 steps, 99,500 draws of 32-bit resolution. By the
    // birthday bound the expected number of coincident values is n^2 / 2^33 ~ 1.2, so count distinct
    // values and allow a handful (a generator that ignored part of the key would repeat thousands).
    std::set<double> values;
    long draws = 0;
    for (std::uint64_t step = 0; step < 5; ++step)
        for (std::uint64_t a = 0; a < 200; ++a)
            for (std::uint64_t b = a + 1; b < 200; ++b, ++draws) values.insert(r1.pairUniform(step, a, b));
    EXPECT_GE(static_cast<long>(values.size()), draws - 10);

    // The same key with a different seed: for 10^4 keys, almost never equal.
    long equal = 0;
    for (std::uint64_t k = 0; k < 10000; ++k) equal += r1.pairUniform(k, k, k + 1) == r2.pairUniform(k, k, k + 1);
    EXPECT_LE(equal, 2);

    // Per-particle streams separate uses.
    const auto g1 = r1.particleGaussians(5, 9, dpd::kStreamInitialVelocity);
    const auto g3 = r1.particleGaussians(5, 9, dpd::kStreamReflection);
    const auto g1Next = r1.particleGaussians(6, 9, dpd::kStreamInitialVelocity);
    const auto g1Other = r1.particleGaussians(5, 10, dpd::kStreamInitialVelocity);
    EXPECT_NE(g1[0], g3[0]);
    EXPECT_NE(g1[0], g1Next[0]);
    EXPECT_NE(g1[0], g1Other[0]);
}

// One million pair draws (1000 steps x 1000 pairs): zero mean, unit variance, bounded by sqrt(3),
// flat histogram.
TEST(PairRandom, UnitVarianceUniformMoments) {
    const PairRandom r(2024);
    MomentCheck m1, m2;
    std::array<long, 20> histogram{};
    double maxAbs = 0.0;
    for (std::uint64_t step = 0; step < 1000; ++step)
        for (std::uint64_t i = 0; i < 1000; ++i) {
            // Neighbouring and distant ids alike.
            const double x = r.pairUniform(step, i, (i * 7919 + 1) % 100003 + 1000);
            m1.add(x);
            m2.add(x * x);
            maxAbs = std::max(maxAbs, std::abs(x));
            const int bin = std::min(19, static_cast<int>((x + kSqrt3) / (2.0 * kSqrt3) * 20.0));
            ++histogram[bin];
        }
    // x uniform on [-sqrt3, sqrt3]: E x = 0, Var x = 1, so SE(mean) = 1/sqrt(N).
    EXPECT_LT(std::abs(m1.mean()), m1.bound(1.0)) << "mean " << m1.mean();
    // E x^2 = 1; E x^4 = (sqrt3)^4 / 5 = 9/5, so Var(x^2) = 9/5 - 1 = 4/5.
    EXPECT_LT(std::abs(m2.mean() - 1.0), m2.bound(0.8)) << "variance " << m2.mean();
    EXPECT_LT(maxAbs, kSqrt3);
    // Histogram: chi^2 with 19 degrees of freedom has mean 19 and standard deviation sqrt(38); accept
    // below mean + 4 sd = 43.7.
    const double expected = static_cast<double>(m1.n) / 20.0;
    double chi2 = 0.0;
    for (long c : histogram) chi2 += (c - expected) * (c - expected) / expected;
    EXPECT_LT(chi2, 19.0 + 4.0 * std::sqrt(38.0)) << "chi^2 " << chi2;
}

// Correlations between draws whose keys differ a little: consecutive steps of one pair, neighbouring
// ids, the two ids swapped in role, neighbouring seeds. For independent zero-mean unit-variance x and y
// the product xy has mean 0 and variance E x^2 E y^2 = 1, so the sample correlation of N products has
// standard error 1/sqrt(N).
TEST(PairRandom, NeighbouringKeysAreUncorrelated) {
    const PairRandom r(77), rNext(78);
    MomentCheck lagStep, lag2Step, nextB, nextA, nextSeed, shiftedPair;
    for (std::uint64_t step = 0; step < 2000; ++step)
        for (std::uint64_t a = 0; a < 100; ++a) {
            const std::uint64_t b = a + 2 + (step % 7);  // b > a + 1, so (a + 1, b) is a true pair
            const double x = r.pairUniform(step, a, b);
            lagStep.add(x * r.pairUniform(step + 1, a, b));
            lag2Step.add(x * r.pairUniform(step + 2, a, b));
            nextB.add(x * r.pairUniform(step, a, b + 1));
            nextA.add(x * r.pairUniform(step, a + 1, b));
            nextSeed.add(x * rNext.pairUniform(step, a, b));
            shiftedPair.add(x * r.pairUniform(step, a + 1, b + 1));
        }
    for (const auto* c : {&lagStep, &lag2Step, &nextB, &nextA, &nextSeed, &shiftedPair})
        EXPECT_LT(std::abs(c->mean()), c->bound(1.0)) << "correlation " << c->mean();
}

// Per-particle Gaussians: N = 10^6 variates (250,000 calls, four each).
TEST(PairRandom, ParticleGaussiansAreStandardNormal) {
    const PairRandom r(99);
    MomentCheck m1, m2, m4;
    std::array<MomentCheck, 6> cross;  // the six products of the four variates of one call
    double s2 = 0.0, s4 = 0.0;
    long n = 0;
    for (std::uint64_t step = 0; step < 500; ++step)
        for (std::uint64_t id = 0; id < 500; ++id) {
            const auto g = r.particleGaussians(step, id, dpd::kStreamReflection);
            int k = 0;
            for (int p = 0; p < 4; ++p)
                for (int q = p + 1; q < 4; ++q) cross[k++].add(g[p] * g[q]);
            for (double x : g) {
                m1.add(x);
                m2.add(x * x);
                m4.add(x * x * x * x);
                s2 += x * x;
                s4 += x * x * x * x;
                ++n;
            }
        }
    // Standard normal: E g = 0, Var g = 1; E g^2 = 1, Var g^2 = E g^4 - 1 = 2; E g^4 = 3,
    // Var g^4 = E g^8 - 9 = 105 - 9 = 96.
    EXPECT_LT(std::abs(m1.mean()), m1.bound(1.0)) << "mean " << m1.mean();
    EXPECT_LT(std::abs(m2.mean() - 1.0), m2.bound(2.0)) << "variance " << m2.mean();
    EXPECT_LT(std::abs(m4.mean() - 3.0), m4.bound(96.0)) << "fourth moment " << m4.mean();
    // Kurtosis m4 / m2^2 of a normal sample has asymptotic variance 24 / N.
    const double kurtosis = (s4 / n) / ((s2 / n) * (s2 / n));
    EXPECT_LT(std::abs(kurtosis - 3.0), 4.0 * std::sqrt(24.0 / n)) << "kurtosis " << kurtosis;
    // The four variates of one call are independent: E g_p g_q = 0 with variance 1.
    for (const auto& c : cross) EXPECT_LT(std::abs(c.mean()), c.bound(1.0)) << "cross moment " << c.mean();
}

// Per-particle uniforms: mean 1/2 (variance 1/12), E u^2 = 1/3 (Var u^2 = 1/5 - 1/9 = 4/45), open interval.
TEST(PairRandom, ParticleUniformsAreUniformOnOpenInterval) {
    const PairRandom r(5);
    MomentCheck m1, m2;
    double lo = 1.0, hi = 0.0;
    for (std::uint64_t step = 0; step < 500; ++step)
        for (std::uint64_t id = 0; id < 500; ++id)
            for (double u : r.particleUniforms(step, id, dpd::kStreamInitialPosition)) {
                m1.add(u);
                m2.add(u * u);
                lo = std::min(lo, u);
                hi = std::max(hi, u);
            }
    EXPECT_LT(std::abs(m1.mean() - 0.5), m1.bound(1.0 / 12.0));
    EXPECT_LT(std::abs(m2.mean() - 1.0 / 3.0), m2.bound(4.0 / 45.0));
    EXPECT_GT(lo, 0.0);
    EXPECT_LT(hi, 1.0);
}

// The batch form used by the pair loop (eight Philox counters per AVX2 instruction, a scalar tail)
// gives the scalar generator's numbers to the bit. Built without AVX2 the batch form is the scalar
// loop itself, and the comparison would prove nothing: the test then reports a skip.
TEST(PairRandom, BatchAndScalarFormsAgreeToTheBit) {
#if !defined(__AVX2__)
    GTEST_SKIP() << "built without AVX2: the batch form is the scalar generator, nothing to compare";
#endif
    const PairRandom r(31337);
    const std::uint64_t step = (std::uint64_t{1} << 33) + 12345;  // both step words non-zero
    const std::size_t n = 1003;                                    // 125 blocks of eight and a tail of 3
    std::vector<std::uint32_t> lo(n), hi(n);
    for (std::size_t k = 0; k < n; ++k) {
        lo[k] = static_cast<std::uint32_t>(k * 2654435761u % 100000);
        hi[k] = lo[k] + 1 + static_cast<std::uint32_t>(k % 977) + (k % 5 == 0 ? 0xF0000000u : 0u);
    }
    std::vector<double> zeta(n);
    r.orderedPairUniforms(step, lo.data(), hi.data(), zeta.data(), n);
    for (std::size_t k = 0; k < n; ++k) {
        ASSERT_EQ(zeta[k], r.pairUniform(step, lo[k], hi[k])) << "pair " << k;
        ASSERT_EQ(zeta[k], r.orderedPairUniform(step, lo[k], hi[k])) << "pair " << k;
    }
}

// The signed-conversion form of the uniform equals the textbook sqrt(12) ((bits + 1/2) 2^-32 - 1/2)
// to the bit, at the ends and in between.
TEST(PairRandom, UnitVarianceUniformIsTheTextbookFormToTheBit) {
    for (std::uint32_t bits : {0u, 1u, 0x7FFFFFFFu, 0x80000000u, 0x80000001u, 0xFFFFFFFEu, 0xFFFFFFFFu, 0x12345678u}) {
        const double textbook = 3.4641016151377545870548926830117 * ((static_cast<double>(bits) + 0.5) * 0x1p-32 - 0.5);
        EXPECT_EQ(PairRandom::unitVarianceUniform(bits), textbook) << "bits " << bits;
    }
}

// Philox4x32-10 itself against the known-answer vectors Random123 publishes with the generator
// (Salmon et al.; kat_vectors: counter, key -> output), so the numbers are the published algorithm's
// and not merely self-consistent.
TEST(PairRandom, Philox4x32MatchesThePublishedKnownAnswers) {
    struct Known {
        dpd::PhiloxCounter counter;
        dpd::PhiloxKey key;
        dpd::PhiloxCounter output;
    };
    const Known known[] = {
        {{0u, 0u, 0u, 0u}, {0u, 0u}, {0x6627e8d5u, 0xe169c58du, 0xbc57ac4cu, 0x9b00dbd8u}},
        {{0xffffffffu, 0xffffffffu, 0xffffffffu, 0xffffffffu}, {0xffffffffu, 0xffffffffu},
         {0x408f276du, 0x41c83b0eu, 0xa20bc7c6u, 0x6d5451fdu}},
        {{0x243f6a88u, 0x85a308d3u, 0x13198a2eu, 0x03707344u}, {0xa4093822u, 0x299f31d0u},
         {0xd16cfe09u, 0x94fdccebu, 0x5001e420u, 0x24126ea1u}},
    };
    for (const Known& k : known) EXPECT_EQ(dpd::philox4x32(k.counter, k.key), k.output);
}
