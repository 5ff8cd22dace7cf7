#pragma once
// A regular grid of cells covering the periodic box (docs/walls.md 3.2 step 1): the solid/fluid flags
// and the signed distance are stored at its cell centres. Along an axis where nothing varies (the
// inactive y axis of a 2-D box, or the extrusion axis of a 2-D geometry) it has a single cell.
#include "core/Box.hpp"

#include <Eigen/Core>

#include <array>
#include <cstddef>

namespace dpd {

struct BackgroundGrid {
    Eigen::Vector3d lo{0, 0, 0};
    Eigen::Vector3d spacing{1, 1, 1};   // cell size per axis; the box length over the cell count
    std::array<int, 3> n{1, 1, 1};

    // Cells no larger than cellSize along every varying axis (an integer number fits the box).
    // uniformAxis: an axis along which the geometry does not vary (one cell), or -1.
    static BackgroundGrid covering(const Box& box, double cellSize, int uniformAxis);

    std::size_t size() const { return static_cast<std::size_t>(n[0]) * n[1] * n[2]; }
    std::size_t index(int i, int j, int k) const {
        return (static_cast<std::size_t>(k) * n[1] + j) * n[0] + i;
    }
    std::array<int, 3> cellIndices(std::size_t index) const;
    Eigen::Vector3d centre(int i, int j, int k) const {
        return lo + Eigen::Vector3d((i + 0.5) * spacing[0], (j + 0.5) * spacing[1], (k + 0.5) * spacing[2]);
    }
    // The cell holding a point, wrapped periodically into the grid.
    std::array<int, 3> cellOf(const Eigen::Vector3d& r) const;
    // Per particle and step in the wall passes: the usual index, at most one box away, wraps without a
    // division.
    static int wrapIndex(int i, int count) {
        if (i >= 0 && i < count) return i;
        if (i < 0 && i >= -count) return i + count;
        if (i >= count && i < 2 * count) return i - count;
        return ((i % count) + count) % count;
    }
    // Volume (area in 2-D) of one cell: the product over the varying axes of the box.
    double cellMeasure(const Box& box) const;
};

}  // namespace dpd
