#pragma once
// A sweep over all pairs within the cutoff that may change both particles of a pair as it goes, so
// that each pair sees what the pairs before it did (Shardlow's splitting). The result depends on the
// order, so the order is fixed by the cell layout alone, whatever the number of threads:
//
// - the pairs of a slab of cells (constant x index ix) are those of its cells with their half-stencil
//   neighbours (forces/PairForceLoop.hpp), visited cell by cell (y, then z), stencil entry by stencil
//   entry, particle by particle; they touch particles of slabs ix and ix + 1 only;
// - slabs are swept in colours as the force loop does: all even slabs (the last one excluded when the
//   count is odd), then all odd slabs, then the last slab when the count is odd. Two slabs of one
//   colour share no particle, so sweeping them at the same time on different threads gives exactly
//   what sweeping them one after the other would.
#include "forces/PairForceLoop.hpp"
#include "neighbour/CellList.hpp"

#include <cstdint>
#include <vector>

namespace dpd {

namespace detail {

// visit(i, j, dx, dy, dz, r2) for every pair of slab ix within the cutoff, r_i - r_j = (dx, dy, dz).
template <class Visit>
void sweepSlab(const Particles& p, const CellList& cl, const std::vector<StencilEntry>& stencil, double cutoff2,
               int ix, const Visit& visit) {
    const auto& n = cl.cellsPerAxis();
    const Eigen::Vector3d L = cl.box().length();
    for (int iy = 0; iy < n[1]; ++iy)
        for (int iz = 0; iz < n[2]; ++iz) {
            const int a = cl.cellIndex(ix, iy, iz);
            const std::uint32_t aBegin = cl.cellStart(a), aEnd = cl.cellStart(a + 1);
            if (aBegin == aEnd) continue;
            for (const StencilEntry& s : stencil) {
                int jx = ix + s.dx, jy = iy + s.dy, jz = iz + s.dz;
                // A neighbour index that wraps stands one box length away.
                Eigen::Vector3d image(0, 0, 0);
                if (jx >= n[0]) { jx -= n[0]; image.x() = L.x(); }
                if (jy >= n[1]) { jy -= n[1]; image.y() = L.y(); } else if (jy < 0) { jy += n[1]; image.y() = -L.y(); }
                if (jz >= n[2]) { jz -= n[2]; image.z() = L.z(); } else if (jz < 0) { jz += n[2]; image.z() = -L.z(); }
                const int b = cl.cellIndex(jx, jy, jz);
                const std::uint32_t bEnd = cl.cellStart(b + 1);
                for (std::uint32_t i = aBegin; i < aEnd; ++i) {
                    const double xi = p.rx[i] - image.x(), yi = p.ry[i] - image.y(), zi = p.rz[i] - image.z();
                    for (std::uint32_t j = b == a ? i + 1 : cl.cellStart(b); j < bEnd; ++j) {
                        const double dx = xi - p.rx[j], dy = yi - p.ry[j], dz = zi - p.rz[j];
                        const double r2 = dx * dx + dy * dy + dz * dz;
                        if (r2 < cutoff2) visit(i, j, dx, dy, dz, r2);
                    }
                }
            }
        }
}

}  // namespace detail

// Calls visit(i, j, dx, dy, dz, r2) once for every pair closer than the cutoff, in the fixed order
// above; `visit` may change the velocities of i and j (never positions: the cell list must stay valid).
template <class Visit>
void sweepPairs(const Particles& p, const CellList& cells, double cutoff, const Visit& visit) {
    const std::vector<StencilEntry> stencil = halfStencil(cells.box());
    const int nx = cells.cellsPerAxis()[0];
    const double cutoff2 = cutoff * cutoff;
    const int lastEven = (nx % 2 == 0) ? nx : nx - 1;
    for (int colour = 0; colour < 3; ++colour) {
        std::vector<int> slabs;
        if (colour == 0) for (int ix = 0; ix < lastEven; ix += 2) slabs.push_back(ix);
        if (colour == 1) for (int ix = 1; ix < nx; ix += 2) slabs.push_back(ix);
        if (colour == 2 && nx % 2 == 1) slabs.push_back(nx - 1);
        const int count = static_cast<int>(slabs.size());
#pragma omp parallel for schedule(dynamic, 1)
        for (int k = 0; k < count; ++k) detail::sweepSlab(p, cells, stencil, cutoff2, slabs[k], visit);
    }
}

}  // namespace dpd
