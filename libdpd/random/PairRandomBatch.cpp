// PairRandom::orderedPairUniforms: Philox4x32-10 on eight counters at once with AVX2.
//
// A Philox round needs the high and low halves of two 32 x 32 -> 64-bit products per counter. AVX2
// multiplies the even 32-bit lanes of a vector (_mm256_mul_epu32); the odd lanes are shifted down
// and multiplied in a second instruction, and blends put the halves back in place. Integer arithmetic
// only, so every lane gives exactly the scalar generator's bits; the conversion to a unit-variance
// uniform is the same exact-then-one-rounding sum as unitVarianceUniform.
#include "random/PairRandom.hpp"

#if defined(__AVX2__)
#include <immintrin.h>
#endif

namespace dpd {

#if defined(__AVX2__)
namespace {

struct MulHiLo {
    __m256i hi, lo;
};

inline MulHiLo mulHiLo(__m256i a, __m256i m) {
    const __m256i even = _mm256_mul_epu32(a, m);
    const __m256i odd = _mm256_mul_epu32(_mm256_srli_epi64(a, 32), m);
    return {_mm256_blend_epi32(_mm256_srli_epi64(even, 32), odd, 0xAA),
            _mm256_blend_epi32(even, _mm256_slli_epi64(odd, 32), 0xAA)};
}

// First output word of Philox4x32-10 for eight counters (c0, c1, c2, c3) under one key.
inline __m256i philoxFirstWord(__m256i c0, __m256i c1, __m256i c2, __m256i c3, PhiloxKey key) {
    const __m256i m0 = _mm256_set1_epi32(static_cast<int>(0xD2511F53u));
    const __m256i m1 = _mm256_set1_epi32(static_cast<int>(0xCD9E8D57u));
    for (int round = 0; round < 10; ++round) {
        const MulHiLo p0 = mulHiLo(c0, m0), p1 = mulHiLo(c2, m1);
        const __m256i k0 = _mm256_set1_epi32(static_cast<int>(key[0]));
        const __m256i k1 = _mm256_set1_epi32(static_cast<int>(key[1]));
        c0 = _mm256_xor_si256(_mm256_xor_si256(p1.hi, c1), k0);
        c1 = p1.lo;
        c2 = _mm256_xor_si256(_mm256_xor_si256(p0.hi, c3), k1);
        c3 = p0.lo;
        key[0] += 0x9E3779B9u;
        key[1] += 0xBB67AE85u;
    }
    return c0;
}

}  // namespace
#endif

void PairRandom::orderedPairUniforms(std::uint64_t step, const std::uint32_t* lo, const std::uint32_t* hi,
                                     double* zeta, std::size_t n) const {
    std::size_t k = 0;
#if defined(__AVX2__)
    const __m256i stepLo = _mm256_set1_epi32(static_cast<int>(static_cast<std::uint32_t>(step)));
    const __m256i stepHi = _mm256_set1_epi32(static_cast<int>(static_cast<std::uint32_t>(step >> 32) ^ kPairStream));
    const __m256i signBit = _mm256_set1_epi32(static_cast<int>(0x80000000u));
    const __m256d half = _mm256_set1_pd(0.5), scale = _mm256_set1_pd(kSqrt12 * 0x1p-32);
    for (; k + 8 <= n; k += 8) {
        const __m256i c0 = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(lo + k));
        const __m256i c1 = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(hi + k));
        const __m256i centred = _mm256_xor_si256(philoxFirstWord(c0, c1, stepLo, stepHi, key_), signBit);
        const __m256d low = _mm256_cvtepi32_pd(_mm256_castsi256_si128(centred));
        const __m256d high = _mm256_cvtepi32_pd(_mm256_extracti128_si256(centred, 1));
        _mm256_storeu_pd(zeta + k, _mm256_mul_pd(_mm256_add_pd(low, half), scale));
        _mm256_storeu_pd(zeta + k + 4, _mm256_mul_pd(_mm256_add_pd(high, half), scale));
    }
#endif
    for (; k < n; ++k) zeta[k] = orderedPairUniform(step, lo[k], hi[k]);
}

}  // namespace dpd
