#pragma once
// The inner loop of the pair search: of the pairs (i, j), i of the home cell and j of a run of
// candidates contiguous in memory, append those closer than the cutoff to the pair batch (i, j and
// the separation r_i - r_j), in single precision on cell-local positions (PairInputs.hpp).
//
// The loop goes candidate block by candidate block, and for each block over the home cell's
// particles: a block's candidates are loaded once for the ~3 particles of the cell, and the inner
// loop's trip count (the cell's particle count) is the same for every block of the cell, so the
// branch predictor learns it. Where the CPU has AVX2 a block is eight candidates, the ones inside are
// packed to the front with a permutation looked up by the 8-bit mask (a "compress") and stored
// together: every store writes eight entries, so the batch needs seven entries of room beyond the
// pairs. The scalar form visits the pairs in the same order, with the same arithmetic (the squared
// distance as two fused multiply-adds), so it finds the same pairs in the same order.
#include <cmath>
#include <cstddef>
#include <cstdint>

#if defined(__AVX2__)
#include <immintrin.h>
#endif

namespace dpd {
namespace detail {

// A step no candidate reaches (indices stay below 2^31 - 1, the search compares them signed).
inline constexpr std::uint32_t kNoStep = 0x7FFFFFFFu;

// Candidates [jBegin, jEnd) for the home cell's particles [iBegin, iEnd). They lie in up to three
// consecutive cells along z: a candidate stands at its cell-local position plus (offX, offY, offZ),
// plus one cell size along z from zStep1 on, and one more from zStep2 on.
struct NeighbourRun {
    std::uint32_t jBegin, jEnd;
    std::uint32_t zStep1, zStep2;
    float offX, offY, offZ;
    std::uint32_t iBegin, iEnd;
    bool onlyAfterI;  // the run holds the home cell itself: only the partners j > i
};

struct PairSearchInput {
    const float *x, *y, *z;  // cell-local positions
    float cellZ;             // the cell size along z
    float cutoff2;           // squared cutoff, rounded down to a float
};

struct PairSearchOutput {
    std::uint32_t *i, *j;
    float *dx, *dy, *dz;
};

// Squared distance as the search computes it, and as the force pass recomputes it to the bit.
inline float squaredDistance(float dx, float dy, float dz) { return std::fma(dz, dz, std::fma(dy, dy, dx * dx)); }

#if defined(__AVX2__)
// For each 8-bit mask, the permutation of 32-bit lanes that moves the set lanes to the front.
struct CompressTable {
    alignas(32) std::int32_t lanes[256][8];
    constexpr CompressTable() : lanes() {
        for (int mask = 0; mask < 256; ++mask) {
            int slot = 0;
            for (int lane = 0; lane < 8; ++lane)
                if (mask & (1 << lane)) lanes[mask][slot++] = lane;
        }
    }
};
inline constexpr CompressTable kCompress{};

inline std::size_t appendRunPairs(const NeighbourRun& run, const PairSearchInput& in, const PairSearchOutput& out,
                                  std::size_t k) {
    const __m256i lanes = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
    const __m256 c2 = _mm256_set1_ps(in.cutoff2);
    const __m256 offX = _mm256_set1_ps(run.offX), offY = _mm256_set1_ps(run.offY);
    const __m256i step1 = _mm256_set1_epi32(static_cast<int>(run.zStep1) - 1);
    const __m256i step2 = _mm256_set1_epi32(static_cast<int>(run.zStep2) - 1);
    for (std::uint32_t j = run.jBegin; j < run.jEnd; j += 8) {
        // Lanes past the end are masked: not loaded (no read past the arrays) and never kept.
        const __m256i valid = _mm256_cmpgt_epi32(_mm256_set1_epi32(static_cast<int>(run.jEnd - j)), lanes);
        const __m256i js = _mm256_add_epi32(_mm256_set1_epi32(static_cast<int>(j)), lanes);
        // Cells up along z: 0, 1 or 2 (the comparisons give -1 per step passed).
        const __m256i cellsUp = _mm256_sub_epi32(_mm256_setzero_si256(),
                                                 _mm256_add_epi32(_mm256_cmpgt_epi32(js, step1), _mm256_cmpgt_epi32(js, step2)));
        const __m256 offZ = _mm256_fmadd_ps(_mm256_cvtepi32_ps(cellsUp), _mm256_set1_ps(in.cellZ), _mm256_set1_ps(run.offZ));
        const __m256 X = _mm256_add_ps(_mm256_maskload_ps(in.x + j, valid), offX);
        const __m256 Y = _mm256_add_ps(_mm256_maskload_ps(in.y + j, valid), offY);
        const __m256 Z = _mm256_add_ps(_mm256_maskload_ps(in.z + j, valid), offZ);
        for (std::uint32_t i = run.iBegin; i < run.iEnd; ++i) {
            __m256i keep = valid;
            if (run.onlyAfterI) keep = _mm256_and_si256(keep, _mm256_cmpgt_epi32(js, _mm256_set1_epi32(static_cast<int>(i))));
            const __m256 dx = _mm256_sub_ps(_mm256_set1_ps(in.x[i]), X);
            const __m256 dy = _mm256_sub_ps(_mm256_set1_ps(in.y[i]), Y);
            const __m256 dz = _mm256_sub_ps(_mm256_set1_ps(in.z[i]), Z);
            const __m256 r2 = _mm256_fmadd_ps(dz, dz, _mm256_fmadd_ps(dy, dy, _mm256_mul_ps(dx, dx)));
            const __m256 inside = _mm256_and_ps(_mm256_cmp_ps(r2, c2, _CMP_LT_OQ), _mm256_castsi256_ps(keep));
            // No branch on the mask: whether a block holds a pair is a coin toss the predictor would lose.
            const int mask = _mm256_movemask_ps(inside);
            const __m256i perm = _mm256_load_si256(reinterpret_cast<const __m256i*>(kCompress.lanes[mask]));
            _mm256_storeu_si256(reinterpret_cast<__m256i*>(out.j + k), _mm256_permutevar8x32_epi32(js, perm));
            _mm256_storeu_si256(reinterpret_cast<__m256i*>(out.i + k), _mm256_set1_epi32(static_cast<int>(i)));
            _mm256_storeu_ps(out.dx + k, _mm256_permutevar8x32_ps(dx, perm));
            _mm256_storeu_ps(out.dy + k, _mm256_permutevar8x32_ps(dy, perm));
            _mm256_storeu_ps(out.dz + k, _mm256_permutevar8x32_ps(dz, perm));
            k += static_cast<std::size_t>(__builtin_popcount(static_cast<unsigned>(mask)));
        }
    }
    return k;
}
#else
inline std::size_t appendRunPairs(const NeighbourRun& run, const PairSearchInput& in, const PairSearchOutput& out,
                                  std::size_t k) {
    for (std::uint32_t block = run.jBegin; block < run.jEnd; block += 8) {
        const std::uint32_t blockEnd = block + 8 < run.jEnd ? block + 8 : run.jEnd;
        for (std::uint32_t i = run.iBegin; i < run.iEnd; ++i)
            for (std::uint32_t j = block; j < blockEnd; ++j) {
                if (run.onlyAfterI && j <= i) continue;
                const int cellsUp = (j >= run.zStep1 ? 1 : 0) + (j >= run.zStep2 ? 1 : 0);
                const float offZ = std::fma(static_cast<float>(cellsUp), in.cellZ, run.offZ);
                const float dx = in.x[i] - (in.x[j] + run.offX);
                const float dy = in.y[i] - (in.y[j] + run.offY);
                const float dz = in.z[i] - (in.z[j] + offZ);
                if (!(squaredDistance(dx, dy, dz) < in.cutoff2)) continue;
                out.i[k] = i; out.j[k] = j; out.dx[k] = dx; out.dy[k] = dy; out.dz[k] = dz;
                ++k;
            }
    }
    return k;
}
#endif

}  // namespace detail
}  // namespace dpd
