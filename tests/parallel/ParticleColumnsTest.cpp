// Particles as columns on the wire (parallel/ParticleColumns.hpp): particles listed from two sets of
// arrays come out appended in the listed order, every field bit for bit, in blocks one after the
// other (counts that are not a multiple of eight pad the species column).
#include "parallel/ParticleColumns.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <vector>

using namespace dpd;

namespace {

Particles numbered(std::uint64_t firstId, int count) {
    Particles p;
    for (int k = 0; k < count; ++k) {
        const double s = static_cast<double>(firstId) + k / 7.0;
        p.add(firstId + k, k % 3, s, -s, s * s, 0.1 * s, 0.2 * s, 0.3 * s);
        p.fx.back() = 1.0 / (s + 1.0); p.fy.back() = -s; p.fz.back() = 3.0 * s;
    }
    return p;
}

void expectSame(const Particles& a, std::size_t i, const Particles& b, std::size_t j) {
    for (auto field : {&Particles::rx, &Particles::ry, &Particles::rz, &Particles::vx, &Particles::vy, &Particles::vz,
                       &Particles::fx, &Particles::fy, &Particles::fz})
        EXPECT_EQ(std::memcmp(&(a.*field)[i], &(b.*field)[j], sizeof(double)), 0);
    EXPECT_EQ(a.id[i], b.id[j]);
    EXPECT_EQ(a.species[i], b.species[j]);
}

}  // namespace

TEST(ParticleColumns, ListedParticlesArriveInOrderBitForBit) {
    const Particles lower = numbered(100, 5), own = numbered(200, 9);
    const ParticleRefs first{{&lower, 3}, {&own, 0}, {&own, 7}, {&lower, 1}};  // 4: species padded by 4
    const ParticleRefs second{{&own, 8}, {&own, 2}, {&lower, 4}};
    std::vector<char> wire(columnBytes(first.size()) + columnBytes(second.size()));
    char* end = writeColumns(second, writeColumns(first, wire.data()));
    ASSERT_EQ(end, wire.data() + wire.size());
    EXPECT_EQ(wire.size() % 8, 0u);

    Particles to = numbered(1, 2);  // appended after what the arrays hold
    const char* at = wire.data();
    while (at != wire.data() + wire.size()) at = appendColumns(at, to);
    ASSERT_EQ(to.size(), 2u + first.size() + second.size());
    for (std::size_t k = 0; k < first.size(); ++k) expectSame(to, 2 + k, *first[k].first, first[k].second);
    for (std::size_t k = 0; k < second.size(); ++k) expectSame(to, 2 + first.size() + k, *second[k].first, second[k].second);
    expectSame(to, 0, numbered(1, 2), 0);
}

TEST(ParticleColumns, AnEmptyListIsACountOfZero) {
    std::vector<char> wire(columnBytes(0));
    EXPECT_EQ(writeColumns({}, wire.data()), wire.data() + wire.size());
    Particles to;
    EXPECT_EQ(appendColumns(wire.data(), to), wire.data() + wire.size());
    EXPECT_EQ(to.size(), 0u);
}
