// A run uses one thread per kParticlesPerThread particles (or DPD_PARTICLES_PER_THREAD's), at least one and at
// most what is available.
#include "core/ThreadBudget.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <stdexcept>

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

TEST(ThreadBudget, ParticlesPerThreadFromTheEnvironment) {
    unsetenv("DPD_PARTICLES_PER_THREAD");
    EXPECT_EQ(particlesPerThread(), kParticlesPerThread);
    setenv("DPD_PARTICLES_PER_THREAD", "1", 1);
    EXPECT_EQ(particlesPerThread(), 1u);
    EXPECT_EQ(threadsForParticles(100, 2, particlesPerThread()), 2);
    for (const char* bad : {"0", "-5", "abc", "12x", ""}) {
        setenv("DPD_PARTICLES_PER_THREAD", bad, 1);
        EXPECT_THROW(particlesPerThread(), std::invalid_argument) << "'" << bad << "'";
    }
    unsetenv("DPD_PARTICLES_PER_THREAD");
}
