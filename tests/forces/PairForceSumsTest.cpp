// The pair loop's per-particle force sums (forces/PairForceSums.hpp) and the scatter that fills them
// four pairs at a time (scatterBatch in forces/PairForceLoop.tpp): each pair's force s (r_i - r_j)
// added to particle i and taken from particle j, in the order of the pairs, whatever lane of the
// four-pair vectors it went through.
#include "forces/PairForceLoop.hpp"
#include "forces/PairForceSums.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

using namespace dpd;

namespace {

struct RandomPairs {
    std::vector<std::uint32_t> i, j;
    std::vector<float> dx, dy, dz;
    std::vector<double> s;
};

// `count` pairs among `particles` particles: few particles, so most appear in many pairs, also in
// consecutive ones (as i or as j), as the search's pairs do.
RandomPairs randomPairs(std::size_t count, std::uint32_t particles, unsigned seed) {
    std::mt19937_64 rng(seed);
    std::uniform_int_distribution<std::uint32_t> pick(0, particles - 1);
    std::uniform_real_distribution<float> d(-1.0f, 1.0f);
    std::uniform_real_distribution<double> u(-40.0, 40.0);
    RandomPairs r;
    for (std::size_t k = 0; k < count; ++k) {
        const std::uint32_t a = pick(rng);
        std::uint32_t b = pick(rng);
        if (b == a) b = (a + 1) % particles;
        r.i.push_back(a); r.j.push_back(b);
        r.dx.push_back(d(rng)); r.dy.push_back(d(rng)); r.dz.push_back(d(rng));
        r.s.push_back(u(rng));
    }
    return r;
}

detail::PairBatch& batchOf(const RandomPairs& r) {
    detail::PairBatch& batch = detail::threadPairBatch();
    batch.size = 0;
    batch.reserveMore(r.i.size() + 8);
    for (std::size_t k = 0; k < r.i.size(); ++k) {
        batch.i[k] = r.i[k]; batch.j[k] = r.j[k];
        batch.dx[k] = r.dx[k]; batch.dy[k] = r.dy[k]; batch.dz[k] = r.dz[k];
        batch.forceOverR[k] = r.s[k];
    }
    batch.size = r.i.size();
    return batch;
}

// The sums as the vector form makes them: each component of s d rounded, then added in pair order.
// (volatile: no fused multiply-add may merge the product into the sum.)
std::vector<ForceSum> referenceSums(const RandomPairs& r, std::uint32_t particles) {
    std::vector<ForceSum> sums(particles);
    for (std::size_t k = 0; k < r.i.size(); ++k) {
        volatile double gx = r.s[k] * r.dx[k], gy = r.s[k] * r.dy[k], gz = r.s[k] * r.dz[k];
        sums[r.i[k]].x += gx; sums[r.i[k]].y += gy; sums[r.i[k]].z += gz;
        sums[r.j[k]].x -= gx; sums[r.j[k]].y -= gy; sums[r.j[k]].z -= gz;
    }
    return sums;
}

}  // namespace

TEST(PairForceSums, FourPairsAtATimeAddEachPairToBothParticlesInOrder) {
    constexpr std::uint32_t particles = 37;
    const RandomPairs pairs = randomPairs(400, particles, 5);  // a multiple of four: no scalar tail
    PairForceSums sums;
    ForceSum* s = sums.prepare(particles);
    detail::scatterBatch(s, batchOf(pairs));
    const std::vector<ForceSum> expected = referenceSums(pairs, particles);
    for (std::uint32_t p = 0; p < particles; ++p) {
        // The same roundings in the same order: equal to the bit.
        EXPECT_EQ(s[p].x, expected[p].x) << "particle " << p;
        EXPECT_EQ(s[p].y, expected[p].y) << "particle " << p;
        EXPECT_EQ(s[p].z, expected[p].z) << "particle " << p;
        EXPECT_EQ(s[p].unused, 0.0) << "particle " << p;
    }
}

