// Implementation of accumulatePairForces (included by PairForceLoop.hpp).
#include <omp.h>

namespace dpd {
namespace detail {

// All pairs between the particles of cell a and cell b, whose particles stand at r_j + image.
template <class Evaluator>
inline void cellPairForces(Particles& p, const PairLoopContext& ctx, const Evaluator& eval, double cutoff2,
                           std::uint32_t aBegin, std::uint32_t aEnd, std::uint32_t bBegin, std::uint32_t bEnd,
                           bool sameCell, const Eigen::Vector3d& image) {
    const double* __restrict rx = p.rx.data();
    const double* __restrict ry = p.ry.data();
    const double* __restrict rz = p.rz.data();
    const double* __restrict vx = p.vx.data();
    const double* __restrict vy = p.vy.data();
    const double* __restrict vz = p.vz.data();
    double* __restrict fx = p.fx.data();
    double* __restrict fy = p.fy.data();
    double* __restrict fz = p.fz.data();
    const std::uint64_t* __restrict id = p.id.data();
    const std::uint8_t* __restrict sp = p.species.data();
    for (std::uint32_t i = aBegin; i < aEnd; ++i) {
        const double xi = rx[i] - image.x(), yi = ry[i] - image.y(), zi = rz[i] - image.z();
        double fxi = 0.0, fyi = 0.0, fzi = 0.0;
        const PairCoeffs* row = &ctx.table(sp[i], 0);
        for (std::uint32_t j = sameCell ? i + 1 : bBegin; j < bEnd; ++j) {
            const double dx = xi - rx[j], dy = yi - ry[j], dz = zi - rz[j];
            const double r2 = dx * dx + dy * dy + dz * dz;
            if (r2 >= cutoff2) continue;
            const PairCoeffs& c = row[sp[j]];
            if (!c.interact) continue;  // frozen-frozen pairs, for example
            const double rDotV = dx * (vx[i] - vx[j]) + dy * (vy[i] - vy[j]) + dz * (vz[i] - vz[j]);
            const double zeta = ctx.random.pairUniform(ctx.step, id[i], id[j]);
            const double s = eval.forceOverR(r2, rDotV, c, zeta);
            fxi += s * dx; fyi += s * dy; fzi += s * dz;
            fx[j] -= s * dx; fy[j] -= s * dy; fz[j] -= s * dz;
        }
        fx[i] += fxi; fy[i] += fyi; fz[i] += fzi;
    }
}

template <class Evaluator>
void slabPairForces(Particles& p, const PairLoopContext& ctx, const Evaluator& eval, double cutoff2, int ix,
                    const std::vector<StencilEntry>& stencil) {
    const CellList& cl = ctx.cells;
    const auto& n = cl.cellsPerAxis();
    const Eigen::Vector3d L = cl.box().length();
    for (int iy = 0; iy < n[1]; ++iy)
        for (int iz = 0; iz < n[2]; ++iz) {
            const int a = cl.cellIndex(ix, iy, iz);
            const std::uint32_t aBegin = cl.cellStart(a), aEnd = cl.cellStart(a + 1);
            if (aBegin == aEnd) continue;
            for (const StencilEntry& s : stencil) {
                int jx = ix + s.dx, jy = iy + s.dy, jz = iz + s.dz;
                // Periodic images: when the neighbour index wraps, its particles stand one box
                // length away, r_j + image.
                Eigen::Vector3d image(0, 0, 0);
                if (jx >= n[0]) { jx -= n[0]; image.x() = L.x(); }
                if (jy >= n[1]) { jy -= n[1]; image.y() = L.y(); } else if (jy < 0) { jy += n[1]; image.y() = -L.y(); }
                if (jz >= n[2]) { jz -= n[2]; image.z() = L.z(); } else if (jz < 0) { jz += n[2]; image.z() = -L.z(); }
                const int b = cl.cellIndex(jx, jy, jz);
                cellPairForces(p, ctx, eval, cutoff2, aBegin, aEnd, cl.cellStart(b), cl.cellStart(b + 1), b == a,
                               image);
            }
        }
}

}  // namespace detail

template <class Evaluator>
void accumulatePairForces(Particles& p, const PairLoopContext& ctx, const Evaluator& eval, double cutoff) {
    const std::vector<StencilEntry> stencil = halfStencil(ctx.cells.box());
    const int nx = ctx.cells.cellsPerAxis()[0];
    const double cutoff2 = cutoff * cutoff;
    // Colour 0: even slabs (excluding the last one when nx is odd), colour 1: odd slabs, colour 2:
    // the last slab when nx is odd (it writes into slab 0 through the periodic boundary).
    const int lastEven = (nx % 2 == 0) ? nx : nx - 1;
    for (int colour = 0; colour < 3; ++colour) {
        std::vector<int> slabs;
        if (colour == 0) for (int ix = 0; ix < lastEven; ix += 2) slabs.push_back(ix);
        if (colour == 1) for (int ix = 1; ix < nx; ix += 2) slabs.push_back(ix);
        if (colour == 2 && nx % 2 == 1) slabs.push_back(nx - 1);
        const int count = static_cast<int>(slabs.size());
#pragma omp parallel for schedule(dynamic, 1)
        for (int k = 0; k < count; ++k) detail::slabPairForces(p, ctx, eval, cutoff2, slabs[k], stencil);
    }
}

}  // namespace dpd
