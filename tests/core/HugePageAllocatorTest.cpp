// The allocator of the per-particle arrays (core/HugePageAllocator.hpp): arrays of at least seven
// eighths of a huge page start on a huge-page boundary (the only place a huge page can back them),
// smaller ones keep their type's alignment, and the vectors behave as vectors (grow, copy, swap).
#include "core/HugePageAllocator.hpp"
#include "forces/PairForceSums.hpp"

#include <gtest/gtest.h>

#include <cstdint>

using namespace dpd;

namespace {
std::uintptr_t address(const void* p) { return reinterpret_cast<std::uintptr_t>(p); }
}  // namespace

TEST(HugePageAllocator, LargeArraysStartOnAHugePageSmallOnesKeepTheirAlignment) {
    const std::size_t justUnder = kHugePageBytes / 8 * 7 / sizeof(double);  // 7/8 of a huge page
    ParticleArray<double> large(256000);       // 2,048,000 bytes: just under 2 MiB, over 7/8
    ParticleArray<double> atThreshold(justUnder);
    ParticleArray<double> belowThreshold(justUnder - 1);
    ParticleArray<double> several(3 * kHugePageBytes / sizeof(double) + 5);
    EXPECT_EQ(address(large.data()) % kHugePageBytes, 0u);
    EXPECT_EQ(address(atThreshold.data()) % kHugePageBytes, 0u);
    EXPECT_EQ(address(several.data()) % kHugePageBytes, 0u);
    EXPECT_EQ(address(belowThreshold.data()) % alignof(double), 0u);
    ParticleArray<ForceSum> sums(10);           // 32-byte entries (one vector load each)
    EXPECT_EQ(address(sums.data()) % alignof(ForceSum), 0u);
    ParticleArray<ForceSum> manySums(100000);
    EXPECT_EQ(address(manySums.data()) % kHugePageBytes, 0u);
}

TEST(HugePageAllocator, ArraysGrowCopyAndSwapLikeVectors) {
    ParticleArray<double> a;
    for (int k = 0; k < 300000; ++k) a.push_back(0.5 * k);  // grows through small and huge allocations
    ASSERT_EQ(a.size(), 300000u);
    EXPECT_EQ(a[123456], 0.5 * 123456);
    ParticleArray<double> b = a;
    EXPECT_EQ(b, a);
    ParticleArray<double> c(10, 1.0);
    c.swap(b);
    EXPECT_EQ(c.size(), 300000u);
    EXPECT_EQ(b.size(), 10u);
    EXPECT_EQ(c[299999], 0.5 * 299999);
    b.clear();
    b.shrink_to_fit();
    EXPECT_EQ(b.capacity(), 0u);
}
