#include "sampling/PairVirial.hpp"

#include "forces/DpdPairForce.hpp"
#include "forces/PairForceLoop.hpp"
#include "parallel/RankChains.hpp"
#include "system/System.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace dpd {

namespace {

// Calls add(bin, fraction) for the part [p, q] of a segment lying inside [layout.lo, layout.hi),
// the fraction being overlap x perLength.
template <class Add>
void shareInterval(const BinLayout& L, double p, double q, double perLength, const Add& add) {
    p = std::max(p, L.lo);
    q = std::min(q, L.hi);
    if (!(q > p)) return;
    const double w = L.width();
    const int first = std::max(0, static_cast<int>((p - L.lo) / w));
    const int last = std::min(L.nBins - 1, static_cast<int>((q - L.lo) / w));
    for (int k = first; k <= last; ++k) {
        const double overlap = std::min(q, L.lo + (k + 1) * w) - std::max(p, L.lo + k * w);
        if (overlap > 0.0) add(k, overlap * perLength);
    }
}

// Calls add(bin, fraction) for every bin the segment from a to b (or its periodic images) crosses.
template <class Add>
void forEachSegmentShare(const BinLayout& L, double boxLo, double boxLength, double a, double b, const Add& add) {
    if (a > b) std::swap(a, b);
    const double length = b - a;
    if (length <= 0.0) {
        // Parallel to the bin planes: all of it in the bin holding it (wrapped into the box).
        const int k = L.binOf(a - boxLength * std::floor((a - boxLo) / boxLength));
        if (k >= 0) add(k, 1.0);
        return;
    }
    // The segment and its periodic images: the parts that fall inside the box are what counts.
    const double shift = boxLength * std::floor((a - boxLo) / boxLength);
    for (int image = -1; image <= 1; ++image) {
        const double offset = image * boxLength - shift;
        shareInterval(L, a + offset, b + offset, 1.0 / length, add);
    }
}

// What a traversal reads: particles sorted by `cells` (whose home planes it visits), their pair
// coefficients, the box.
struct VirialScene {
    const Particles& p;
    const CellList& cells;
    const PairTable& pairs;
    const Box& box;
    double cutoff2;
    const std::vector<std::uint8_t>* moved = nullptr;  // by index: pairs with these are left out
    int axis = 0;  // the bins' axis, and the box along it
    double boxLo = 0.0, boxLength = 0.0;
    VirialScene(const Particles& p, const CellList& cells, const PairTable& pairs, const Box& box, double cutoff2,
                const BinLayout& L, const std::vector<std::uint8_t>* moved = nullptr)
        : p(p), cells(cells), pairs(pairs), box(box), cutoff2(cutoff2), moved(moved), axis(L.axis),
          boxLo(box.lo[L.axis]), boxLength(box.length()[L.axis]) {}
};

// One pair's virial r_ij F_ij, shared along its segment (rj the other particle's image nearest ri).
template <class Evaluator>
void addPairVirial(const VirialScene& scene, const BinLayout& L, const Evaluator& eval, std::uint32_t i, std::uint32_t j,
                   const Eigen::Vector3d& ri, const Eigen::Vector3d& rj, std::vector<SymmetricTensor>& bins) {
    const Particles& p = scene.p;
    const Eigen::Vector3d r = ri - rj;
    const double r2 = r.squaredNorm();
    if (r2 >= scene.cutoff2) return;
    const PairCoeffs& c = scene.pairs(p.species[i], p.species[j]);
    if (!c.interact) return;
    const double rDotV = r.x() * (p.vx[i] - p.vx[j]) + r.y() * (p.vy[i] - p.vy[j]) + r.z() * (p.vz[i] - p.vz[j]);
    const double s = eval.forceOverR(r2, rDotV, c, 0.0);  // the evaluator has no random term (see header)
    const SymmetricTensor w{s * r.x() * r.x(), s * r.y() * r.y(), s * r.z() * r.z(),
                            s * r.x() * r.y(), s * r.x() * r.z(), s * r.y() * r.z()};
    forEachSegmentShare(L, scene.boxLo, scene.boxLength, rj[scene.axis], ri[scene.axis], [&](int k, double fraction) {
        for (int m = 0; m < 6; ++m) bins[k][m] += fraction * w[m];
    });
}

// The virial of the pairs of cell a with cell b (particles of b at r_j + image) into `bins`.
template <class Evaluator>
void cellPairVirial(const VirialScene& scene, const BinLayout& L, const Evaluator& eval, std::uint32_t aBegin,
                    std::uint32_t aEnd, std::uint32_t bBegin, std::uint32_t bEnd, bool sameCell,
                    const Eigen::Vector3d& image, std::vector<SymmetricTensor>& bins) {
    const Particles& p = scene.p;
    const std::uint8_t* moved = scene.moved ? scene.moved->data() : nullptr;
    for (std::uint32_t i = aBegin; i < aEnd; ++i) {
        if (moved && moved[i]) continue;
        const Eigen::Vector3d ri(p.rx[i], p.ry[i], p.rz[i]);
        for (std::uint32_t j = sameCell ? i + 1 : bBegin; j < bEnd; ++j) {
            if (moved && moved[j]) continue;
            addPairVirial(scene, L, eval, i, j, ri, Eigen::Vector3d(p.rx[j], p.ry[j], p.rz[j]) + image, bins);
        }
    }
}

// The pairs of the particles that moved after the sort (`movedIndices`, increasing), whose cells no
// longer fit them: with every particle of the (up to 27) cells around where each is now (the others
// lie in the cells the sort gave them), and with each other. The nearest image of each pair.
template <class Evaluator>
void movedPairVirial(const VirialScene& scene, const BinLayout& L, const Evaluator& eval,
                     const std::vector<std::uint32_t>& movedIndices, std::vector<SymmetricTensor>& bins) {
    const Particles& p = scene.p;
    const CellList& cl = scene.cells;
    const auto& n = cl.cellsPerAxis();
    const Box& box = scene.box;
    const auto nearestImage = [&](const Eigen::Vector3d& ri, std::uint32_t j) {
        Eigen::Vector3d rj(p.rx[j], p.ry[j], p.rz[j]);
        for (int a = 0; a < 3; ++a)
            if (box.isActiveAxis(a)) rj[a] += box.length()[a] * std::nearbyint((ri[a] - rj[a]) / box.length()[a]);
        return rj;
    };
    const auto wrappedCell = [](int c, int count) { return ((c % count) + count) % count; };
    // The distinct cells around along each axis: offsets -1..1, or 0..1 where two cells make -1 and
    // +1 the same one (the nearest image then picks the side), or 0 alone along an inactive axis.
    std::array<int, 3> firstOffset{}, lastOffset{};
    for (int a = 0; a < 3; ++a) {
        firstOffset[a] = n[a] > 2 ? -1 : 0;
        lastOffset[a] = n[a] > 1 ? 1 : 0;
    }
    for (std::size_t k = 0; k < movedIndices.size(); ++k) {
        const std::uint32_t i = movedIndices[k];
        const Eigen::Vector3d ri(p.rx[i], p.ry[i], p.rz[i]);
        std::array<int, 3> home{};
        for (int a = 0; a < 3; ++a) home[a] = cl.axisCell(box.wrap(ri[a], a), a);
        for (int dx = firstOffset[0]; dx <= lastOffset[0]; ++dx)
            for (int dy = firstOffset[1]; dy <= lastOffset[1]; ++dy)
                for (int dz = firstOffset[2]; dz <= lastOffset[2]; ++dz) {
                    const int c = cl.cellIndex(wrappedCell(home[0] + dx, n[0]), wrappedCell(home[1] + dy, n[1]),
                                               wrappedCell(home[2] + dz, n[2]));
                    for (std::uint32_t j = cl.cellStart(c); j < cl.cellStart(c + 1); ++j)
                        if (!(*scene.moved)[j]) addPairVirial(scene, L, eval, i, j, ri, nearestImage(ri, j), bins);
                }
        for (std::size_t m = k + 1; m < movedIndices.size(); ++m)
            addPairVirial(scene, L, eval, i, movedIndices[m], ri, nearestImage(ri, movedIndices[m]), bins);
    }
}

template <class Evaluator>
std::vector<SymmetricTensor> traverse(const VirialScene& scene, const BinLayout& L, const Evaluator& eval) {
    const CellList& cl = scene.cells;
    const auto& n = cl.cellsPerAxis();
    const Eigen::Vector3d len = cl.box().length();
    const std::vector<StencilEntry> stencil = halfStencil(cl.box());
    std::vector<std::vector<SymmetricTensor>> perSlab(n[0], std::vector<SymmetricTensor>(L.nBins, SymmetricTensor{}));
#pragma omp parallel for schedule(dynamic, 1)
        for (int ix = 0; ix < n[0]; ++ix)
            for (int iy = 0; iy < n[1] && cl.isHomePlane(ix); ++iy)
                for (int iz = 0; iz < n[2]; ++iz) {
                    const int a = cl.cellIndex(ix, iy, iz);
                    if (cl.cellStart(a) == cl.cellStart(a + 1)) continue;
                    for (const StencilEntry& s : stencil) {
                        int jx = ix + s.dx, jy = iy + s.dy, jz = iz + s.dz;
                        Eigen::Vector3d image(0, 0, 0);
                        if (jx >= n[0]) { jx -= n[0]; image.x() = len.x(); }
                        if (jy >= n[1]) { jy -= n[1]; image.y() = len.y(); } else if (jy < 0) { jy += n[1]; image.y() = -len.y(); }
                        if (jz >= n[2]) { jz -= n[2]; image.z() = len.z(); } else if (jz < 0) { jz += n[2]; image.z() = -len.z(); }
                        const int b = cl.cellIndex(jx, jy, jz);
                        cellPairVirial(scene, L, eval, cl.cellStart(a), cl.cellStart(a + 1), cl.cellStart(b),
                                       cl.cellStart(b + 1), a == b, image, perSlab[ix]);
                    }
                }
    std::vector<SymmetricTensor> total(L.nBins, SymmetricTensor{});
    for (const auto& slab : perSlab)
        for (int k = 0; k < L.nBins; ++k)
            for (int m = 0; m < 6; ++m) total[k][m] += slab[k][m];
    return total;
}

// The virial of the pairs at the system's state. On one rank through its cell list (the particles are
// sorted by it after a step), the few particles a crossing completed at the end of the step moved
// since (System::movedAfterSort) taken apart. In a decomposed run, whose ghosts are gone, through a
// cell list of this rank's particles and the next rank's first plane (`work` holds both), visiting
// this rank's planes only (each pair once over the ranks).
template <class Evaluator>
std::vector<SymmetricTensor> pairVirial(const System& sys, const BinLayout& L, const Evaluator& eval, PairVirialWork& work) {
    const double cutoff2 = sys.forceParameters.cutoff * sys.forceParameters.cutoff;
    if (const SlabDomain* domain = sys.domain()) {
        work.local = domain->withPlaneAbove(sys.particles, sys.cells());
        work.cells.setup(sys.box, sys.forceParameters.cutoff);
        std::vector<std::uint8_t> own(static_cast<std::size_t>(domain->slabs().planes()), 0);
        std::fill(own.begin() + domain->firstPlane(), own.begin() + domain->endPlane(), 1);
        work.cells.setHomePlanes(own);
        work.cells.sortParticles(work.local);
        return traverse(VirialScene(work.local, work.cells, sys.pairs, sys.box, cutoff2, L), L, eval);
    }
    if (!sys.cellsFitPositions()) throw std::logic_error("binnedPairVirial: the particles are not sorted by the system's cells");
    if (sys.movedAfterSort().empty())
        return traverse(VirialScene(sys.particles, sys.cells(), sys.pairs, sys.box, cutoff2, L), L, eval);
    const std::vector<std::uint64_t>& movedIds = sys.movedAfterSort();  // increasing
    const std::vector<std::uint32_t> at = indexById(sys.particles, movedIds.back());
    std::vector<std::uint32_t> movedIndices;
    for (const std::uint64_t id : movedIds) movedIndices.push_back(at[id]);
    std::sort(movedIndices.begin(), movedIndices.end());
    std::vector<std::uint8_t> moved(sys.particles.size(), 0);
    for (const std::uint32_t i : movedIndices) moved[i] = 1;
    const VirialScene scene(sys.particles, sys.cells(), sys.pairs, sys.box, cutoff2, L, &moved);
    std::vector<SymmetricTensor> bins = traverse(scene, L, eval);
    movedPairVirial(scene, L, eval, movedIndices, bins);
    return bins;
}

// The springs' virial: for a bond b = r_second - r_first with F_second = f(b^2) b, the pair's
// r_ij F_ij (i the first) is f b b, shared along the bond's segment like a pair's. In bond order; in a
// decomposed run each rank takes the bonds whose first particle it owns.
void addBondVirial(const System& sys, const BinLayout& L, std::vector<SymmetricTensor>& bins) {
    if (sys.bonds.empty()) return;
    const Bonds& b = sys.bonds.bonds();
    const Particles& p = sys.particles;
    const int axis = L.axis;
    const double boxLo = sys.box.lo[axis], boxLength = sys.box.length()[axis];
    const std::vector<std::uint32_t> ownIndex = sys.domain() ? indexById(p, maxBondedId(b)) : std::vector<std::uint32_t>();
    for (std::size_t k = 0; k < b.size(); ++k) {
        const std::uint32_t first = sys.domain() ? ownIndex[b.first[k]] : sys.bonds.indexOf(b.first[k]);
        if (first == kNotHeld) continue;
        const Eigen::Vector3d v = b.vector(k);
        const double f = sys.bondPotential->forceOverR(v.squaredNorm());
        const SymmetricTensor w{f * v.x() * v.x(), f * v.y() * v.y(), f * v.z() * v.z(),
                                f * v.x() * v.y(), f * v.x() * v.z(), f * v.y() * v.z()};
        const double start = p.position(axis)[first];
        forEachSegmentShare(L, boxLo, boxLength, start, start + v[axis], [&](int bin, double fraction) {
            for (int m = 0; m < 6; ++m) bins[bin][m] += fraction * w[m];
        });
    }
}

}  // namespace

void addSegmentShares(const BinLayout& L, double boxLo, double boxLength, double a, double b, std::vector<double>& share,
                      double weight) {
    forEachSegmentShare(L, boxLo, boxLength, a, b, [&](int k, double fraction) { share[k] += weight * fraction; });
}

std::vector<SymmetricTensor> binnedPairVirial(const System& sys, const BinLayout& layout) {
    PairVirialWork work;
    return binnedPairVirial(sys, layout, work);
}

std::vector<SymmetricTensor> binnedPairVirial(const System& sys, const BinLayout& layout, PairVirialWork& work) {
    std::vector<SymmetricTensor> bins = withDpdWeight(sys.forceParameters, [&](auto weight) {
        const DpdPairTerms<kConservativeTerm | kDissipativeTerm, decltype(weight)> deterministic(weight, sys.forceParameters);
        return pairVirial(sys, layout, deterministic, work);
    });
    addBondVirial(sys, layout, bins);
    return bins;
}

}  // namespace dpd
