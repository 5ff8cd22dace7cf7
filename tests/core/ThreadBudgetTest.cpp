// A run uses one thread per kParticlesPerThread particles, at least one and at most what is available.
#include "core/ThreadBudget.hpp"

#include <gtest/gtest.h>

using namespace dpd;

TEST(ThreadBudget, SmallSystemsRunOnOneThread) {
    EXPECT_EQ(threadsForParticles(0, 2), 1);
    EXPECT_EQ(threadsForParticles(kParticlesPerThread - 1, 2), 1);
    EXPECT_EQ(threadsForParticles(2 * kParticlesPerThread - 1, 2), 1);
}

TEST(ThreadBudget, LargeSystemsUseWhatIsAvailable) {
    EXPECT_EQ(threadsForParticles(2 * kParticlesPerThread, 2), 2);
    EXPECT_EQ(threadsForParticles(1000000, 2), 2);
    EXPECT_EQ(threadsForParticles(1000000, 1), 1);
    EXPECT_EQ(threadsForParticles(3 * kParticlesPerThread + 1, 16), 3);
}
