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
//
// The neighbour columns other than the home one hold ~9 candidates each for a home cell, one more
// than a block: searched column by column, the second block of a column is mostly empty lanes. So a
// row of home cells first stages its neighbour columns level by level (RowStage: for each z index,
// the particles of that cell of every column), and a home cell away from the z boundary then finds
// all its candidates but the home column's in one contiguous window of three levels, searched in
// full blocks (~5 blocks per home particle instead of ~7 at rho 3). Each particle is staged once per
// column, not once per home cell that sees it.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

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

// The neighbour columns of one row of home cells (all but the home column), staged level by level:
// for each z index c, the particles of cell c of each column in turn, at their cell-local position
// plus the column's x and y offsets (z stays cell-local: where the levels start says how far up),
// with their indices and, where frozen particles are kept apart, whether each is mobile. Each thread
// keeps its own.
struct RowStage {
    std::vector<float> x, y, z;
    std::vector<std::uint32_t> j;
    std::vector<std::int32_t> mobile;        // all bits set for a mobile candidate (filled when split)
    std::vector<std::uint32_t> levelStart;   // level c is entries [levelStart[c], levelStart[c + 1])

    // Room for `count` entries plus the seven lanes a block of eight may read or write beyond them.
    void reserve(std::size_t count, int levels) {
        levelStart.resize(static_cast<std::size_t>(levels) + 1);
        if (count + 8 <= j.size()) return;
        const std::size_t n = std::max(count + 8, 2 * j.size());
        x.resize(n); y.resize(n); z.resize(n); j.resize(n); mobile.resize(n);
    }
};

// Where stageCell writes: the stage's arrays (raw pointers: a vector's own pointer would be reloaded
// after every vector store, which may alias it).
struct StageOutput {
    float *x, *y, *z;
    std::uint32_t* j;
    std::int32_t* mobile;
    explicit StageOutput(RowStage& st)
        : x(st.x.data()), y(st.y.data()), z(st.z.data()), j(st.j.data()), mobile(st.mobile.data()) {}
};

inline RowStage& threadRowStage() {
    thread_local RowStage stage;
    return stage;
}

// Squared distance as the search computes it, and as the force pass recomputes it to the bit.
inline float squaredDistance(float dx, float dy, float dz) { return std::fma(dz, dz, std::fma(dy, dy, dx * dx)); }

// The home cell and the one above it in its column, consecutive in memory: the home particles
// [begin, end) (mobile before mobileEnd) and the candidates [begin, aboveEnd), those from end on (the
// cell above) one cell size up along z (mobile before aboveMobileEnd).
struct HomeColumnCells {
    std::uint32_t begin, mobileEnd, end;     // the home cell
    std::uint32_t aboveMobileEnd, aboveEnd;  // the cell above, which starts at end
};

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

// Block of candidates (X, Y, Z, indices js) against home particle i: those of `keep` closer than the
// cutoff packed to the front with the permutation their mask looks up, and appended at k together
// (every store writes eight entries). Returns the new end. No branch on the mask: whether a block
// holds a pair is a coin toss the predictor would lose.
inline std::size_t appendBlockHits(std::uint32_t i, __m256 X, __m256 Y, __m256 Z, __m256i js, __m256 keep,
                                   const PairSearchInput& in, const PairSearchOutput& out, std::size_t k) {
    const __m256 dx = _mm256_sub_ps(_mm256_set1_ps(in.x[i]), X);
    const __m256 dy = _mm256_sub_ps(_mm256_set1_ps(in.y[i]), Y);
    const __m256 dz = _mm256_sub_ps(_mm256_set1_ps(in.z[i]), Z);
    const __m256 r2 = _mm256_fmadd_ps(dz, dz, _mm256_fmadd_ps(dy, dy, _mm256_mul_ps(dx, dx)));
    const int mask = _mm256_movemask_ps(_mm256_and_ps(_mm256_cmp_ps(r2, _mm256_set1_ps(in.cutoff2), _CMP_LT_OQ), keep));
    const __m256i perm = _mm256_load_si256(reinterpret_cast<const __m256i*>(kCompress.lanes[mask]));
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(out.j + k), _mm256_permutevar8x32_epi32(js, perm));
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(out.i + k), _mm256_set1_epi32(static_cast<int>(i)));
    _mm256_storeu_ps(out.dx + k, _mm256_permutevar8x32_ps(dx, perm));
    _mm256_storeu_ps(out.dy + k, _mm256_permutevar8x32_ps(dy, perm));
    _mm256_storeu_ps(out.dz + k, _mm256_permutevar8x32_ps(dz, perm));
    return k + static_cast<std::size_t>(__builtin_popcount(static_cast<unsigned>(mask)));
}

