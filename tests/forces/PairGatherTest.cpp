// The four-at-a-time gather of the pair loop (forces/PairGather.hpp) against the scalar form the loop
// uses for the remainder: the same relative velocities and ordered ids, to the bit, so where a batch
// splits between the two forms does not change a trajectory.
#include "forces/PairGather.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

using namespace dpd::detail;

TEST(PairGather, FourAtATimeMatchesTheScalarFormToTheBit) {
    constexpr std::size_t particles = 200, pairs = 403;  // pairs not a multiple of four: a scalar tail
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(-3.0, 3.0);
    std::uniform_int_distribution<std::uint32_t> pick(0, particles - 1);
    std::vector<double> vx(particles), vy(particles), vz(particles), dx(pairs), dy(pairs), dz(pairs);
    std::vector<std::uint64_t> id(particles);
    for (std::size_t p = 0; p < particles; ++p) {
        vx[p] = u(rng); vy[p] = u(rng); vz[p] = u(rng);
        id[p] = rng() >> 20;  // ids above 2^32 too: the order is taken on the full id, then cut
    }
    std::vector<std::uint32_t> bi(pairs), bj(pairs), lo(pairs), hi(pairs);
    for (std::size_t k = 0; k < pairs; ++k) {
        bi[k] = pick(rng); bj[k] = pick(rng);
        dx[k] = u(rng); dy[k] = u(rng); dz[k] = u(rng);
    }
    std::vector<double> rDotV(pairs);
    const std::size_t gathered = gatherPairKinematics<true, true>(
        {vx.data(), vy.data(), vz.data(), id.data(), bi.data(), bj.data(), dx.data(), dy.data(), dz.data()},
        {rDotV.data(), lo.data(), hi.data()}, pairs);
#if defined(__AVX2__)
    EXPECT_EQ(gathered, pairs / 4 * 4);
#endif
    for (std::size_t k = 0; k < gathered; ++k) {
        const std::uint32_t i = bi[k], j = bj[k];
        const double expected =
            separationDotRelativeVelocity(dx[k], dy[k], dz[k], vx[i] - vx[j], vy[i] - vy[j], vz[i] - vz[j]);
        EXPECT_EQ(rDotV[k], expected) << "pair " << k;
        EXPECT_EQ(lo[k], static_cast<std::uint32_t>(std::min(id[i], id[j]))) << "pair " << k;
        EXPECT_EQ(hi[k], static_cast<std::uint32_t>(std::max(id[i], id[j]))) << "pair " << k;
    }
}
