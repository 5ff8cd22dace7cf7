#pragma once
// A solid of any shape in the periodic box, whatever it was read from (an image mask, a gmsh
// geometry): which points are solid, and the nearest point of the solid surface. Builders
// (ImageMask, GmshGeometry) make one; SolidFlags and SignedDistanceField sample it on a grid.
#include "geometry/BoundaryFacets.hpp"
#include "geometry/GeometryFrame.hpp"

#include <Eigen/Core>

#include <functional>
#include <memory>
#include <string>

namespace dpd {

// Signed distance to the solid surface: positive in the fluid, negative in the solid; the normal is
// the unit vector pointing into the fluid (the direction in which the distance grows).
struct SurfaceDistance {
    double distance = 0.0;
    Eigen::Vector3d normal{0, 0, 0};
};

class SolidGeometry {
public:
    // isSolidLocal takes geometry coordinates (frame.toLocal of a box point). searchReach: the
    // distance up to which signedDistance is usually asked (it sizes the facet search buckets).
    using Classifier = std::function<bool(const Eigen::Vector3d& local)>;
    SolidGeometry(GeometryFrame frame, Classifier isSolidLocal, BoundaryFacets facets, std::string source,
                  double searchReach);

    bool isSolid(const Eigen::Vector3d& r) const { return isSolidLocal_(frame_.toLocal(r)); }
    // The exact signed distance and normal at a box point, the distance clipped to +-maxDistance (the
    // normal is then zero). The sign comes from isSolid, the magnitude from the surface facets.
    SurfaceDistance signedDistance(const Eigen::Vector3d& r, double maxDistance) const;

    const GeometryFrame& frame() const { return frame_; }
    // Box axis along which the geometry does not vary (planar geometries), -1 otherwise.
    int uniformAxis() const { return frame_.extrudeAxis; }
    const std::string& source() const { return source_; }  // the file it was read from
    std::size_t facetCount() const { return facets_.size(); }

private:
    GeometryFrame frame_;
    Classifier isSolidLocal_;
    BoundaryFacets facets_;
    std::string source_;
};

}  // namespace dpd
