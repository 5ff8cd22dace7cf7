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
    smoothNormals();
}

Eigen::Vector3d SignedDistanceField::distanceGradient(const std::array<int, 3>& ijk, bool& reliable) const {
    Eigen::Vector3d g(0, 0, 0);
    reliable = true;
    for (int a = 0; a < 3; ++a) {
        if (grid_.n[a] < 3) continue;
        std::array<int, 3> lo = ijk, hi = ijk;
        lo[a] = BackgroundGrid::wrapIndex(ijk[a] - 1, grid_.n[a]);
        hi[a] = BackgroundGrid::wrapIndex(ijk[a] + 1, grid_.n[a]);
        const double dLo = nodes_[grid_.index(lo[0], lo[1], lo[2])].distance;
        const double dHi = nodes_[grid_.index(hi[0], hi[1], hi[2])].distance;
        // A neighbour clipped to the band has lost its slope: the difference would be too small.
        if (std::abs(dLo) >= band_ || std::abs(dHi) >= band_) reliable = false;
        g[a] = (dHi - dLo) / (2.0 * grid_.spacing[a]);
    }
    return g;
}

void SignedDistanceField::smoothNormals() {
    // The nearest-point normal of a staircase contour (an image mask) tilts with every pixel step
    // (up to ~14 degrees); the central-difference gradient of the distance over two cells averages
    // those steps out. Where the difference is unreliable -- a neighbour clipped to the band, or a
    // ridge of the distance (the middle of a channel, the inside of a thin solid), where the slopes
    // on either side cancel and the gradient's length falls well below 1 or turns against the
    // nearest-point normal -- the nearest-point normal is kept.
    std::vector<Node> smoothed = nodes_;
    const auto cells = static_cast<long>(grid_.size());
#pragma omp parallel for schedule(static)
    for (long c = 0; c < cells; ++c) {
        const Node& node = nodes_[c];
        const Eigen::Vector3d nearest(node.normal[0], node.normal[1], node.normal[2]);
        if (nearest.squaredNorm() == 0.0) continue;
        bool reliable = false;
        const Eigen::Vector3d g = distanceGradient(grid_.cellIndices(static_cast<std::size_t>(c)), reliable);
        const double length = g.norm();
        if (!reliable || length < 0.8 || length > 1.2 || g.dot(nearest) < 0.7 * length) continue;
        for (int a = 0; a < 3; ++a) smoothed[c].normal[a] = static_cast<float>(g[a] / length);
    }
    nodes_ = std::move(smoothed);
}

int SignedDistanceField::corners(const Eigen::Vector3d& r, std::size_t* index, double* weight) const {
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
    const int cornersY = grid_.n[1] == 1 ? 1 : 2, cornersZ = grid_.n[2] == 1 ? 1 : 2;
    int count = 0;
    for (int cz = 0; cz < cornersZ; ++cz)
        for (int cy = 0; cy < cornersY; ++cy)
            for (int cx = 0; cx < 2; ++cx) {
                const double w = (cx ? t[0] : 1.0 - t[0]) * (cy ? t[1] : 1.0 - t[1]) * (cz ? t[2] : 1.0 - t[2]);
                if (w == 0.0) continue;
                index[count] = grid_.index(cx ? i1[0] : i0[0], cy ? i1[1] : i0[1], cz ? i1[2] : i0[2]);
                weight[count++] = w;
            }
    return count;
}

SurfaceDistance SignedDistanceField::at(const Eigen::Vector3d& r) const {
    std::size_t index[8];
    double weight[8];
    const int count = corners(r, index, weight);
    double d = 0.0;
    Eigen::Vector3d n(0, 0, 0);
    for (int k = 0; k < count; ++k) {
        const Node& node = nodes_[index[k]];
        d += weight[k] * node.distance;
        n += weight[k] * Eigen::Vector3d(node.normal[0], node.normal[1], node.normal[2]);
    }
    const double norm = n.norm();
    return {d, norm > 0.0 ? Eigen::Vector3d(n / norm) : Eigen::Vector3d::Zero()};
}

double SignedDistanceField::distance(const Eigen::Vector3d& r) const {
    std::size_t index[8];
    double weight[8];
    const int count = corners(r, index, weight);
    double d = 0.0;
    for (int k = 0; k < count; ++k) d += weight[k] * nodes_[index[k]].distance;
    return d;
}

}  // namespace dpd
