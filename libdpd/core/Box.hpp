#pragma once
// The simulation box: an axis-aligned periodic domain in two or three dimensions.
//
// A two-dimensional scene lives in the x-z plane (the scenes of docs/scenes.md are drawn in x-z with y
// thin), so in 2-D the y axis is inactive: every particle sits at y = 0 with vy = 0, and "volume"
// means the x-z area.
#include <Eigen/Core>

namespace dpd {

struct Box {
    Eigen::Vector3d lo{0.0, 0.0, 0.0};
    Eigen::Vector3d hi{1.0, 1.0, 1.0};
    int dimension = 3;

    Eigen::Vector3d length() const { return hi - lo; }
    bool isActiveAxis(int axis) const { return dimension == 3 || axis != 1; }
    // Volume in 3-D, x-z area in 2-D.
    double volume() const {
        const Eigen::Vector3d l = length();
        return dimension == 3 ? l.x() * l.y() * l.z() : l.x() * l.z();
    }
    // Map a coordinate back into [lo, hi) along one axis.
    double wrap(double x, int axis) const {
        const double L = hi[axis] - lo[axis];
        if (x >= hi[axis]) x -= L * static_cast<long>((x - lo[axis]) / L);
        else if (x < lo[axis]) x += L * static_cast<long>((hi[axis] - x) / L);
        return x;
    }
    // Map a position back into the box along every active axis (y stays put in 2-D).
    void wrapPoint(double& x, double& y, double& z) const {
        x = wrap(x, 0);
        if (isActiveAxis(1)) y = wrap(y, 1);
        z = wrap(z, 2);
    }
};

}  // namespace dpd
