#pragma once
// The signed distance to the solid surface and its normal (into the fluid), tabulated at the cell
// centres of a background grid and interpolated (linearly along each varying axis) anywhere in the
// periodic box. A query is O(1): one cell lookup and 2^d table entries, so the solver can afford one
// per particle and step.
//
// Accuracy: the table holds the exact distance to the geometry's surface facets (SolidGeometry);
// linear interpolation of a distance function adds at most h^2 / (8 R) for a surface of curvature
// radius R on a grid of spacing h, and up to h/2 within a cell of a ridge (points equally near two
// surfaces, like the middle of a channel) or a sharp corner. The normal is the central-difference
// gradient of the tabulated distance (over two cells, which smooths the pixel staircase of image
// masks) where that is reliable, else the direction to the nearest surface point; interpolated and
// normalised. Beyond +-band the distance is clipped to
// +-band and the normal is zero.
#include "geometry/BackgroundGrid.hpp"
#include "geometry/SolidGeometry.hpp"

#include <array>
#include <vector>

namespace dpd {

class SignedDistanceField {
public:
    // Tabulates the geometry at the grid's cell centres. The signs there come from the same
    // SolidGeometry::isSolid as SolidFlags on that grid, so the two agree cell by cell.
    SignedDistanceField(const SolidGeometry& geometry, const BackgroundGrid& grid, double band);

    // Distance (positive in the fluid) and unit normal into the fluid at a box point.
    SurfaceDistance at(const Eigen::Vector3d& r) const;
    // The distance alone (the same number as at(r).distance, without the normal's cost).
    double distance(const Eigen::Vector3d& r) const;

    // The distance tabulated at a grid cell's centre (BackgroundGrid::index).
    float tabulatedDistance(std::size_t cell) const { return nodes_[cell].distance; }
    const BackgroundGrid& grid() const { return grid_; }
    double band() const { return band_; }

private:
    // The corners of the grid cell r interpolates in (x fastest; along an axis of one cell only the
    // first) and their weights, the number of corners returned.
    int corners(const Eigen::Vector3d& r, std::size_t* index, double* weight) const;
    // The distance's central-difference gradient at a cell centre; reliable is false when a
    // neighbour is clipped to the band.
    Eigen::Vector3d distanceGradient(const std::array<int, 3>& ijk, bool& reliable) const;
    void smoothNormals();

    struct Node {
        float distance;
        float normal[3];
    };
    BackgroundGrid grid_;
    double band_;
    std::vector<Node> nodes_;
};

}  // namespace dpd
