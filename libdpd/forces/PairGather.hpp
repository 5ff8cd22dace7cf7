#pragma once
// What the pair force needs of the two particles beyond their separation, gathered for four pairs at
// a time with AVX2 gather instructions: the relative velocity along the separation,
// (r_i - r_j).(v_i - v_j), and the pair's ids ordered (lower first, cut to 32 bits), which key its
// random number. The same numbers to the bit as the scalar form below (the dot product summed in the
// same order with the same fused multiply-adds, written out so that no compiler contracts it its own
// way), which the pair loop uses for the last pairs of a batch.
#include <cmath>
#include <cstddef>
#include <cstdint>

#if defined(__AVX2__)
#include <immintrin.h>
#endif

namespace dpd {
namespace detail {

// (r_i - r_j).(v_i - v_j) from the separation d and the velocity difference dv.
// Without FMA hardware (and so without AVX2) std::fma would be a slow library call: the plain sum.
inline double separationDotRelativeVelocity(double dx, double dy, double dz, double dvx, double dvy, double dvz) {
#if defined(__FMA__)
    return std::fma(dz, dvz, std::fma(dx, dvx, dy * dvy));
#else
    return dx * dvx + dy * dvy + dz * dvz;
#endif
}

struct PairGatherInput {
    const double *vx, *vy, *vz;
    const std::uint64_t* id;
    const std::uint32_t *i, *j;
    const double *dx, *dy, *dz;
};

struct PairGatherOutput {
    double* rDotV;
    std::uint32_t *idLo, *idHi;
};

// Fills entries [0, m) of the output, m the largest multiple of four up to n (0 without AVX2), and
// returns m; the caller finishes the rest.
template <bool kVelocity, bool kRandom>
inline std::size_t gatherPairKinematics(const PairGatherInput& in, const PairGatherOutput& out, std::size_t n) {
    std::size_t k = 0;
#if defined(__AVX2__)
    // Lanes 0, 2, 4, 6: the low halves of four 64-bit ids.
    const __m256i lowHalves = _mm256_setr_epi32(0, 2, 4, 6, 0, 0, 0, 0);
    // The masked gathers with every lane on are the plain ones (GCC 12 warns about the plain ones'
    // undefined source operand).
    const __m256d all = _mm256_castsi256_pd(_mm256_set1_epi64x(-1));
    const auto gather = [all](const double* base, __m128i index) {
        return _mm256_mask_i32gather_pd(_mm256_setzero_pd(), base, index, all, 8);
    };
    for (; k + 4 <= n; k += 4) {
        const __m128i i = _mm_loadu_si128(reinterpret_cast<const __m128i*>(in.i + k));
        const __m128i j = _mm_loadu_si128(reinterpret_cast<const __m128i*>(in.j + k));
        if constexpr (kVelocity) {
            const __m256d dvx = _mm256_sub_pd(gather(in.vx, i), gather(in.vx, j));
            const __m256d dvy = _mm256_sub_pd(gather(in.vy, i), gather(in.vy, j));
            const __m256d dvz = _mm256_sub_pd(gather(in.vz, i), gather(in.vz, j));
            // As separationDotRelativeVelocity, rounding for rounding.
            const __m256d dot = _mm256_fmadd_pd(
                _mm256_loadu_pd(in.dz + k), dvz,
                _mm256_fmadd_pd(_mm256_loadu_pd(in.dx + k), dvx, _mm256_mul_pd(_mm256_loadu_pd(in.dy + k), dvy)));
            _mm256_storeu_pd(out.rDotV + k, dot);
        }
        if constexpr (kRandom) {
            const auto* ids = reinterpret_cast<const long long*>(in.id);
            const __m256i on = _mm256_castpd_si256(all);
            const __m256i a = _mm256_mask_i32gather_epi64(_mm256_setzero_si256(), ids, i, on, 8);
            const __m256i b = _mm256_mask_i32gather_epi64(_mm256_setzero_si256(), ids, j, on, 8);
            // Signed comparison: ids stay far below 2^63.
            const __m256i aAbove = _mm256_cmpgt_epi64(a, b);
            const __m256i lo = _mm256_blendv_epi8(a, b, aAbove), hi = _mm256_blendv_epi8(b, a, aAbove);
            _mm_storeu_si128(reinterpret_cast<__m128i*>(out.idLo + k),
                             _mm256_castsi256_si128(_mm256_permutevar8x32_epi32(lo, lowHalves)));
            _mm_storeu_si128(reinterpret_cast<__m128i*>(out.idHi + k),
                             _mm256_castsi256_si128(_mm256_permutevar8x32_epi32(hi, lowHalves)));
        }
    }
#else
    (void)in; (void)out; (void)n;
#endif
    return k;
}

}  // namespace detail
}  // namespace dpd
