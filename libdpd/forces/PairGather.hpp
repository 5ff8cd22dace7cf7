#pragma once
// What the pair force needs of the two particles beyond their separation, gathered from the pair
// inputs (PairInputs.hpp) for eight pairs at a time with AVX2 gather instructions: the relative
// velocity along the separation, (r_i - r_j).(v_i - v_j), and the pair's ids ordered (lower first),
// which key its random number. The same numbers to the bit as the scalar form below (the dot product
// summed in the same order with the same fused multiply-adds), which the pair loop uses for the last
// pairs of a batch.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

#if defined(__AVX2__)
#include <immintrin.h>
#endif

namespace dpd {
namespace detail {

// (r_i - r_j).(v_i - v_j) from the separation d and the velocity difference dv.
inline float separationDotRelativeVelocity(float dx, float dy, float dz, float dvx, float dvy, float dvz) {
    return std::fma(dz, dvz, std::fma(dx, dvx, dy * dvy));
}

struct PairGatherInput {
    const float *vx, *vy, *vz;
    const std::uint32_t* id;
    const std::uint32_t *i, *j;
    const float *dx, *dy, *dz;
};

struct PairGatherOutput {
    float* rDotV;
    std::uint32_t *idLo, *idHi;
};

// Fills entries [0, m) of the output, m the largest multiple of eight up to n (0 without AVX2), and
// returns m; the caller finishes the rest with gatherPairKinematicsScalar.
template <bool kVelocity, bool kRandom>
inline std::size_t gatherPairKinematics(const PairGatherInput& in, const PairGatherOutput& out, std::size_t n) {
    std::size_t k = 0;
#if defined(__AVX2__)
    for (; k + 8 <= n; k += 8) {
        const __m256i i = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(in.i + k));
        const __m256i j = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(in.j + k));
        if constexpr (kVelocity) {
            const __m256 dvx = _mm256_sub_ps(_mm256_i32gather_ps(in.vx, i, 4), _mm256_i32gather_ps(in.vx, j, 4));
            const __m256 dvy = _mm256_sub_ps(_mm256_i32gather_ps(in.vy, i, 4), _mm256_i32gather_ps(in.vy, j, 4));
            const __m256 dvz = _mm256_sub_ps(_mm256_i32gather_ps(in.vz, i, 4), _mm256_i32gather_ps(in.vz, j, 4));
            // As separationDotRelativeVelocity, rounding for rounding.
            const __m256 dot = _mm256_fmadd_ps(
                _mm256_loadu_ps(in.dz + k), dvz,
                _mm256_fmadd_ps(_mm256_loadu_ps(in.dx + k), dvx, _mm256_mul_ps(_mm256_loadu_ps(in.dy + k), dvy)));
            _mm256_storeu_ps(out.rDotV + k, dot);
        }
        if constexpr (kRandom) {
            const auto* ids = reinterpret_cast<const int*>(in.id);
            const __m256i a = _mm256_i32gather_epi32(ids, i, 4), b = _mm256_i32gather_epi32(ids, j, 4);
            _mm256_storeu_si256(reinterpret_cast<__m256i*>(out.idLo + k), _mm256_min_epu32(a, b));
            _mm256_storeu_si256(reinterpret_cast<__m256i*>(out.idHi + k), _mm256_max_epu32(a, b));
        }
    }
#else
    (void)in; (void)out; (void)n;
#endif
    return k;
}

// Entries [first, n), one at a time.
template <bool kVelocity, bool kRandom>
inline void gatherPairKinematicsScalar(const PairGatherInput& in, const PairGatherOutput& out, std::size_t first,
                                       std::size_t n) {
    for (std::size_t k = first; k < n; ++k) {
        const std::uint32_t i = in.i[k], j = in.j[k];
        if constexpr (kVelocity)
            out.rDotV[k] = separationDotRelativeVelocity(in.dx[k], in.dy[k], in.dz[k], in.vx[i] - in.vx[j],
                                                         in.vy[i] - in.vy[j], in.vz[i] - in.vz[j]);
        if constexpr (kRandom) {
            out.idLo[k] = std::min(in.id[i], in.id[j]);
            out.idHi[k] = std::max(in.id[i], in.id[j]);
        }
    }
}

}  // namespace detail
}  // namespace dpd
