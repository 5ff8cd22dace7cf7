#include "geometry/SolidGeometry.hpp"

namespace dpd {

SolidGeometry::SolidGeometry(GeometryFrame frame, Classifier isSolidLocal, BoundaryFacets facets, std::string source,
                             double searchReach)
    : frame_(frame), isSolidLocal_(std::move(isSolidLocal)), facets_(std::move(facets)), source_(std::move(source)) {
    facets_.build(searchReach);
}

SurfaceDistance SolidGeometry::signedDistance(const Eigen::Vector3d& r, double maxDistance) const {
    const Eigen::Vector3d p = frame_.toLocal(r);
    const double sign = isSolidLocal_(p) ? -1.0 : 1.0;
    const NearestSurface s = facets_.nearest(p, maxDistance);
    if (!s.found) return {sign * maxDistance, Eigen::Vector3d::Zero()};
    // Into the fluid: away from the surface in the fluid, towards it in the solid; on the surface
    // itself `away` is already the facet's normal into the fluid.
    const double towardsFluid = s.distance > 1e-12 ? sign : 1.0;
    return {sign * s.distance, frame_.toBoxVector(towardsFluid * s.away)};
}

}  // namespace dpd
