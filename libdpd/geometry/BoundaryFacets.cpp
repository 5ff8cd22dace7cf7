#include "geometry/BoundaryFacets.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace dpd {

Eigen::Vector3d closestPointOnSegment(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    const Eigen::Vector3d ab = b - a;
    const double len2 = ab.squaredNorm();
    if (len2 == 0.0) return a;
    return a + std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) * ab;
}

Eigen::Vector3d closestPointOnTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                       const Eigen::Vector3d& c) {
    // Voronoi regions of the vertices, then of the edges, else the face (Ericson, Real-Time Collision
    // Detection, 5.1.5).
    const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
    const double d1 = ab.dot(ap), d2 = ac.dot(ap);
    if (d1 <= 0.0 && d2 <= 0.0) return a;
    const Eigen::Vector3d bp = p - b;
    const double d3 = ab.dot(bp), d4 = ac.dot(bp);
    if (d3 >= 0.0 && d4 <= d3) return b;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + d1 / (d1 - d3) * ab;
    const Eigen::Vector3d cp = p - c;
    const double d5 = ab.dot(cp), d6 = ac.dot(cp);
    if (d6 >= 0.0 && d5 <= d6) return c;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + d2 / (d2 - d6) * ac;
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
    const double denom = 1.0 / (va + vb + vc);
    return a + ab * (vb * denom) + ac * (vc * denom);
}

void BoundaryFacets::addSegment(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& normal) {
    facets_.push_back({a, b, b, normal, false});
}

void BoundaryFacets::addTriangle(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                                 const Eigen::Vector3d& normal) {
    facets_.push_back({a, b, c, normal, true});
}

void BoundaryFacets::build(double maxSearchDistance) {
    // Buckets about the search distance wide: a query visits 3 per axis. Each facet is filed by its
    // bounding box so that a query needs no allowance for facet size.
    buckets_ = BucketGrid(frame_.dimension, frame_.localLo, frame_.period, maxSearchDistance);
    for (std::size_t k = 0; k < facets_.size(); ++k) {
        const Facet& f = facets_[k];
        const Eigen::Vector3d lo = f.a.cwiseMin(f.b).cwiseMin(f.c), hi = f.a.cwiseMax(f.b).cwiseMax(f.c);
        buckets_.add(static_cast<std::uint32_t>(k), lo, hi);
    }
    buckets_.build();
}

Eigen::Vector3d BoundaryFacets::closestPoint(const Facet& f, const Eigen::Vector3d& p) const {
    return f.triangle ? closestPointOnTriangle(p, f.a, f.b, f.c) : closestPointOnSegment(p, f.a, f.b);
}

NearestSurface BoundaryFacets::nearest(const Eigen::Vector3d& p, double maxDistance) const {
    NearestSurface best;
    double best2 = maxDistance * maxDistance;
    buckets_.forEachNear(p, maxDistance, [&](std::uint32_t k) {
        const Facet& f = facets_[k];
        // The image of p next to this facet: facets are small next to the box.
        const Eigen::Vector3d q = frame_.nearestImage(p, f.a);
        const Eigen::Vector3d d = q - closestPoint(f, q);
        const double d2 = d.squaredNorm();
        if (d2 > best2 || (best.found && d2 == best2)) return;
        best.found = true;
        best2 = d2;
        best.distance = std::sqrt(d2);
        best.away = best.distance > 1e-12 ? Eigen::Vector3d(d / best.distance) : f.normal;
    });
    return best;
}

}  // namespace dpd
