#include "sampling/ChainShapes.hpp"

#include <stdexcept>
#include <string>

namespace dpd {

namespace {

ChainShape shapeOf(const ChainBonds& chains, std::size_t c, const Eigen::Vector3d& head, const Box& box) {
    const Bonds& b = chains.bonds();
    // Bead positions relative to the first bead: the sums of the bond vectors along the chain.
    std::vector<Eigen::Vector3d> r{Eigen::Vector3d::Zero()};
    ChainShape s;
    for (std::size_t k = chains.chainBegin(c); k < chains.chainEnd(c); ++k) {
        if (k > chains.chainBegin(c) && b.first[k] != b.second[k - 1])
            throw std::invalid_argument("chain " + std::to_string(b.chain[k]) + " is not a linear chain in order");
        r.push_back(r.back() + b.vector(k));
        s.bondLength2 += b.vector(k).squaredNorm();
    }
    s.beads = static_cast<long>(r.size());
    s.bondLength2 /= static_cast<double>(r.size() - 1);
    s.endToEnd = r.back();
    Eigen::Vector3d mean = Eigen::Vector3d::Zero(), lo = r[0], hi = r[0];
    for (const Eigen::Vector3d& x : r) {
        mean += x;
        lo = lo.cwiseMin(x);
        hi = hi.cwiseMax(x);
    }
    mean /= static_cast<double>(r.size());
    for (const Eigen::Vector3d& x : r) s.gyration2 += (x - mean).squaredNorm();
    s.gyration2 /= static_cast<double>(r.size());
    s.span = hi - lo;
    s.centre = head + mean;
    box.wrapPoint(s.centre.x(), s.centre.y(), s.centre.z());
    return s;
}

}  // namespace

std::vector<ChainShape> chainShapes(const ChainBonds& chains, const std::vector<Eigen::Vector3d>& heads, const Box& box) {
    if (heads.size() != chains.chainCount()) throw std::invalid_argument("chainShapes: a head for each chain");
    std::vector<ChainShape> shapes;
    shapes.reserve(chains.chainCount());
    for (std::size_t c = 0; c < chains.chainCount(); ++c) shapes.push_back(shapeOf(chains, c, heads[c], box));
    return shapes;
}

std::vector<ChainShape> chainShapes(const ChainBonds& chains, const Particles& p, const Box& box) {
    std::vector<Eigen::Vector3d> heads;
    heads.reserve(chains.chainCount());
    for (const std::uint64_t id : chainHeadIds(chains)) {
        const std::uint32_t i = chains.indexOf(id);
        heads.emplace_back(p.rx[i], p.ry[i], p.rz[i]);
    }
    return chainShapes(chains, heads, box);
}

std::vector<std::uint64_t> chainHeadIds(const ChainBonds& chains) {
    std::vector<std::uint64_t> ids;
    ids.reserve(chains.chainCount());
    for (std::size_t c = 0; c < chains.chainCount(); ++c) ids.push_back(chains.bonds().first[chains.chainBegin(c)]);
    return ids;
}

}  // namespace dpd
