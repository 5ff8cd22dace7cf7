#pragma once
// The solid surface as facets in a geometry's own coordinates: segments for a planar geometry,
// triangles for a spatial one, each with its unit normal pointing into the fluid. Answers "nearest
// surface point within a distance" exactly (to the facets), with periodic images, through a bucket
// grid: the cost of a query is the number of facets within reach, independent of the total.
#include "geometry/BucketGrid.hpp"
#include "geometry/GeometryFrame.hpp"

#include <Eigen/Core>

#include <vector>

namespace dpd {

struct NearestSurface {
    bool found = false;                 // false when no facet lies within the search distance
    double distance = 0.0;
    Eigen::Vector3d away{0, 0, 0};      // unit vector from the nearest surface point to the query point
                                        // (the facet normal when the point is on the surface)
};

class BoundaryFacets {
public:
    explicit BoundaryFacets(const GeometryFrame& frame) : frame_(frame) {}

    void addSegment(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& normalIntoFluid);
    void addTriangle(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                     const Eigen::Vector3d& normalIntoFluid);
    // Call once after the last add: files the facets for searches reaching up to maxSearchDistance.
    void build(double maxSearchDistance);

    std::size_t size() const { return facets_.size(); }
    // The nearest facet point to p (geometry coordinates) no farther than maxDistance (at most the
    // distance given to build()).
    NearestSurface nearest(const Eigen::Vector3d& p, double maxDistance) const;

private:
    struct Facet {
        Eigen::Vector3d a, b, c;   // c == b for a segment
        Eigen::Vector3d normal;
        bool triangle;
    };
    Eigen::Vector3d closestPoint(const Facet& f, const Eigen::Vector3d& p) const;
    GeometryFrame frame_;
    std::vector<Facet> facets_;
    BucketGrid buckets_;
};

// Closest points on simple shapes (exposed for tests).
Eigen::Vector3d closestPointOnSegment(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b);
Eigen::Vector3d closestPointOnTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                       const Eigen::Vector3d& c);

}  // namespace dpd
