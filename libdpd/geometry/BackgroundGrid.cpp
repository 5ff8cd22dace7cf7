#include "geometry/BackgroundGrid.hpp"

#include <cmath>

namespace dpd {

BackgroundGrid BackgroundGrid::covering(const Box& box, double cellSize, int uniformAxis) {
    BackgroundGrid g;
    g.lo = box.lo;
    const Eigen::Vector3d length = box.length();
    for (int a = 0; a < 3; ++a) {
        const bool varies = box.isActiveAxis(a) && a != uniformAxis;
        g.n[a] = varies ? std::max(1, static_cast<int>(std::ceil(length[a] / cellSize - 1e-9))) : 1;
        g.spacing[a] = length[a] / g.n[a];
    }
    return g;
}

std::array<int, 3> BackgroundGrid::cellIndices(std::size_t index) const {
    const int i = static_cast<int>(index % n[0]);
    const std::size_t rest = index / n[0];
    return {i, static_cast<int>(rest % n[1]), static_cast<int>(rest / n[1])};
}

std::array<int, 3> BackgroundGrid::cellOf(const Eigen::Vector3d& r) const {
    std::array<int, 3> c{};
    for (int a = 0; a < 3; ++a) c[a] = wrapIndex(static_cast<int>(std::floor((r[a] - lo[a]) / spacing[a])), n[a]);
    return c;
}

double BackgroundGrid::cellMeasure(const Box& box) const {
    return box.dimension == 3 ? spacing[0] * spacing[1] * spacing[2] : spacing[0] * spacing[2];
}

}  // namespace dpd
