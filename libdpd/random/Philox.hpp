#pragma once
// Philox-4x32-10, the counter-based generator of Salmon et al. (SC'11, "Parallel random numbers: as
// easy as 1, 2, 3"). A counter-based generator has no state: the numbers for a pair of particles at a
// step are a pure function of (seed, step, ids), so any thread, in any order, on any number of
// threads or ranks, draws the same numbers, and a restart reproduces the uninterrupted run.
#include <array>
#include <cstdint>

namespace dpd {

using PhiloxCounter = std::array<std::uint32_t, 4>;
using PhiloxKey = std::array<std::uint32_t, 2>;

// The round multipliers and the key's increments per round (a Weyl sequence).
inline constexpr std::uint32_t kPhiloxM0 = 0xD2511F53u, kPhiloxM1 = 0xCD9E8D57u;
inline constexpr std::uint32_t kPhiloxW0 = 0x9E3779B9u, kPhiloxW1 = 0xBB67AE85u;

inline PhiloxCounter philox4x32(PhiloxCounter c, PhiloxKey k) {
    for (int round = 0; round < 10; ++round) {
        const std::uint64_t p0 = static_cast<std::uint64_t>(kPhiloxM0) * c[0];
        const std::uint64_t p1 = static_cast<std::uint64_t>(kPhiloxM1) * c[2];
        c = {static_cast<std::uint32_t>(p1 >> 32) ^ c[1] ^ k[0], static_cast<std::uint32_t>(p1),
             static_cast<std::uint32_t>(p0 >> 32) ^ c[3] ^ k[1], static_cast<std::uint32_t>(p0)};
        k[0] += kPhiloxW0;
        k[1] += kPhiloxW1;
    }
    return c;
}

// Uniform on the open interval (0, 1) from 32 random bits; never exactly 0, so log() is safe.
inline double uniformOpen01(std::uint32_t bits) { return (static_cast<double>(bits) + 0.5) * 0x1p-32; }

}  // namespace dpd
