#include "walls/PlaneShape.hpp"

#include "random/PairRandom.hpp"

#include <algorithm>
#include <cmath>

namespace dpd {

void PlaneShape::markWithin(const Particles& p, long begin, long end, double reach, const std::vector<std::uint8_t>&,
                            std::uint8_t* near) const {
    // Frozen particles are marked too: a species lookup would cost the plane's vectorised test more than it saves.
    const double* rx = p.rx.data() + begin;
    const double* ry = p.ry.data() + begin;
    const double* rz = p.rz.data() + begin;
    for (long k = 0; k < end - begin; ++k) near[k] = signedDistance(rx[k], ry[k], rz[k]) < reach;
}

ShapeCrossing PlaneShape::crossing(const Particles& p, std::size_t i, const Box&, double, SurfaceDistance& atEnd) const {
    const Eigen::Vector3d r(p.rx[i], p.ry[i], p.rz[i]);
    const double depth = signedDistance(p.rx[i], p.ry[i], p.rz[i]);
    atEnd = {depth, normal_};
    if (depth >= 0.0) return {};
    return {true, r - 2.0 * depth * normal_, normal_};
}

Eigen::Vector3d PlaneShape::placed(const Eigen::Vector3d& back, const Box& box) const {
    Eigen::Vector3d r = back;
    for (int a = 0; a < 3; ++a)
        if (box.isActiveAxis(a)) r[a] = box.wrap(r[a], a);
    return r;
}

void PlaneShape::markFlowAxes(const Box&, std::array<bool, 3>& varies) const {
    for (int a = 0; a < 3; ++a)
        if (std::abs(std::abs(normal_[a]) - 1.0) < 1e-12) varies[a] = true;
}

std::uint32_t PlaneShape::reflectionStream() const { return kStreamReflection; }

}  // namespace dpd
