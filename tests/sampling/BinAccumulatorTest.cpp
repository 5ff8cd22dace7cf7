// BinAccumulator::sample in parallel (sampling/BinAccumulator.hpp): the particles are summed in fixed
// ranges whose bins are added in order, so a sample gives the same sums to the bit on any number of
// threads, and the same sums as adding every particle straight into the bins up to round-off.
#include "sampling/BinAccumulator.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <random>

using namespace dpd;

namespace {

// n particles spread over [0, 10) along z with random velocities; species 1 (every 7th) is left out
// of the sample by the mask.
Particles spreadParticles(std::size_t n, unsigned seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 10.0);
    std::normal_distribution<double> g(0.3, 1.0);
    Particles p;
    for (std::size_t i = 0; i < n; ++i) {
        const double x = u(rng), y = u(rng), z = u(rng);
        const double vx = g(rng), vy = g(rng), vz = g(rng);
        p.add(i, i % 7 == 0 ? 1 : 0, x, y, z, vx, vy, vz);
    }
    return p;
}

BinLayout zBins() {
    BinLayout layout;
    layout.axis = 2;
    layout.nBins = 20;
    layout.lo = 0.0;
    layout.hi = 10.0;
    return layout;
}

}  // namespace

TEST(BinAccumulator, SamplesAreTheSameOnAnyNumberOfThreads) {
    // 50,000 particles: eight ranges of ~6,000 (sampleRanges), so the ranges really are summed apart.
    const Particles p = spreadParticles(50000, 7);
    const int saved = omp_get_max_threads();
    const auto sums = [&](int threads) {
        omp_set_num_threads(threads);
        BinAccumulator acc(zBins(), {1, 0}, 2);
        for (int k = 0; k < 3; ++k) acc.sample(p);
        return acc.blocks();
    };
    const auto one = sums(1), two = sums(2), three = sums(3);
    omp_set_num_threads(saved);
    ASSERT_EQ(one.size(), 2u);
    for (std::size_t blk = 0; blk < one.size(); ++blk)
        for (std::size_t b = 0; b < one[blk].size(); ++b)
            for (int f = 0; f < BinSums::kFields; ++f) {
                ASSERT_EQ(one[blk][b].s[f], two[blk][b].s[f]) << "block " << blk << " bin " << b << " field " << f;
                ASSERT_EQ(one[blk][b].s[f], three[blk][b].s[f]) << "block " << blk << " bin " << b << " field " << f;
            }
}

TEST(BinAccumulator, SampleSumsEveryParticleOfTheMaskOnce) {
    const Particles p = spreadParticles(50000, 11);
    const BinLayout layout = zBins();
    BinAccumulator acc(layout, {1, 0}, 10);
    acc.sample(p);
    // The same sums particle by particle into the bins, and the sums of the terms' absolute values:
    // two orders of summing N terms each differ from the exact sum by at most (N - 1) u sum|term|
    // (u = 2^-53), and the ranges' bins add up to eight more terms, so the two may differ by
    // 2 (N + 8) u sum|term|. The counts are exact.
    std::vector<BinSums> expected(static_cast<std::size_t>(layout.nBins)), magnitude(expected.size());
    for (std::size_t i = 0; i < p.size(); ++i) {
        if (p.species[i] != 0) continue;
        const int b = layout.binOf(p.rz[i]);
        const double x = p.rz[i] - layout.centre(b);
        expected[static_cast<std::size_t>(b)].add(x, p.vx[i], p.vy[i], p.vz[i]);
        magnitude[static_cast<std::size_t>(b)].add(std::abs(x), std::abs(p.vx[i]), std::abs(p.vy[i]), std::abs(p.vz[i]));
    }
    const std::vector<BinSums>& got = acc.blocks().front();
    double counted = 0.0;
    for (std::size_t b = 0; b < expected.size(); ++b) {
        EXPECT_EQ(got[b].s[0], expected[b].s[0]) << "count, bin " << b;
        counted += got[b].s[0];
        const double terms = expected[b].s[0] + 8.0;
        for (int f = 1; f < BinSums::kFields; ++f)
            EXPECT_NEAR(got[b].s[f], expected[b].s[f], 2.0 * terms * 0x1p-53 * magnitude[b].s[f]) << "bin " << b << " field " << f;
    }
    EXPECT_EQ(counted, static_cast<double>(p.size() - (p.size() + 6) / 7));  // every 7th is species 1
}