TEST(PairForceSums, TheLastPairsOfABatchCountToo) {
    constexpr std::uint32_t particles = 23;
    const RandomPairs pairs = randomPairs(403, particles, 9);  // three pairs past the last four
    PairForceSums sums;
    ForceSum* s = sums.prepare(particles);
    detail::scatterBatch(s, batchOf(pairs));
    const std::vector<ForceSum> expected = referenceSums(pairs, particles);
    // The scalar form may fuse a product into its sum (one rounding fewer per term): each of a
    // particle's m terms then differs by at most one rounding of |g| (u |g|, u = 2^-53), and each of
    // the m sums by one rounding of the partial sum, itself at most sum |g|: |difference| <= 2 m u sum |g|.
    std::vector<double> bound(particles, 0.0);
    std::vector<int> terms(particles, 0);
    for (std::size_t k = 0; k < pairs.i.size(); ++k) {
        const double g = std::abs(pairs.s[k]) * (std::abs(pairs.dx[k]) + std::abs(pairs.dy[k]) + std::abs(pairs.dz[k]));
        bound[pairs.i[k]] += g; bound[pairs.j[k]] += g;
        ++terms[pairs.i[k]]; ++terms[pairs.j[k]];
    }
    const double u = std::numeric_limits<double>::epsilon() / 2;
    for (std::uint32_t p = 0; p < particles; ++p) {
        const double tolerance = 2.0 * terms[p] * u * bound[p];
        EXPECT_NEAR(s[p].x, expected[p].x, tolerance) << "particle " << p;
        EXPECT_NEAR(s[p].y, expected[p].y, tolerance) << "particle " << p;
        EXPECT_NEAR(s[p].z, expected[p].z, tolerance) << "particle " << p;
    }
    // The check sees a lost tail: the code given the batch without its last three pairs misses whole
    // pair forces, far above the tolerance.
    RandomPairs withoutTail = pairs;
    for (auto* column : {&withoutTail.i, &withoutTail.j}) column->resize(400);
    for (auto* column : {&withoutTail.dx, &withoutTail.dy, &withoutTail.dz}) column->resize(400);
    withoutTail.s.resize(400);
    PairForceSums shortSums;
    ForceSum* t = shortSums.prepare(particles);
    detail::scatterBatch(t, batchOf(withoutTail));
    double largest = 0.0;
    for (std::uint32_t p = 0; p < particles; ++p) largest = std::max(largest, std::abs(t[p].x - expected[p].x));
    EXPECT_GT(largest, 1e-3);
}

TEST(PairForceSums, HandedToTheParticlesAddedOrReplacingThenCleared) {
    Particles p;
    for (int k = 0; k < 5; ++k) p.add(static_cast<std::uint64_t>(k), 0, k, 0.0, 0.0, 0.0, 0.0, 0.0);
    for (std::size_t k = 0; k < p.size(); ++k) { p.fx[k] = 1.0; p.fy[k] = 2.0; p.fz[k] = 3.0; }
    PairForceSums sums;
    ForceSum* s = sums.prepare(p.size());
    for (std::size_t k = 0; k < p.size(); ++k) s[k] = {0.5 * k, -1.0 * k, 0.25, 7.0};
    sums.handTo(p, false);
    for (std::size_t k = 0; k < p.size(); ++k) {
        EXPECT_EQ(p.fx[k], 1.0 + 0.5 * k);
        EXPECT_EQ(p.fy[k], 2.0 - 1.0 * k);
        EXPECT_EQ(p.fz[k], 3.25);
    }
    // Cleared: the next loop starts from zero, and handing zeros over changes nothing but replaces.
    s = sums.prepare(p.size());
    for (std::size_t k = 0; k < p.size(); ++k) {
        EXPECT_EQ(s[k].x, 0.0); EXPECT_EQ(s[k].y, 0.0); EXPECT_EQ(s[k].z, 0.0); EXPECT_EQ(s[k].unused, 0.0);
    }
    s[2] = {4.0, 5.0, 6.0, 0.0};
    sums.handTo(p, true);
    EXPECT_EQ(p.fx[2], 4.0); EXPECT_EQ(p.fy[2], 5.0); EXPECT_EQ(p.fz[2], 6.0);
    EXPECT_EQ(p.fx[0], 0.0); EXPECT_EQ(p.fy[4], 0.0);
}
