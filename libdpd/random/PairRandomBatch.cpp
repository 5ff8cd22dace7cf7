// PairRandom::orderedPairUniforms: Philox4x32-10 on eight counters at once with AVX2.
//
// A Philox round needs the high and low halves of two 32 x 32 -> 64-bit products per counter. AVX2
// multiplies the even 32-bit lanes of a vector (_mm256_mul_epu32); the odd lanes are shifted down
// and multiplied in a second instruction, and a blend puts the high halves in place; the low halves
// are one _mm256_mullo_epi32. Integer arithmetic only, so every lane gives exactly the scalar
// generator's bits; the conversion to a unit-variance uniform is the same exact-then-one-rounding sum
// as unitVarianceUniform.
//
// The pair force reads word 0 of the output only, and the counters of one call share their last two
// words (the step): so round 0's product of the third word is one scalar product for all lanes, and
// the last two rounds make only what word 0 depends on (~10 % fewer instructions than ten full rounds).
#include "random/PairRandom.hpp"

#if defined(__AVX2__)
#include <immintrin.h>
#endif

namespace dpd {

#if defined(__AVX2__)
namespace {

inline __m256i broadcast(std::uint32_t word) { return _mm256_set1_epi32(static_cast<int>(word)); }

inline __m256i xor3(__m256i a, __m256i b, __m256i c) { return _mm256_xor_si256(_mm256_xor_si256(a, b), c); }

// The high halves of the eight products a * m.
inline __m256i mulHi(__m256i a, __m256i m) {
    const __m256i even = _mm256_mul_epu32(a, m);
    const __m256i odd = _mm256_mul_epu32(_mm256_srli_epi64(a, 32), m);
    return _mm256_blend_epi32(_mm256_srli_epi64(even, 32), odd, 0xAA);
}

// Word 0 of Philox4x32-10 for G groups of eight counters (lo, hi, s0, s1) under one key. The groups
// go through each round together, so that one group's dependent products do not leave the
// multipliers idle (measurements: applications/utilities/dpdBenchmark/README.md).
template <int G>
inline void philoxFirstWords(const __m256i (&lo)[G], const __m256i (&hi)[G], std::uint32_t s0, std::uint32_t s1,
                             PhiloxKey key, __m256i (&word0)[G]) {
    const __m256i m0 = broadcast(kPhiloxM0), m1 = broadcast(kPhiloxM1);
    // Round 0: (c0, c1, c2, c3) = (lo, hi, s0, s1) becomes
    // (hi(M1 s0) ^ hi ^ k0, lo(M1 s0), hi(M0 lo) ^ s1 ^ k1, lo(M0 lo)).
    const std::uint64_t p = std::uint64_t{kPhiloxM1} * s0;
    const __m256i c1First = broadcast(static_cast<std::uint32_t>(p));
    __m256i c0[G], c1[G], c2[G], c3[G];
    for (int g = 0; g < G; ++g) {
        c0[g] = _mm256_xor_si256(hi[g], broadcast(static_cast<std::uint32_t>(p >> 32) ^ key[0]));
        c1[g] = c1First;
        c2[g] = _mm256_xor_si256(mulHi(lo[g], m0), broadcast(s1 ^ key[1]));
        c3[g] = _mm256_mullo_epi32(lo[g], m0);
    }
    for (int round = 1; round < 8; ++round) {
        key[0] += kPhiloxW0;
        key[1] += kPhiloxW1;
        for (int g = 0; g < G; ++g) {
            const __m256i hi0 = mulHi(c0[g], m0), lo0 = _mm256_mullo_epi32(c0[g], m0);
            const __m256i hi1 = mulHi(c2[g], m1), lo1 = _mm256_mullo_epi32(c2[g], m1);
            c0[g] = xor3(hi1, c1[g], broadcast(key[0]));
            c1[g] = lo1;
            c2[g] = xor3(hi0, c3[g], broadcast(key[1]));
            c3[g] = lo0;
        }
    }
    // Round 8: only the words round 9 reads, c1 and c2; round 9: word 0 alone.
    key[0] += kPhiloxW0;
    key[1] += kPhiloxW1;
    const std::uint32_t lastKey0 = key[0] + kPhiloxW0;
    for (int g = 0; g < G; ++g) {
        const __m256i c1Last = _mm256_mullo_epi32(c2[g], m1);
        const __m256i c2Last = xor3(mulHi(c0[g], m0), c3[g], broadcast(key[1]));
        word0[g] = xor3(mulHi(c2Last, m1), c1Last, broadcast(lastKey0));
    }
}

// ((int) (bits ^ 2^31) + 1/2) scale of eight words, as unitVarianceUniform (scale sqrt(12) 2^-32),
// stored at zeta[0..7].
inline void storeUnitVarianceUniforms(__m256i bits, __m256d scale, double* zeta) {
    const __m256i centred = _mm256_xor_si256(bits, _mm256_set1_epi32(static_cast<int>(0x80000000u)));
    const __m256d half = _mm256_set1_pd(0.5);
    const __m256d low = _mm256_cvtepi32_pd(_mm256_castsi256_si128(centred));
    const __m256d high = _mm256_cvtepi32_pd(_mm256_extracti128_si256(centred, 1));
    _mm256_storeu_pd(zeta, _mm256_mul_pd(_mm256_add_pd(low, half), scale));
    _mm256_storeu_pd(zeta + 4, _mm256_mul_pd(_mm256_add_pd(high, half), scale));
}

inline __m256i load8(const std::uint32_t* words) { return _mm256_loadu_si256(reinterpret_cast<const __m256i*>(words)); }

}  // namespace
#endif

void PairRandom::orderedPairUniforms(std::uint64_t step, const std::uint32_t* lo, const std::uint32_t* hi,
                                     double* zeta, std::size_t n) const {
    std::size_t k = 0;
#if defined(__AVX2__)
    const auto stepLo = static_cast<std::uint32_t>(step);
    const std::uint32_t stepHi = static_cast<std::uint32_t>(step >> 32) ^ kPairStream;
    const __m256d scale = _mm256_set1_pd(kSqrt12 * 0x1p-32);
    for (; k + 16 <= n; k += 16) {
        const __m256i l[2] = {load8(lo + k), load8(lo + k + 8)}, h[2] = {load8(hi + k), load8(hi + k + 8)};
        __m256i w[2];
        philoxFirstWords<2>(l, h, stepLo, stepHi, key_, w);
        storeUnitVarianceUniforms(w[0], scale, zeta + k);
        storeUnitVarianceUniforms(w[1], scale, zeta + k + 8);
    }
    for (; k + 8 <= n; k += 8) {
        const __m256i l[1] = {load8(lo + k)}, h[1] = {load8(hi + k)};
        __m256i w[1];
        philoxFirstWords<1>(l, h, stepLo, stepHi, key_, w);
        storeUnitVarianceUniforms(w[0], scale, zeta + k);
    }
#endif
    for (; k < n; ++k) zeta[k] = orderedPairUniform(step, lo[k], hi[k]);
}

}  // namespace dpd
