#pragma once
// Where a geometry sits in the box. A geometry has its own coordinates (an image's pixels times the
// pixel size, or a gmsh file's x, y, z) and is either
//  - planar (2-D): it lies in the plane of two box axes and is extruded along the third. Its x runs
//    along the first of the two in-plane box axes in the order x, y, z, its y along the second:
//    extrudeAxis y -> (x, z); extrudeAxis x -> (y, z); extrudeAxis z -> (x, y); or
//  - spatial (3-D): its x, y, z are the box's x, y, z.
// A box point r has geometry coordinates r - origin (in-plane components only when planar),
// wrapped periodically into the box, since the box is periodic along every axis.
#include "core/Box.hpp"

#include <Eigen/Core>

namespace dpd {

struct GeometryFrame {
    int dimension = 3;        // 2: planar, extruded along extrudeAxis; 3: spatial
    int extrudeAxis = -1;     // box axis along which a planar geometry is extruded; -1 when spatial
    int axes[3] = {0, 1, 2};  // box axis of each geometry axis (the third unused when planar)
    Eigen::Vector3d origin{0, 0, 0};    // box position of the geometry's (0, 0, 0)
    Eigen::Vector3d localLo{0, 0, 0};   // geometry coordinates of the box's lower corner
    Eigen::Vector3d period{0, 0, 0};    // box length along each geometry axis (0 when unused)

    static GeometryFrame planar(const Box& box, int extrudeAxis, const Eigen::Vector3d& origin);
    static GeometryFrame spatial(const Box& box, const Eigen::Vector3d& origin);

    // Geometry coordinates of a box point, wrapped into [localLo, localLo + period).
    Eigen::Vector3d toLocal(const Eigen::Vector3d& r) const;
    // A geometry-space vector (a normal) as a box vector.
    Eigen::Vector3d toBoxVector(const Eigen::Vector3d& v) const;
    // The periodic image of `p` (geometry coordinates) nearest to `reference`.
    Eigen::Vector3d nearestImage(const Eigen::Vector3d& p, const Eigen::Vector3d& reference) const;
};

}  // namespace dpd
