#pragma once
// The inner loop of the pair search: of the candidates j in [jBegin, jEnd), append those closer to
// particle i than the cutoff to the pair batch (i, j and the separation r_i - r_j).
//
// Where the CPU has AVX2 four candidates are tested at once and the ones inside are packed to the
// front with a permutation looked up by the 4-bit mask (a "compress"), then stored together. Every
// store writes four entries, so the batch needs three entries of room beyond the candidates. Elsewhere
// a scalar loop writes every candidate and moves the count on only for the ones kept (no branch).
// Both give the same pairs in the same order.
#include <cstddef>
#include <cstdint>

#if defined(__AVX2__)
#include <immintrin.h>
#endif

namespace dpd {
namespace detail {

struct PairSearchOutput {
    std::uint32_t* i;
    std::uint32_t* j;
    double* dx;
    double* dy;
    double* dz;
};

#if defined(__AVX2__)
// For each 4-bit mask, the permutation that moves the set lanes to the front: as 32-bit lane indices
// for the j indices, and as pairs of 32-bit lanes for the doubles.
struct CompressTables {
    alignas(32) std::int32_t index[16][8];
    alignas(32) std::int32_t pairs[16][8];
    constexpr CompressTables() : index(), pairs() {
        for (int mask = 0; mask < 16; ++mask) {
            int slot = 0;
            for (int lane = 0; lane < 4; ++lane)
                if (mask & (1 << lane)) {
                    index[mask][slot] = lane;
                    pairs[mask][2 * slot] = 2 * lane;
                    pairs[mask][2 * slot + 1] = 2 * lane + 1;
                    ++slot;
                }
        }
    }
};
inline constexpr CompressTables kCompress{};

inline void storeCompressed(double* out, __m256d v, __m256i pairs) {
    _mm256_storeu_pd(out, _mm256_castps_pd(_mm256_permutevar8x32_ps(_mm256_castpd_ps(v), pairs)));
}
#endif

inline std::size_t appendPairsWithinCutoff(std::uint32_t i, double xi, double yi, double zi, std::uint32_t jBegin,
                                           std::uint32_t jEnd, const double* __restrict rx,
                                           const double* __restrict ry, const double* __restrict rz,
                                           double cutoff2, const PairSearchOutput& out, std::size_t k) {
#if defined(__AVX2__)
    const __m256d x = _mm256_set1_pd(xi), y = _mm256_set1_pd(yi), z = _mm256_set1_pd(zi);
    const __m256d c2 = _mm256_set1_pd(cutoff2);
    const __m256i lanes = _mm256_setr_epi64x(0, 1, 2, 3);
    const __m256i laneOffsets = _mm256_setr_epi32(0, 1, 2, 3, 0, 0, 0, 0);
    const __m128i iv = _mm_set1_epi32(static_cast<int>(i));
    for (std::uint32_t j = jBegin; j < jEnd; j += 4) {
        // Lanes past the end are masked: not loaded (no read past the arrays) and never kept.
        const __m256i valid = _mm256_cmpgt_epi64(_mm256_set1_epi64x(static_cast<long long>(jEnd - j)), lanes);
        const __m256d dx = _mm256_sub_pd(x, _mm256_maskload_pd(rx + j, valid));
        const __m256d dy = _mm256_sub_pd(y, _mm256_maskload_pd(ry + j, valid));
        const __m256d dz = _mm256_sub_pd(z, _mm256_maskload_pd(rz + j, valid));
        const __m256d r2 = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy)), _mm256_mul_pd(dz, dz));
        const __m256d inside = _mm256_and_pd(_mm256_cmp_pd(r2, c2, _CMP_LT_OQ), _mm256_castsi256_pd(valid));
        // No branch on the mask: whether a block holds a pair is a coin toss the predictor would lose.
        const int mask = _mm256_movemask_pd(inside);
        const __m256i pairs = _mm256_load_si256(reinterpret_cast<const __m256i*>(kCompress.pairs[mask]));
        const __m256i index = _mm256_load_si256(reinterpret_cast<const __m256i*>(kCompress.index[mask]));
        const __m256i js = _mm256_add_epi32(_mm256_set1_epi32(static_cast<int>(j)), laneOffsets);
        _mm_storeu_si128(reinterpret_cast<__m128i*>(out.j + k), _mm256_castsi256_si128(_mm256_permutevar8x32_epi32(js, index)));
        _mm_storeu_si128(reinterpret_cast<__m128i*>(out.i + k), iv);
        storeCompressed(out.dx + k, dx, pairs);
        storeCompressed(out.dy + k, dy, pairs);
        storeCompressed(out.dz + k, dz, pairs);
        k += static_cast<std::size_t>(__builtin_popcount(static_cast<unsigned>(mask)));
    }
    return k;
#else
    for (std::uint32_t j = jBegin; j < jEnd; ++j) {
        const double dx = xi - rx[j], dy = yi - ry[j], dz = zi - rz[j];
        const double r2 = dx * dx + dy * dy + dz * dz;
        out.i[k] = i; out.j[k] = j; out.dx[k] = dx; out.dy[k] = dy; out.dz[k] = dz;
        k += r2 < cutoff2 ? 1 : 0;
    }
    return k;
#endif
}

}  // namespace detail
}  // namespace dpd