inline std::size_t appendRunPairs(const NeighbourRun& run, const PairSearchInput& in, const PairSearchOutput& out,
                                  std::size_t k) {
    const __m256i lanes = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
    const __m256 offX = _mm256_set1_ps(run.offX), offY = _mm256_set1_ps(run.offY);
    const __m256i step1 = _mm256_set1_epi32(static_cast<int>(run.zStep1) - 1);
    const __m256i step2 = _mm256_set1_epi32(static_cast<int>(run.zStep2) - 1);
    for (std::uint32_t j = run.jBegin; j < run.jEnd; j += 8) {
        // Lanes past the end are loaded (the inputs have room: kPairInputPadding; a masked load
        // cost Zen 3 several times as much) but never kept.
        const __m256i valid = _mm256_cmpgt_epi32(_mm256_set1_epi32(static_cast<int>(run.jEnd - j)), lanes);
        const __m256i js = _mm256_add_epi32(_mm256_set1_epi32(static_cast<int>(j)), lanes);
        // Cells up along z: 0, 1 or 2 (the comparisons give -1 per step passed).
        const __m256i cellsUp = _mm256_sub_epi32(_mm256_setzero_si256(),
                                                 _mm256_add_epi32(_mm256_cmpgt_epi32(js, step1), _mm256_cmpgt_epi32(js, step2)));
        const __m256 offZ = _mm256_fmadd_ps(_mm256_cvtepi32_ps(cellsUp), _mm256_set1_ps(in.cellZ), _mm256_set1_ps(run.offZ));
        const __m256 X = _mm256_add_ps(_mm256_loadu_ps(in.x + j), offX);
        const __m256 Y = _mm256_add_ps(_mm256_loadu_ps(in.y + j), offY);
        const __m256 Z = _mm256_add_ps(_mm256_loadu_ps(in.z + j), offZ);
        for (std::uint32_t i = run.iBegin; i < run.iEnd; ++i) {
            __m256i keep = valid;
            if (run.onlyAfterI) keep = _mm256_and_si256(keep, _mm256_cmpgt_epi32(js, _mm256_set1_epi32(static_cast<int>(i))));
            k = appendBlockHits(i, X, Y, Z, js, _mm256_castsi256_ps(keep), in, out, k);
        }
    }
    return k;
}

// Appends particles [jBegin, jEnd) of one cell to the stage from entry s on (those before
// mobileEnd mobile); returns the new end.
inline std::uint32_t stageCell(const PairSearchInput& in, std::uint32_t jBegin, std::uint32_t jEnd, std::uint32_t mobileEnd,
                               float offX, float offY, bool split, const StageOutput& st, std::uint32_t s) {
    const __m256i lanes = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
    for (std::uint32_t j = jBegin; j < jEnd; j += 8) {
        const __m256i js = _mm256_add_epi32(_mm256_set1_epi32(static_cast<int>(j)), lanes);
        // Lanes past the cell's end are read (the inputs have room: kPairInputPadding) and written
        // too, and overwritten by the next cell's particles.
        _mm256_storeu_ps(st.x + s, _mm256_add_ps(_mm256_loadu_ps(in.x + j), _mm256_set1_ps(offX)));
        _mm256_storeu_ps(st.y + s, _mm256_add_ps(_mm256_loadu_ps(in.y + j), _mm256_set1_ps(offY)));
        _mm256_storeu_ps(st.z + s, _mm256_loadu_ps(in.z + j));
        _mm256_storeu_si256(reinterpret_cast<__m256i*>(st.j + s), js);
        if (split)
            _mm256_storeu_si256(reinterpret_cast<__m256i*>(st.mobile + s),
                                _mm256_cmpgt_epi32(_mm256_set1_epi32(static_cast<int>(mobileEnd)), js));
        s += std::min<std::uint32_t>(8, jEnd - j);
    }
    return s;
}

