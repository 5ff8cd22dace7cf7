#include "geometry/SignedDistanceField.hpp"

#include <cmath>

namespace dpd {

SignedDistanceField::SignedDistanceField(const SolidGeometry& geometry, const BackgroundGrid& grid, double band)
    : grid_(grid), band_(band), nodes_(grid_.size()) {
    const auto cells = static_cast<long>(grid_.size());
#pragma omp parallel for schedule(dynamic, 256)
    for (long c = 0; c < cells; ++c) {
        const auto ijk = grid_.cellIndices(static_cast<std::size_t>(c));
        const SurfaceDistance s = geometry.signedDistance(grid_.centre(ijk[0], ijk[1], ijk[2]), band_);
        nodes_[c] = {static_cast<float>(s.distance),
                     {static_cast<float>(s.normal.x()), static_cast<float>(s.normal.y()), static_cast<float>(s.normal.z())}};
    }
}

SurfaceDistance SignedDistanceField::at(const Eigen::Vector3d& r) const {
    // Linear weights between the two cell centres that bracket r along each varying axis.
    int i0[3], i1[3];
    double t[3];
    for (int a = 0; a < 3; ++a) {
        if (grid_.n[a] == 1) {
            i0[a] = i1[a] = 0;
            t[a] = 0.0;
            continue;
        }
        const double u = (r[a] - grid_.lo[a]) / grid_.spacing[a] - 0.5;
        const double f = std::floor(u);
        t[a] = u - f;
        i0[a] = BackgroundGrid::wrapIndex(static_cast<int>(f), grid_.n[a]);
        i1[a] = i0[a] + 1 == grid_.n[a] ? 0 : i0[a] + 1;
    }
    double d = 0.0;
    Eigen::Vector3d n(0, 0, 0);
    for (int corner = 0; corner < 8; ++corner) {
        const int cx = corner & 1, cy = (corner >> 1) & 1, cz = (corner >> 2) & 1;
        const double w = (cx ? t[0] : 1.0 - t[0]) * (cy ? t[1] : 1.0 - t[1]) * (cz ? t[2] : 1.0 - t[2]);
        if (w == 0.0) continue;
        const Node& node = nodes_[grid_.index(cx ? i1[0] : i0[0], cy ? i1[1] : i0[1], cz ? i1[2] : i0[2])];
        d += w * node.distance;
        n += w * Eigen::Vector3d(node.normal[0], node.normal[1], node.normal[2]);
    }
    const double norm = n.norm();
    return {d, norm > 0.0 ? Eigen::Vector3d(n / norm) : Eigen::Vector3d::Zero()};
}

}  // namespace dpd
