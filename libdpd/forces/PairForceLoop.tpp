// Implementation of accumulatePairForces (included by PairForceLoop.hpp).
#include "forces/PairBatch.hpp"
#include "forces/PairForceSums.hpp"
#include "forces/PairGather.hpp"
#include "forces/PairLoopPlan.hpp"
#include "forces/PairSearch.hpp"

#include <algorithm>
#include <cmath>

namespace dpd {
namespace detail {

// The squared cutoff as a float no larger than the double one: a pair the search keeps has
// r^2 < cutoff^2 also when its squared distance is read back in double precision (the weight
// 1 - r/rc stays positive).
inline float cutoff2Below(double cutoff) {
    const double c2 = cutoff * cutoff;
    float f = static_cast<float>(c2);
    if (static_cast<double>(f) > c2) f = std::nextafter(f, 0.0f);
    return f;
}

// A cell index c in [-count, 2 count) brought into [0, count) through the periodic boundary (by
// comparison: a division per cell cost as much as the search itself).
inline int wrapCellIndex(int c, int count) { return c >= count ? c - count : (c < 0 ? c + count : c); }

// A stencil column seen from one row of home cells (ix, iy): its cells are base + jz.
struct RowColumn {
    int base, dzFirst, cells;
    float offX, offY;
};

// The stencil columns of row (ix, iy), wrapped through the periodic boundaries along x and y.
inline void rowColumns(const CellList& cl, const PairInputs& in, const std::vector<StencilColumn>& columns, int ix,
                       int iy, RowColumn* out) {
    const auto& n = cl.cellsPerAxis();
    for (std::size_t k = 0; k < columns.size(); ++k) {
        const StencilColumn& col = columns[k];
        out[k] = {cl.cellIndex(wrapCellIndex(ix + col.dx, n[0]), wrapCellIndex(iy + col.dy, n[1]), 0), col.dzFirst, col.cells,
                  static_cast<float>(col.dx) * in.cellX, static_cast<float>(col.dy) * in.cellY};
    }
}

// Adds to `runs` the candidates of column `col` for the home particles [iBegin, iEnd) of cell
// `home` = (ix, iy, iz): the column's cells in one run while they follow each other in memory (a new
// run where the column wraps through the periodic boundary along z), or, with `mobileOnly`, the
// mobile part of each cell but the home cell, one run each.
inline int addColumnRuns(const CellList& cl, const PairInputs& in, const RowColumn& col, int home, int iz,
                         std::uint32_t iBegin, std::uint32_t iEnd, bool mobileOnly, NeighbourRun* runs, int count) {
    const int nz = cl.cellsPerAxis()[2];
    const int first = iz + col.dzFirst;
    if (!mobileOnly && first >= 0 && first + col.cells <= nz) {
        // Away from the boundary along z (all but two cells of a row): one run, no branches.
        const int c = col.base + first;
        runs[count++] = {cl.cellStart(c), cl.cellStart(c + col.cells), cl.cellStart(c + 1),
                         col.cells == 3 ? cl.cellStart(c + 2) : kNoStep, col.offX, col.offY,
                         static_cast<float>(col.dzFirst) * in.cellZ, iBegin, iEnd, c == home};
        return count;
    }
    NeighbourRun* open = nullptr;  // the run the next cell may extend
    int openCells = 0;
    for (int m = 0; m < col.cells; ++m) {
        const int dz = col.dzFirst + m;
        const int jz = wrapCellIndex(iz + dz, nz);
        const int c = col.base + jz;
        const float offZ = static_cast<float>(dz) * in.cellZ;
        if (mobileOnly) {
            if (c != home && cl.cellStart(c) < cl.mobileEnd(c))
                runs[count++] = {cl.cellStart(c), cl.mobileEnd(c), kNoStep, kNoStep, col.offX, col.offY, offZ, iBegin, iEnd, false};
            continue;
        }
        const std::uint32_t begin = cl.cellStart(c), end = cl.cellStart(c + 1);
        if (open && jz > 0) {  // the cell follows the open run's last one in memory
            (openCells == 1 ? open->zStep1 : open->zStep2) = begin;
            open->jEnd = end;
            ++openCells;
            continue;
        }
        runs[count] = {begin, end, kNoStep, kNoStep, col.offX, col.offY, offZ, iBegin, iEnd, c == home};
        open = &runs[count++];
        openCells = 1;
    }
    return count;
}

// Stages the row's neighbour columns (all but the home column, columns[0]) level by level.
inline void stageRow(const CellList& cl, const PairInputs& in, const PairLoopPlan& plan, const RowColumn* columns,
                     int nColumns, RowStage& stage) {
    const int nz = cl.cellsPerAxis()[2];
    std::size_t count = 0;
    for (int k = 1; k < nColumns; ++k) count += cl.cellStart(columns[k].base + nz) - cl.cellStart(columns[k].base);
    stage.reserve(count, nz);
    const PairSearchInput search{in.x.data(), in.y.data(), in.z.data(), in.cellZ, 0.0f};
    const bool split = plan.skipFrozenPairs;
    const StageOutput out(stage);
    std::uint32_t s = 0;
    for (int c = 0; c < nz; ++c) {
        stage.levelStart[c] = s;
        for (int k = 1; k < nColumns; ++k) {
            const int cell = columns[k].base + c;
            s = stageCell(search, cl.cellStart(cell), cl.cellStart(cell + 1), split ? cl.mobileEnd(cell) : cl.cellStart(cell + 1),
                          columns[k].offX, columns[k].offY, split, out, s);
        }
    }
    stage.levelStart[nz] = s;
}

// The runs of home cell (ix, iy, iz), given its row's columns: its mobile particles (all of them
// unless the plan skips frozen pairs) meet every particle of the half stencil, its frozen ones only
// the mobile particles.
inline int neighbourRuns(const CellList& cl, const PairInputs& in, const PairLoopPlan& plan, const RowColumn* columns,
                         int nColumns, int home, int iz, NeighbourRun* runs) {
    const std::uint32_t aBegin = cl.cellStart(home), aEnd = cl.cellStart(home + 1);
    const std::uint32_t aMobileEnd = plan.skipFrozenPairs ? cl.mobileEnd(home) : aEnd;
    int count = 0;
    if (aBegin < aMobileEnd)
        for (int k = 0; k < nColumns; ++k)
            count = addColumnRuns(cl, in, columns[k], home, iz, aBegin, aMobileEnd, false, runs, count);
    if (aMobileEnd < aEnd)
        for (int k = 0; k < nColumns; ++k)
            count = addColumnRuns(cl, in, columns[k], home, iz, aMobileEnd, aEnd, true, runs, count);
    return count;
}

// Keeps, of the pairs [first, end), those whose species interact; returns the new end.
inline std::size_t dropNonInteracting(const Particles& p, const PairLoopPlan& plan, PairBatch& batch,
                                      std::size_t first, std::size_t end) {
    std::size_t kept = first;
    for (std::size_t k = first; k < end; ++k) {
        if (!plan.interacts[p.species[batch.i[k]] * plan.nSpecies + p.species[batch.j[k]]]) continue;
        batch.i[kept] = batch.i[k]; batch.j[kept] = batch.j[k];
        batch.dx[kept] = batch.dx[k]; batch.dy[kept] = batch.dy[k]; batch.dz[kept] = batch.dz[k];
        ++kept;
    }
    return kept;
}

// Pass 1: the pairs of home cell (ix, iy, iz) closer than the cutoff, appended to the batch
// (PairSearch.hpp). With kFilter the pairs of species that do not interact are dropped again.
template <bool kFilter>
inline void findCellPairs(const Particles& p, const PairInputs& in, const CellList& cl, const PairLoopPlan& plan,
                          const RowColumn* columns, int nColumns, const RowStage& stage, float cutoff2, int home, int iz,
                          PairBatch& batch) {
    const std::uint32_t aBegin = cl.cellStart(home), aEnd = cl.cellStart(home + 1);
    if (aBegin == aEnd) return;
    const int nz = cl.cellsPerAxis()[2];
    // Away from the ends of the column, the home column's two cells directly, the other columns
    // through the row's stage; at the ends (where the window would wrap) every column's runs.
    const bool window = iz > 0 && iz < nz - 1;
    const bool split = plan.skipFrozenPairs;
    const std::uint32_t aMobileEnd = split ? cl.mobileEnd(home) : aEnd;
    // The cell above the home cell ends where the next one starts (read inside the column only).
    const std::uint32_t aboveEnd = window ? cl.cellStart(home + 2) : aEnd;
    NeighbourRun runs[40];
    const int nRuns = window ? 0 : neighbourRuns(cl, in, plan, columns, nColumns, home, iz, runs);
    std::size_t candidates = 0;
    for (int r = 0; r < nRuns; ++r)
        candidates += std::size_t(runs[r].jEnd - runs[r].jBegin) * (runs[r].iEnd - runs[r].iBegin);
    if (window)
        candidates += std::size_t(stage.levelStart[iz + 2] - stage.levelStart[iz - 1] + aboveEnd - aBegin) * (aEnd - aBegin);
    batch.reserveMore(candidates + 8);
    const PairSearchInput search{in.x.data(), in.y.data(), in.z.data(), in.cellZ, cutoff2};
    const PairSearchOutput out{batch.i, batch.j, batch.dx, batch.dy, batch.dz};
    const std::size_t first = batch.size;
    std::size_t k = first;
    for (int r = 0; r < nRuns; ++r) k = appendRunPairs(runs[r], search, out, k);
    if (window) {
        const HomeColumnCells homeColumn{aBegin, aMobileEnd, aEnd, split ? cl.mobileEnd(home + 1) : aboveEnd, aboveEnd};
        k = appendHomeColumnPairs(homeColumn, split, search, out, k);
        k = appendWindowPairs(stage, iz, aBegin, aMobileEnd, aEnd, split, search, out, k);
    }
    if constexpr (kFilter) k = dropNonInteracting(p, plan, batch, first, k);
    batch.size = k;
}

// Pass 2: what the force needs beyond the separation, gathered per pair (relative velocity along
// the separation, the ordered ids, the coefficients when they differ), the random numbers of all the
// pairs at once (eight Philox counters per instruction), then the force over r of every pair in one
// loop over contiguous arrays, which the compiler vectorises.
template <bool kCommon, class Evaluator>
inline void evaluateBatch(const Particles& p, const PairInputs& in, const PairLoopContext& ctx, const PairLoopPlan& plan,
                          const Evaluator& eval, PairBatch& batch) {
    const std::size_t n = batch.size;
    const std::uint8_t* __restrict sp = p.species.data();
    const std::uint32_t* __restrict bi = batch.i;
    const std::uint32_t* __restrict bj = batch.j;
    const float* __restrict bdx = batch.dx;
    const float* __restrict bdy = batch.dy;
    const float* __restrict bdz = batch.dz;
    float* __restrict rDotV = batch.rDotV;
    double* __restrict ca = batch.a;
    double* __restrict cg = batch.gamma;
    double* __restrict cs = batch.sigma;
    constexpr bool kRandom = EvaluatorUsesRandom<Evaluator>::value;
    constexpr bool kVelocity = EvaluatorUsesVelocity<Evaluator>::value;
    // Eight pairs at a time with AVX2 (PairGather.hpp), the rest one by one.
    const PairGatherInput gatherIn{in.kinematics.data(), bi, bj, bdx, bdy, bdz};
    const PairGatherOutput gatherOut{rDotV, batch.idLo, batch.idHi};
    const std::size_t gathered = gatherPairKinematics<kVelocity, kRandom>(gatherIn, gatherOut, n);
    gatherPairKinematicsScalar<kVelocity, kRandom>(gatherIn, gatherOut, gathered, n);
    if constexpr (!kVelocity) std::fill(rDotV, rDotV + n, 0.0f);
    if constexpr (!kCommon)
        for (std::size_t k = 0; k < n; ++k) {
            const PairCoeffs& c = ctx.table(sp[bi[k]], sp[bj[k]]);
            ca[k] = c.a; cg[k] = c.gamma; cs[k] = c.sigma;
        }
    double* __restrict zeta = batch.zeta;
    // The partial evaluators of the split integrators ignore zeta: no Philox for them.
    if constexpr (kRandom) ctx.random.orderedPairUniforms(ctx.step, batch.idLo, batch.idHi, zeta, n);
    else std::fill(zeta, zeta + n, 0.0);
    double* __restrict s = batch.forceOverR;
    const PairCoeffs common = plan.common;
    for (std::size_t k = 0; k < n; ++k) {
        // The search's squared distance to the bit: below the cutoff's square (cutoff2Below).
        const double r2 = squaredDistance(bdx[k], bdy[k], bdz[k]);
        if constexpr (kCommon) {
            s[k] = eval.forceOverR(r2, rDotV[k], common, zeta[k]);
        } else {
            const PairCoeffs c{ca[k], cg[k], cs[k], true};
            s[k] = eval.forceOverR(r2, rDotV[k], c, zeta[k]);
        }
    }
}

// Pass 3: the forces added to the sums of both particles of every pair (PairForceSums.hpp), in the
// order the pairs were found: four pairs' forces made at a time and turned into one (x, y, z, 0)
// vector each; the last pairs of a batch one by one.
inline void scatterBatch(ForceSum* sums, const PairBatch& batch) {
    const std::size_t n = batch.size;
    const std::uint32_t* __restrict bi = batch.i;
    const std::uint32_t* __restrict bj = batch.j;
    const float* __restrict bdx = batch.dx;
    const float* __restrict bdy = batch.dy;
    const float* __restrict bdz = batch.dz;
    const double* __restrict s = batch.forceOverR;
    std::size_t k = 0;
#if defined(__AVX2__)
    const __m256d zero = _mm256_setzero_pd();
    for (; k + 4 <= n; k += 4) {
        const __m256d sk = _mm256_loadu_pd(s + k);
        const __m256d gx = _mm256_mul_pd(sk, _mm256_cvtps_pd(_mm_loadu_ps(bdx + k)));
        const __m256d gy = _mm256_mul_pd(sk, _mm256_cvtps_pd(_mm_loadu_ps(bdy + k)));
        const __m256d gz = _mm256_mul_pd(sk, _mm256_cvtps_pd(_mm_loadu_ps(bdz + k)));
        const __m256d xy02 = _mm256_unpacklo_pd(gx, gy), xy13 = _mm256_unpackhi_pd(gx, gy);
        const __m256d z02 = _mm256_unpacklo_pd(gz, zero), z13 = _mm256_unpackhi_pd(gz, zero);
        const __m256d g[4] = {_mm256_permute2f128_pd(xy02, z02, 0x20), _mm256_permute2f128_pd(xy13, z13, 0x20),
                              _mm256_permute2f128_pd(xy02, z02, 0x31), _mm256_permute2f128_pd(xy13, z13, 0x31)};
        for (int m = 0; m < 4; ++m) {
            double* a = &sums[bi[k + m]].x;
            double* b = &sums[bj[k + m]].x;
            _mm256_store_pd(a, _mm256_add_pd(_mm256_load_pd(a), g[m]));
            _mm256_store_pd(b, _mm256_sub_pd(_mm256_load_pd(b), g[m]));
        }
    }
#endif
    for (; k < n; ++k) {
        const double gx = s[k] * bdx[k], gy = s[k] * bdy[k], gz = s[k] * bdz[k];
        ForceSum& a = sums[bi[k]];
        ForceSum& b = sums[bj[k]];
        a.x += gx; a.y += gy; a.z += gz;
        b.x -= gx; b.y -= gy; b.z -= gz;
    }
}

// The pairs of each row of cells (ix, iy) of slab ix, found into this thread's batch (pass 1), then
// handed to rowDone(batch).
template <class RowDone>
void forEachPairRow(const Particles& p, const PairInputs& in, const CellList& cl, const PairLoopPlan& plan,
                    const std::vector<StencilColumn>& columns, float cutoff2, int ix, const RowDone& rowDone) {
    const auto& n = cl.cellsPerAxis();
    PairBatch& batch = threadPairBatch();
    RowStage& stage = threadRowStage();
    RowColumn row[8];
    const int nColumns = static_cast<int>(columns.size());
    for (int iy = 0; iy < n[1]; ++iy) {
        batch.size = 0;
        rowColumns(cl, in, columns, ix, iy, row);
        stageRow(cl, in, plan, row, nColumns, stage);
        const int rowBase = cl.cellIndex(ix, iy, 0);
        for (int iz = 0; iz < n[2]; ++iz) {
            if (plan.filterInteracting)
                findCellPairs<true>(p, in, cl, plan, row, nColumns, stage, cutoff2, rowBase + iz, iz, batch);
            else
                findCellPairs<false>(p, in, cl, plan, row, nColumns, stage, cutoff2, rowBase + iz, iz, batch);
        }
        rowDone(batch);
    }
}

// slab(ix) for every slab of cells ix, in colours: all even slabs in parallel (excluding the last one
// when nx is odd), then all odd slabs, then the last slab when nx is odd (it writes into slab 0
// through the periodic boundary). Slabs of one colour share no particle.
template <class Slab>
void forEachSlabInColours(int nx, const Slab& slab) {
    const int lastEven = (nx % 2 == 0) ? nx : nx - 1;
    const int first[3] = {0, 1, lastEven};
    const int end[3] = {lastEven, nx, nx};
    for (int colour = 0; colour < 3; ++colour) {
        const int count = (end[colour] - first[colour] + 1) / 2;
#pragma omp parallel for schedule(dynamic, 1)
        for (int k = 0; k < count; ++k) slab(first[colour] + 2 * k);
    }
}

// rowDone(batch) for every row of cells with the row's pairs, rows of one slab in order, slabs in
// colours (the one traversal of the force loop and of the pair sweep): the pair inputs filled (with
// velocities and ids when asked), the cutoff rounded for the single-precision search.
template <class RowDone>
void forEachPairRowInColours(const Particles& p, const CellList& cells, const PairLoopPlan& plan, bool velocities,
                             bool ids, double cutoff, const RowDone& rowDone) {
    const std::vector<StencilColumn> columns = halfStencilColumns(cells.box());
    PairInputs& in = sharedPairInputs();
    fillPairInputs(p, cells, velocities, ids, in);
    const float cutoff2 = cutoff2Below(cutoff);
    forEachSlabInColours(cells.cellsPerAxis()[0], [&](int ix) {
        if (cells.isHomePlane(ix)) forEachPairRow(p, in, cells, plan, columns, cutoff2, ix, rowDone);
    });
}

}  // namespace detail

template <class Evaluator>
void accumulatePairForces(Particles& p, const PairLoopContext& ctx, const Evaluator& eval, double cutoff) {
    const PairLoopPlan plan = makePairLoopPlan(ctx.table, ctx.cells);
    PairInputs& in = sharedPairInputs();
    constexpr bool kVelocity = EvaluatorUsesVelocity<Evaluator>::value;
    constexpr bool kRandom = EvaluatorUsesRandom<Evaluator>::value;
    const bool predict = ctx.predictor.shift != 0.0;
    // The predicted velocities and the ids in one pass before the fill, which then leaves them.
    const bool predictedFill = predict && kVelocity;
    if (predictedFill)
        fillPredictedVelocities(p, ctx.predictor.shift, ctx.predictor.frozenOfSpecies, ctx.predictor.forceOrder, kRandom,
                                in);
    PairForceSums& sums = sharedPairForceSums();
    ForceSum* sum = sums.prepare(p.size());
    const auto rows = [&](auto common) {
        detail::forEachPairRowInColours(p, ctx.cells, plan, kVelocity && !predict, kRandom && !predictedFill, cutoff,
                                        [&](detail::PairBatch& batch) {
                                            detail::evaluateBatch<decltype(common)::value>(p, in, ctx, plan, eval, batch);
                                            detail::scatterBatch(sum, batch);
                                        });
    };
    // The switches pick the loop once per call: a species check per pair only where some pair the
    // layout does not skip is non-interacting (in forEachPairRow), per-pair coefficients only where
    // they differ.
    if (plan.commonCoefficients) rows(std::true_type{});
    else rows(std::false_type{});
    // With a predictor the pair forces replace p.f (which the predicted velocities were made from).
    sums.handTo(p, predict || ctx.replaceForces);
}

}  // namespace dpd