// The pairs of the home cell's particles among themselves (j > i) and with the cell above, for a
// home cell away from the top of its column. Written for this one case instead of built as a run
// (NeighbourRun) for appendRunPairs, whose set-up per home cell cost about as much as its blocks.
// A mobile home particle meets every candidate, a frozen one only the mobile candidates (none of
// them after it in its own cell, where the mobile come first); pairs come block by block, for each
// block the home particles in order.
inline std::size_t appendHomeColumnPairs(const HomeColumnCells& c, bool split, const PairSearchInput& in,
                                         const PairSearchOutput& out, std::size_t k) {
    const __m256i lanes = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
    const __m256i aboveFrom = _mm256_set1_epi32(static_cast<int>(c.end) - 1);
    const __m256 cellZ = _mm256_set1_ps(in.cellZ);
    for (std::uint32_t j = c.begin; j < c.aboveEnd; j += 8) {
        const __m256i js = _mm256_add_epi32(_mm256_set1_epi32(static_cast<int>(j)), lanes);
        const __m256i valid = _mm256_cmpgt_epi32(_mm256_set1_epi32(static_cast<int>(c.aboveEnd)), js);
        const __m256i above = _mm256_cmpgt_epi32(js, aboveFrom);  // -1 in the cell above
        __m256i validMobile = valid;
        if (split) {
            // Mobile: before the home cell's mobile end, or in the cell above before its own.
            const __m256i homeMobile = _mm256_cmpgt_epi32(_mm256_set1_epi32(static_cast<int>(c.mobileEnd)), js);
            const __m256i aboveMobile =
                _mm256_and_si256(above, _mm256_cmpgt_epi32(_mm256_set1_epi32(static_cast<int>(c.aboveMobileEnd)), js));
            validMobile = _mm256_and_si256(valid, _mm256_or_si256(homeMobile, aboveMobile));
        }
        const __m256 X = _mm256_loadu_ps(in.x + j), Y = _mm256_loadu_ps(in.y + j);
        // z + 1 cell size in the cell above (the and of -1 with its bits), z + 0 in the home cell.
        const __m256 Z = _mm256_add_ps(_mm256_loadu_ps(in.z + j), _mm256_and_ps(_mm256_castsi256_ps(above), cellZ));
        for (std::uint32_t i = c.begin; i < c.end; ++i) {
            const __m256i after = _mm256_cmpgt_epi32(js, _mm256_set1_epi32(static_cast<int>(i)));
            const __m256i keep = _mm256_and_si256(after, i < c.mobileEnd ? valid : validMobile);
            k = appendBlockHits(i, X, Y, Z, js, _mm256_castsi256_ps(keep), in, out, k);
        }
    }
    return k;
}

