// The eight-at-a-time gather of the pair loop (forces/PairGather.hpp) against the scalar form the loop
// uses for the remainder: the same relative velocities and ordered ids, to the bit, so where a batch
// splits between the two forms does not change a trajectory.
#include "forces/PairGather.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

using namespace dpd::detail;

TEST(PairGather, EightAtATimeMatchesTheScalarFormToTheBit) {
    constexpr std::size_t particles = 200, pairs = 403;  // pairs not a multiple of eight: a scalar tail
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<float> u(-3.0f, 3.0f);
    std::uniform_int_distribution<std::uint32_t> pick(0, particles - 1);
    std::vector<float> dx(pairs), dy(pairs), dz(pairs);
    std::vector<dpd::PairKinematics> kin(particles);
    for (auto& entry : kin) {
        entry.vx = u(rng); entry.vy = u(rng); entry.vz = u(rng);
        entry.id = static_cast<std::uint32_t>(rng());  // ids above 2^31 too: the order is unsigned
    }
    std::vector<std::uint32_t> bi(pairs), bj(pairs), lo(pairs), hi(pairs), loScalar(pairs), hiScalar(pairs);
    for (std::size_t k = 0; k < pairs; ++k) {
        bi[k] = pick(rng); bj[k] = pick(rng);
        dx[k] = u(rng); dy[k] = u(rng); dz[k] = u(rng);
    }
    std::vector<float> rDotV(pairs), rDotVScalar(pairs);
    const PairGatherInput in{kin.data(), bi.data(), bj.data(), dx.data(), dy.data(), dz.data()};
    const std::size_t gathered = gatherPairKinematics<true, true>(in, {rDotV.data(), lo.data(), hi.data()}, pairs);
#if defined(__AVX2__)
    EXPECT_EQ(gathered, pairs / 8 * 8);
#else
    EXPECT_EQ(gathered, 0u);  // no vector unit: the scalar form does every pair (checked below)
#endif
    gatherPairKinematicsScalar<true, true>(in, {rDotVScalar.data(), loScalar.data(), hiScalar.data()}, 0, pairs);
    for (std::size_t k = 0; k < gathered; ++k) {
        EXPECT_EQ(rDotV[k], rDotVScalar[k]) << "pair " << k;
        EXPECT_EQ(lo[k], loScalar[k]) << "pair " << k;
        EXPECT_EQ(hi[k], hiScalar[k]) << "pair " << k;
    }
    // Both forms against the definition, for every pair: ordered ids, and r . v with the components in
    // the right lanes (the scalar form on a build without AVX2 too).
    for (std::size_t k = 0; k < pairs; ++k) {
        EXPECT_EQ(loScalar[k], std::min(kin[bi[k]].id, kin[bj[k]].id)) << "pair " << k;
        EXPECT_EQ(hiScalar[k], std::max(kin[bi[k]].id, kin[bj[k]].id)) << "pair " << k;
        const float dvx = kin[bi[k]].vx - kin[bj[k]].vx, dvy = kin[bi[k]].vy - kin[bj[k]].vy,
                    dvz = kin[bi[k]].vz - kin[bj[k]].vz;
        EXPECT_EQ(rDotVScalar[k], std::fma(dz[k], dvz, std::fma(dx[k], dvx, dy[k] * dvy))) << "pair " << k;
    }
}
