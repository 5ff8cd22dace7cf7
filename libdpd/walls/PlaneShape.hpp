#pragma once
// A plane (the `plane` wall type): the solid is the half-space behind it. A particle that ends a step
// behind the plane crossed it and goes back to its mirror image across the plane.
#include "walls/WallShape.hpp"

namespace dpd {

class PlaneShape : public WallShape {
public:
    PlaneShape(const Eigen::Vector3d& point, const Eigen::Vector3d& unitNormal) : point_(point), normal_(unitNormal) {}

    double signedDistance(double x, double y, double z) const {
        return (x - point_.x()) * normal_.x() + (y - point_.y()) * normal_.y() + (z - point_.z()) * normal_.z();
    }
    double signedDistance(const Eigen::Vector3d& r) const override { return signedDistance(r.x(), r.y(), r.z()); }
    SurfaceDistance surfaceAt(const Eigen::Vector3d& r) const override { return {signedDistance(r), normal_}; }
    // A test the compiler vectorises (few particles are near the plane).
    void markWithin(const Particles& p, long begin, long end, double reach, const std::vector<std::uint8_t>& frozenOfSpecies,
                    std::uint8_t* near) const override;
    ShapeCrossing crossing(const Particles& p, std::size_t i, const Box& box, double normalWithin,
                           SurfaceDistance& atEnd) const override;
    bool returnsAlong(int axis) const override { return normal_[axis] != 0.0; }
    Eigen::Vector3d placed(const Eigen::Vector3d& back, const Box& box) const override;
    void markFlowAxes(const Box& box, std::array<bool, 3>& varies) const override;
    std::uint32_t reflectionStream() const override;

private:
    Eigen::Vector3d point_;
    Eigen::Vector3d normal_;  // unit, into the fluid
};

}  // namespace dpd
