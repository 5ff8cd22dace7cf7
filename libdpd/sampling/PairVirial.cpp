#include "sampling/PairVirial.hpp"

#include "forces/DpdPairForce.hpp"
#include "forces/PairForceLoop.hpp"
#include "system/System.hpp"

#include <algorithm>
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

// The virial of the pairs of cell a with cell b (particles of b at r_j + image) into `bins`.
template <class Evaluator>
void cellPairVirial(const System& sys, const BinLayout& L, const Evaluator& eval, double cutoff2, std::uint32_t aBegin,
                    std::uint32_t aEnd, std::uint32_t bBegin, std::uint32_t bEnd, bool sameCell,
                    const Eigen::Vector3d& image, std::vector<SymmetricTensor>& bins) {
    const Particles& p = sys.particles;
    const int axis = L.axis;
    const double boxLo = sys.box.lo[axis], boxLength = sys.box.length()[axis];
    for (std::uint32_t i = aBegin; i < aEnd; ++i) {
        const Eigen::Vector3d ri(p.rx[i], p.ry[i], p.rz[i]);
        for (std::uint32_t j = sameCell ? i + 1 : bBegin; j < bEnd; ++j) {
            const Eigen::Vector3d rj = Eigen::Vector3d(p.rx[j], p.ry[j], p.rz[j]) + image;
            const Eigen::Vector3d r = ri - rj;
            const double r2 = r.squaredNorm();
            if (r2 >= cutoff2) continue;
            const PairCoeffs& c = sys.pairs(p.species[i], p.species[j]);
            if (!c.interact) continue;
            const double rDotV = r.x() * (p.vx[i] - p.vx[j]) + r.y() * (p.vy[i] - p.vy[j]) + r.z() * (p.vz[i] - p.vz[j]);
            const double s = eval.forceOverR(r2, rDotV, c, 0.0);  // the evaluator has no random term (see header)
            const SymmetricTensor w{s * r.x() * r.x(), s * r.y() * r.y(), s * r.z() * r.z(),
                                    s * r.x() * r.y(), s * r.x() * r.z(), s * r.y() * r.z()};
            forEachSegmentShare(L, boxLo, boxLength, rj[axis], ri[axis], [&](int k, double fraction) {
                for (int m = 0; m < 6; ++m) bins[k][m] += fraction * w[m];
            });
        }
    }
}

template <class Evaluator>
std::vector<SymmetricTensor> traverse(const System& sys, const BinLayout& L, const Evaluator& eval) {
    const CellList& cl = sys.cells();
    const auto& n = cl.cellsPerAxis();
    const Eigen::Vector3d len = cl.box().length();
    const std::vector<StencilEntry> stencil = halfStencil(cl.box());
    const double cutoff2 = sys.forceParameters.cutoff * sys.forceParameters.cutoff;
    std::vector<std::vector<SymmetricTensor>> perSlab(n[0], std::vector<SymmetricTensor>(L.nBins, SymmetricTensor{}));
#pragma omp parallel for schedule(dynamic, 1)
        for (int ix = 0; ix < n[0]; ++ix)
            for (int iy = 0; iy < n[1]; ++iy)
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
                        cellPairVirial(sys, L, eval, cutoff2, cl.cellStart(a), cl.cellStart(a + 1), cl.cellStart(b),
                                       cl.cellStart(b + 1), a == b, image, perSlab[ix]);
                    }
                }
    std::vector<SymmetricTensor> total(L.nBins, SymmetricTensor{});
    for (const auto& slab : perSlab)
        for (int k = 0; k < L.nBins; ++k)
            for (int m = 0; m < 6; ++m) total[k][m] += slab[k][m];
    return total;
}

// The springs' virial: for a bond b = r_second - r_first with F_second = f(b^2) b, the pair's
// r_ij F_ij (i the first) is f b b, shared along the bond's segment like a pair's. In bond order.
void addBondVirial(const System& sys, const BinLayout& L, std::vector<SymmetricTensor>& bins) {
    if (sys.bonds.empty()) return;
    if (!sys.bondedPairs.keepsAll())
        throw std::logic_error("the stress with bondedPairs other than dpd all is not sampled: the pair virial would count the left-out terms");
    const Bonds& b = sys.bonds.bonds();
    const Particles& p = sys.particles;
    const int axis = L.axis;
    const double boxLo = sys.box.lo[axis], boxLength = sys.box.length()[axis];
    for (std::size_t k = 0; k < b.size(); ++k) {
        const Eigen::Vector3d v = b.vector(k);
        const double f = sys.bondPotential->forceOverR(v.squaredNorm());
        const SymmetricTensor w{f * v.x() * v.x(), f * v.y() * v.y(), f * v.z() * v.z(),
                                f * v.x() * v.y(), f * v.x() * v.z(), f * v.y() * v.z()};
        const std::uint32_t first = sys.bonds.indexOf(b.first[k]);
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
    std::vector<SymmetricTensor> bins = withDpdWeight(sys.forceParameters, [&](auto weight) {
        const DpdPairTerms<kConservativeTerm | kDissipativeTerm, decltype(weight)> deterministic(weight, sys.forceParameters);
        return traverse(sys, layout, deterministic);
    });
    addBondVirial(sys, layout, bins);
    return bins;
}

}  // namespace dpd
