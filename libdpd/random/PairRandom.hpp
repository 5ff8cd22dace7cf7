#pragma once
// Random numbers for pair forces and for per-particle draws, keyed by (seed, step, identities).
//
// Pair noise: zeta_ij must equal zeta_ji, have zero mean and unit variance, and be independent for
// every pair and step. The fluctuation-dissipation theorem fixes only the first two moments, so a
// uniform variate scaled to unit variance (sqrt(12) (u - 1/2)) serves as well as a Gaussian and is
// cheaper (Groot & Warren 1997). One Philox call yields four 32-bit words; the pair force needs one.
#include "random/Philox.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>

namespace dpd {

class PairRandom {
public:
    explicit PairRandom(std::uint64_t seed = 0) : key_{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32)} {}

    // Unit-variance uniform variate for the pair (idA, idB) at a step; symmetric in the two ids.
    double pairUniform(std::uint64_t step, std::uint64_t idA, std::uint64_t idB) const {
        const std::uint64_t lo = idA < idB ? idA : idB;
        const std::uint64_t hi = idA < idB ? idB : idA;
        return orderedPairUniform(step, static_cast<std::uint32_t>(lo), static_cast<std::uint32_t>(hi));
    }

    // The same variate for ids already ordered (lo the lower) and cut to their low 32 bits: ids up to
    // 2^32 each, the step fills the other two counter words (64-bit steps). Branch-free and made of
    // 32-bit words only, so a loop over many pairs vectorises (the pair loop calls it that way).
    double orderedPairUniform(std::uint64_t step, std::uint32_t lo, std::uint32_t hi) const {
        const PhiloxCounter c{lo, hi, static_cast<std::uint32_t>(step), static_cast<std::uint32_t>(step >> 32) ^ kPairStream};
        return unitVarianceUniform(philox4x32(c, key_)[0]);
    }

    // orderedPairUniform for n pairs at once: zeta[k] for (lo[k], hi[k]), the same numbers to the bit
    // (Philox on eight pairs per instruction where the CPU has AVX2).
    void orderedPairUniforms(std::uint64_t step, const std::uint32_t* lo, const std::uint32_t* hi, double* zeta,
                             std::size_t n) const;

    // sqrt(12) (u - 1/2) with u = (bits + 1/2) 2^-32, written through a signed conversion
    // ((int) (bits ^ 2^31) = bits - 2^31 exactly), which vector units have and the unsigned one lacks
    // before AVX-512. Every step is exact but the last product, so the value is the same as the
    // textbook form to the bit.
    static double unitVarianceUniform(std::uint32_t bits) {
        const auto centred = static_cast<std::int32_t>(bits ^ 0x80000000u);
        return (static_cast<double>(centred) + 0.5) * (kSqrt12 * 0x1p-32);
    }

    // Standard normal variate for the pair (idA, idB) at a step, symmetric in the two ids, from a
    // stream of its own (a RandomStream value below 0x8000): a pair scheme that draws more than once
    // per step (Shardlow's splitting, one draw per sweep) gives each sweep its own stream, and none
    // of them meets pairUniform's numbers (whose fourth word has the top 16 bits exactly 0x8000 for
    // any step below 2^48, while these carry 0x8000 | stream with stream >= 1).
    double pairGaussian(std::uint64_t step, std::uint64_t idA, std::uint64_t idB, std::uint32_t stream) const {
        const std::uint64_t lo = idA < idB ? idA : idB;
        const std::uint64_t hi = idA < idB ? idB : idA;
        const PhiloxCounter c{static_cast<std::uint32_t>(lo), static_cast<std::uint32_t>(hi),
                              static_cast<std::uint32_t>(step),
                              (static_cast<std::uint32_t>(step >> 32) & 0xFFFFu) | ((kPairStream >> 16 | stream) << 16)};
        const PhiloxCounter w = philox4x32(c, key_);
        // Box-Muller, cosine branch only.
        return std::sqrt(-2.0 * std::log(uniformOpen01(w[0]))) * std::cos(2.0 * M_PI * uniformOpen01(w[1]));
    }

    // Four independent standard normal variates for one particle at a step; `stream` separates
    // independent uses (thermostat walls, reflections, initial velocities ...).
    std::array<double, 4> particleGaussians(std::uint64_t step, std::uint64_t id, std::uint32_t stream) const {
        const PhiloxCounter c{static_cast<std::uint32_t>(id), static_cast<std::uint32_t>(id >> 32),
                              static_cast<std::uint32_t>(step),
                              (static_cast<std::uint32_t>(step >> 32) & 0xFFFFu) | (stream << 16)};
        const PhiloxCounter w = philox4x32(c, key_);
        // Box-Muller on two pairs of uniforms.
        std::array<double, 4> g{};
        for (int k = 0; k < 2; ++k) {
            const double radius = std::sqrt(-2.0 * std::log(uniformOpen01(w[2 * k])));
            const double angle = 2.0 * M_PI * uniformOpen01(w[2 * k + 1]);
            g[2 * k] = radius * std::cos(angle);
            g[2 * k + 1] = radius * std::sin(angle);
        }
        return g;
    }

    // Four independent uniforms on (0,1) for one particle at a step.
    std::array<double, 4> particleUniforms(std::uint64_t step, std::uint64_t id, std::uint32_t stream) const {
        const PhiloxCounter c{static_cast<std::uint32_t>(id), static_cast<std::uint32_t>(id >> 32),
                              static_cast<std::uint32_t>(step),
                              (static_cast<std::uint32_t>(step >> 32) & 0xFFFFu) | (stream << 16)};
        const PhiloxCounter w = philox4x32(c, key_);
        return {uniformOpen01(w[0]), uniformOpen01(w[1]), uniformOpen01(w[2]), uniformOpen01(w[3])};
    }

private:
    static constexpr double kSqrt12 = 3.4641016151377545870548926830117;
    // Pair draws use the top bits of the fourth word, which per-particle streams (< 0x8000) never set.
    static constexpr std::uint32_t kPairStream = 0x80000000u;
    PhiloxKey key_;
};

// Named streams for per-particle draws, so no two uses share numbers.
enum RandomStream : std::uint32_t {
    kStreamInitialVelocity = 1,
    kStreamInitialPosition = 2,
    kStreamReflection = 3,
    kStreamWallThermostat = 4,
    kStreamShardlowSweep = 5,  // pair Gaussians of Shardlow's dissipative-random sweep (pairGaussian)
    kStreamTunableSlip = 6,    // random force of a tunable-slip wall (the wall's index in bits 8-14:
                               // walls/TunableSlipParameters.cpp tunableSlipStream)
    kStreamChainBuilder = 7,   // the random walks of setup/ChainBuilder (id = chain, step = draw)
    kStreamGeometryWall = 0x40,  // the geometry wall's reflections: apart from the others, from
                                 // Shardlow's 5 + 16 k and from the +16 of an emitted speed
};

}  // namespace dpd
