#include "geometry/GeometryFrame.hpp"

#include <cmath>

namespace dpd {

GeometryFrame GeometryFrame::planar(const Box& box, int extrudeAxis, const Eigen::Vector3d& origin) {
    GeometryFrame f;
    f.dimension = 2;
    f.extrudeAxis = extrudeAxis;
    f.axes[0] = extrudeAxis == 0 ? 1 : 0;
    f.axes[1] = extrudeAxis == 2 ? 1 : 2;
    f.axes[2] = extrudeAxis;
    f.origin = origin;
    for (int k = 0; k < 2; ++k) {
        f.localLo[k] = box.lo[f.axes[k]] - origin[f.axes[k]];
        f.period[k] = box.hi[f.axes[k]] - box.lo[f.axes[k]];
    }
    return f;
}

GeometryFrame GeometryFrame::spatial(const Box& box, const Eigen::Vector3d& origin) {
    GeometryFrame f;
    f.origin = origin;
    f.localLo = box.lo - origin;
    f.period = box.hi - box.lo;
    return f;
}

Eigen::Vector3d GeometryFrame::toLocal(const Eigen::Vector3d& r) const {
    Eigen::Vector3d p(0, 0, 0);
    for (int k = 0; k < dimension; ++k) {
        double x = r[axes[k]] - origin[axes[k]];
        x -= period[k] * std::floor((x - localLo[k]) / period[k]);
        p[k] = x;
    }
    return p;
}

Eigen::Vector3d GeometryFrame::toBoxVector(const Eigen::Vector3d& v) const {
    Eigen::Vector3d b(0, 0, 0);
    for (int k = 0; k < dimension; ++k) b[axes[k]] = v[k];
    return b;
}

Eigen::Vector3d GeometryFrame::nearestImage(const Eigen::Vector3d& p, const Eigen::Vector3d& reference) const {
    Eigen::Vector3d q = p;
    for (int k = 0; k < dimension; ++k) q[k] -= period[k] * std::round((p[k] - reference[k]) / period[k]);
    return q;
}

}  // namespace dpd
