// Implementation of accumulatePairForces (included by PairForceLoop.hpp).
#include "forces/PairBatch.hpp"
#include "forces/PairGather.hpp"
#include "forces/PairLoopPlan.hpp"
#include "forces/PairSearch.hpp"

#include <algorithm>

namespace dpd {
namespace detail {

// A run of neighbour particles [begin, end) standing at r_j + image: consecutive stencil cells that
// are also consecutive in memory (the z neighbours of a row, mostly) make one run.
struct NeighbourRun {
    std::uint32_t begin, end;
    double imageX, imageY, imageZ;
};

// The runs of the half stencil of cell (ix, iy, iz), the cell itself first. For a frozen particle only
// the mobile part of each cell counts (when the plan skips frozen pairs). Returns the number of runs.
inline int neighbourRuns(const CellList& cl, const std::vector<StencilEntry>& stencil, int ix, int iy, int iz,
                         bool mobileOnly, NeighbourRun* runs) {
    const auto& n = cl.cellsPerAxis();
    const Eigen::Vector3d L = cl.box().length();
    int count = 0;
    for (const StencilEntry& s : stencil) {
        int jx = ix + s.dx, jy = iy + s.dy, jz = iz + s.dz;
        // Periodic images: when the neighbour index wraps, its particles stand one box length away.
        double imx = 0.0, imy = 0.0, imz = 0.0;
        if (jx >= n[0]) { jx -= n[0]; imx = L.x(); }
        if (jy >= n[1]) { jy -= n[1]; imy = L.y(); } else if (jy < 0) { jy += n[1]; imy = -L.y(); }
        if (jz >= n[2]) { jz -= n[2]; imz = L.z(); } else if (jz < 0) { jz += n[2]; imz = -L.z(); }
        const int b = cl.cellIndex(jx, jy, jz);
        const std::uint32_t begin = cl.cellStart(b), end = mobileOnly ? cl.mobileEnd(b) : cl.cellStart(b + 1);
        NeighbourRun* last = count > 0 ? &runs[count - 1] : nullptr;
        if (last && last->end == begin && last->imageX == imx && last->imageY == imy && last->imageZ == imz)
            last->end = end;
        else
            runs[count++] = {begin, end, imx, imy, imz};
    }
    return count;
}

// Keeps, of the pairs [first, end) of particle i, those whose species interact; returns the new end.
inline std::size_t dropNonInteracting(const Particles& p, const PairLoopPlan& plan, PairBatch& batch,
                                      std::size_t first, std::size_t end) {
    if (first == end) return end;
    const std::uint8_t* interactsI = &plan.interacts[p.species[batch.i[first]] * plan.nSpecies];
    std::size_t kept = first;
    for (std::size_t k = first; k < end; ++k) {
        if (!interactsI[p.species[batch.j[k]]]) continue;
        batch.j[kept] = batch.j[k];
        batch.dx[kept] = batch.dx[k]; batch.dy[kept] = batch.dy[k]; batch.dz[kept] = batch.dz[k];
        ++kept;
    }
    return kept;
}

// Pass 1: the pairs (i in cell a, j in its half stencil) closer than the cutoff, appended to the
// batch (PairSearch.hpp). With kFilter the pairs of species that do not interact are dropped again.
template <bool kFilter>
inline void findCellPairs(const Particles& p, const CellList& cl, const PairLoopPlan& plan,
                          const std::vector<StencilEntry>& stencil, double cutoff2, int ix, int iy, int iz,
                          PairBatch& batch) {
    const int a = cl.cellIndex(ix, iy, iz);
    const std::uint32_t aBegin = cl.cellStart(a), aEnd = cl.cellStart(a + 1);
    if (aBegin == aEnd) return;
    const std::uint32_t aMobileEnd = plan.skipFrozenPairs ? cl.mobileEnd(a) : aEnd;
    NeighbourRun all[32], mobile[32];
    const int nAll = neighbourRuns(cl, stencil, ix, iy, iz, false, all);
    const int nMobile = aMobileEnd < aEnd ? neighbourRuns(cl, stencil, ix, iy, iz, true, mobile) : 0;
    std::size_t candidates = 0;
    for (int r = 0; r < nAll; ++r) candidates += all[r].end - all[r].begin;
    batch.reserveMore(candidates * (aEnd - aBegin) + 3);

    const double* rx = p.rx.data();
    const double* ry = p.ry.data();
    const double* rz = p.rz.data();
    const PairSearchOutput out{batch.i.data(), batch.j.data(), batch.dx.data(), batch.dy.data(), batch.dz.data()};
    std::size_t k = batch.size;
    for (std::uint32_t i = aBegin; i < aEnd; ++i) {
        const bool frozenI = i >= aMobileEnd;
        const NeighbourRun* runs = frozenI ? mobile : all;
        const int nRuns = frozenI ? nMobile : nAll;
        const std::size_t first = k;
        for (int r = 0; r < nRuns; ++r) {
            const NeighbourRun& run = runs[r];
            // The first run starts with cell a itself: only the partners after i.
            const std::uint32_t jBegin = r == 0 ? std::max(run.begin, i + 1) : run.begin;
            k = appendPairsWithinCutoff(i, rx[i] - run.imageX, ry[i] - run.imageY, rz[i] - run.imageZ, jBegin,
                                        run.end, rx, ry, rz, cutoff2, out, k);
        }
        if constexpr (kFilter) k = dropNonInteracting(p, plan, batch, first, k);
    }
    batch.size = k;
}

// Pass 2: what the force needs beyond the separation, gathered per pair (relative velocity along
// the separation, the ordered ids, the coefficients when they differ), the random numbers of all the
// pairs at once (eight Philox counters per instruction), then the force over r of every pair in one
// loop over contiguous arrays, which the compiler vectorises.
template <bool kCommon, class Evaluator>
inline void evaluateBatch(const Particles& p, const PairLoopContext& ctx, const PairLoopPlan& plan,
                          const Evaluator& eval, PairBatch& batch) {
    const std::size_t n = batch.size;
    const double* __restrict vx = p.vx.data();
    const double* __restrict vy = p.vy.data();
    const double* __restrict vz = p.vz.data();
    const std::uint64_t* __restrict id = p.id.data();
    const std::uint8_t* __restrict sp = p.species.data();
    const std::uint32_t* __restrict bi = batch.i.data();
    const std::uint32_t* __restrict bj = batch.j.data();
    const double* __restrict bdx = batch.dx.data();
    const double* __restrict bdy = batch.dy.data();
    const double* __restrict bdz = batch.dz.data();
    double* __restrict rDotV = batch.rDotV.data();
    std::uint32_t* __restrict idLo = batch.idLo.data();
    std::uint32_t* __restrict idHi = batch.idHi.data();
    double* __restrict ca = batch.a.data();
    double* __restrict cg = batch.gamma.data();
    double* __restrict cs = batch.sigma.data();
    constexpr bool kRandom = EvaluatorUsesRandom<Evaluator>::value;
    constexpr bool kVelocity = EvaluatorUsesVelocity<Evaluator>::value;
    // Four pairs at a time with AVX2 gathers (PairGather.hpp), the rest here.
    const std::size_t gathered = gatherPairKinematics<kVelocity, kRandom>(
        {vx, vy, vz, id, bi, bj, bdx, bdy, bdz}, {rDotV, idLo, idHi}, n);
    for (std::size_t k = gathered; k < n; ++k) {
        const std::uint32_t i = bi[k], j = bj[k];
        if constexpr (kVelocity)
            rDotV[k] = separationDotRelativeVelocity(bdx[k], bdy[k], bdz[k], vx[i] - vx[j], vy[i] - vy[j], vz[i] - vz[j]);
        if constexpr (kRandom) {
            const std::uint64_t lo = std::min(id[i], id[j]), hi = std::max(id[i], id[j]);
            idLo[k] = static_cast<std::uint32_t>(lo);
            idHi[k] = static_cast<std::uint32_t>(hi);
        }
    }
    if constexpr (!kVelocity) std::fill(rDotV, rDotV + n, 0.0);
    if constexpr (!kCommon)
        for (std::size_t k = 0; k < n; ++k) {
            const PairCoeffs& c = ctx.table(sp[bi[k]], sp[bj[k]]);
            ca[k] = c.a; cg[k] = c.gamma; cs[k] = c.sigma;
        }
    double* __restrict zeta = batch.zeta.data();
    // The partial evaluators of the split integrators ignore zeta: no Philox for them.
    if constexpr (kRandom) ctx.random.orderedPairUniforms(ctx.step, idLo, idHi, zeta, n);
    else std::fill(zeta, zeta + n, 0.0);
    double* __restrict s = batch.forceOverR.data();
    const PairCoeffs common = plan.common;
    for (std::size_t k = 0; k < n; ++k) {
        const double r2 = bdx[k] * bdx[k] + bdy[k] * bdy[k] + bdz[k] * bdz[k];
        if constexpr (kCommon) {
            s[k] = eval.forceOverR(r2, rDotV[k], common, zeta[k]);
        } else {
            const PairCoeffs c{ca[k], cg[k], cs[k], true};
            s[k] = eval.forceOverR(r2, rDotV[k], c, zeta[k]);
        }
    }
}

// Pass 3: the forces added to both particles of every pair, in the order the pairs were found. The
// pairs of one particle i come together, so its share is summed in registers and stored once per run.
inline void scatterBatch(Particles& p, const PairBatch& batch) {
    const std::size_t n = batch.size;
    if (n == 0) return;
    double* __restrict fx = p.fx.data();
    double* __restrict fy = p.fy.data();
    double* __restrict fz = p.fz.data();
    const std::uint32_t* __restrict bi = batch.i.data();
    const std::uint32_t* __restrict bj = batch.j.data();
    const double* __restrict bdx = batch.dx.data();
    const double* __restrict bdy = batch.dy.data();
    const double* __restrict bdz = batch.dz.data();
    const double* __restrict s = batch.forceOverR.data();
    std::uint32_t current = bi[0];
    double fxi = 0.0, fyi = 0.0, fzi = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
        if (bi[k] != current) {
            fx[current] += fxi; fy[current] += fyi; fz[current] += fzi;
            fxi = fyi = fzi = 0.0;
            current = bi[k];
        }
        const double gx = s[k] * bdx[k], gy = s[k] * bdy[k], gz = s[k] * bdz[k];
        fxi += gx; fyi += gy; fzi += gz;
        const std::uint32_t j = bj[k];
        fx[j] -= gx; fy[j] -= gy; fz[j] -= gz;
    }
    fx[current] += fxi; fy[current] += fyi; fz[current] += fzi;
}

// The pairs of each row of cells (ix, iy) of slab ix, found into this thread's batch (pass 1), then
// handed to rowDone(batch).
template <class RowDone>
void forEachPairRow(const Particles& p, const CellList& cl, const PairLoopPlan& plan,
                    const std::vector<StencilEntry>& stencil, double cutoff2, int ix, const RowDone& rowDone) {
    const auto& n = cl.cellsPerAxis();
    PairBatch& batch = threadPairBatch();
    for (int iy = 0; iy < n[1]; ++iy) {
        batch.size = 0;
        for (int iz = 0; iz < n[2]; ++iz) {
            if (plan.filterInteracting) findCellPairs<true>(p, cl, plan, stencil, cutoff2, ix, iy, iz, batch);
            else findCellPairs<false>(p, cl, plan, stencil, cutoff2, ix, iy, iz, batch);
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

template <bool kCommon, class Evaluator>
void colouredSlabs(Particles& p, const PairLoopContext& ctx, const PairLoopPlan& plan, const Evaluator& eval,
                   double cutoff2, const std::vector<StencilEntry>& stencil) {
    forEachSlabInColours(ctx.cells.cellsPerAxis()[0], [&](int ix) {
        forEachPairRow(p, ctx.cells, plan, stencil, cutoff2, ix, [&](PairBatch& batch) {
            evaluateBatch<kCommon>(p, ctx, plan, eval, batch);
            scatterBatch(p, batch);
        });
    });
}

}  // namespace detail

template <class Evaluator>
void accumulatePairForces(Particles& p, const PairLoopContext& ctx, const Evaluator& eval, double cutoff) {
    const std::vector<StencilEntry> stencil = halfStencil(ctx.cells.box());
    const PairLoopPlan plan = makePairLoopPlan(ctx.table, ctx.cells);
    const double cutoff2 = cutoff * cutoff;
    // The switches pick the loop once per call: a species check per candidate only where some pair
    // the layout does not skip is non-interacting (in forEachPairRow), per-pair coefficients only
    // where they differ.
    if (plan.commonCoefficients) detail::colouredSlabs<true>(p, ctx, plan, eval, cutoff2, stencil);
    else detail::colouredSlabs<false>(p, ctx, plan, eval, cutoff2, stencil);
}

}  // namespace dpd