// The pairs of home particles [iBegin, iEnd) of the cell at level iz (0 < iz < levels - 1) with the
// staged candidates of levels iz - 1 to iz + 1; home particles from iMobileEnd on are frozen and meet
// only the mobile candidates.
inline std::size_t appendWindowPairs(const RowStage& st, int iz, std::uint32_t iBegin, std::uint32_t iMobileEnd,
                                     std::uint32_t iEnd, bool split, const PairSearchInput& in,
                                     const PairSearchOutput& out, std::size_t k) {
    const __m256i lanes = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
    const __m256 cellZ = _mm256_set1_ps(in.cellZ);
    const std::uint32_t wBegin = st.levelStart[iz - 1], wEnd = st.levelStart[iz + 2];
    // Entries from levelStart[iz] on are one level up, and from levelStart[iz + 1] on one more.
    const __m256i home = _mm256_set1_epi32(static_cast<int>(st.levelStart[iz]) - 1);
    const __m256i above = _mm256_set1_epi32(static_cast<int>(st.levelStart[iz + 1]) - 1);
    for (std::uint32_t b = wBegin; b < wEnd; b += 8) {
        const __m256i validI = _mm256_cmpgt_epi32(_mm256_set1_epi32(static_cast<int>(wEnd - b)), lanes);
        const __m256 valid = _mm256_castsi256_ps(validI);
        const __m256 validMobile =
            split ? _mm256_and_ps(valid, _mm256_loadu_ps(reinterpret_cast<const float*>(st.mobile.data() + b))) : valid;
        // The level's offset along z: -1, 0 or +1 cell sizes, exactly (the comparisons give -1 per level passed).
        const __m256i entries = _mm256_add_epi32(_mm256_set1_epi32(static_cast<int>(b)), lanes);
        const __m256i up = _mm256_sub_epi32(_mm256_set1_epi32(-1), _mm256_add_epi32(_mm256_cmpgt_epi32(entries, home),
                                                                                     _mm256_cmpgt_epi32(entries, above)));
        const __m256 X = _mm256_loadu_ps(st.x.data() + b), Y = _mm256_loadu_ps(st.y.data() + b);
        const __m256 Z = _mm256_add_ps(_mm256_loadu_ps(st.z.data() + b), _mm256_mul_ps(_mm256_cvtepi32_ps(up), cellZ));
        const __m256i js = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(st.j.data() + b));
        for (std::uint32_t i = iBegin; i < iEnd; ++i)
            k = appendBlockHits(i, X, Y, Z, js, i < iMobileEnd ? valid : validMobile, in, out, k);
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
inline std::uint32_t stageCell(const PairSearchInput& in, std::uint32_t jBegin, std::uint32_t jEnd, std::uint32_t mobileEnd,
                               float offX, float offY, bool split, const StageOutput& st, std::uint32_t s) {
    for (std::uint32_t j = jBegin; j < jEnd; ++j, ++s) {
        st.x[s] = in.x[j] + offX;
        st.y[s] = in.y[j] + offY;
        st.z[s] = in.z[j];
        st.j[s] = j;
        if (split) st.mobile[s] = j < mobileEnd ? -1 : 0;
    }
    return s;
}

inline std::size_t appendHomeColumnPairs(const HomeColumnCells& c, bool split, const PairSearchInput& in,
                                         const PairSearchOutput& out, std::size_t k) {
    for (std::uint32_t block = c.begin; block < c.aboveEnd; block += 8) {
        const std::uint32_t blockEnd = std::min<std::uint32_t>(block + 8, c.aboveEnd);
        for (std::uint32_t i = c.begin; i < c.end; ++i)
            for (std::uint32_t j = std::max(block, i + 1); j < blockEnd; ++j) {
                const bool above = j >= c.end;
                const bool mobile = j < c.mobileEnd || (above && j < c.aboveMobileEnd);
                if (split && i >= c.mobileEnd && !mobile) continue;
                const float dx = in.x[i] - in.x[j];
                const float dy = in.y[i] - in.y[j];
                const float dz = in.z[i] - (in.z[j] + (above ? in.cellZ : 0.0f));
                if (!(squaredDistance(dx, dy, dz) < in.cutoff2)) continue;
                out.i[k] = i; out.j[k] = j; out.dx[k] = dx; out.dy[k] = dy; out.dz[k] = dz;
                ++k;
            }
    }
    return k;
}

inline std::size_t appendWindowPairs(const RowStage& st, int iz, std::uint32_t iBegin, std::uint32_t iMobileEnd,
                                     std::uint32_t iEnd, bool split, const PairSearchInput& in,
                                     const PairSearchOutput& out, std::size_t k) {
    const std::uint32_t wBegin = st.levelStart[iz - 1], wEnd = st.levelStart[iz + 2];
    for (std::uint32_t block = wBegin; block < wEnd; block += 8) {
        const std::uint32_t blockEnd = std::min<std::uint32_t>(block + 8, wEnd);
        for (std::uint32_t i = iBegin; i < iEnd; ++i)
            for (std::uint32_t m = block; m < blockEnd; ++m) {
                if (split && i >= iMobileEnd && !st.mobile[m]) continue;
                const int up = (m >= st.levelStart[iz] ? 1 : 0) + (m >= st.levelStart[iz + 1] ? 1 : 0) - 1;
                const float z = st.z[m] + static_cast<float>(up) * in.cellZ;
                const float dx = in.x[i] - st.x[m];
                const float dy = in.y[i] - st.y[m];
                const float dz = in.z[i] - z;
                if (!(squaredDistance(dx, dy, dz) < in.cutoff2)) continue;
                out.i[k] = i; out.j[k] = st.j[m]; out.dx[k] = dx; out.dy[k] = dy; out.dz[k] = dz;
                ++k;
            }
    }
    return k;
}
#endif

}  // namespace detail
}  // namespace dpd
