#pragma once
// Solid/fluid flags on a background grid (docs/walls.md 3.2 step 1): a cell is solid when its centre is.
#include "geometry/BackgroundGrid.hpp"

#include <cstdint>
#include <vector>

namespace dpd {

class SolidGeometry;

class SolidFlags {
public:
    SolidFlags(const BackgroundGrid& grid, const SolidGeometry& geometry);

    const BackgroundGrid& grid() const { return grid_; }
    bool isSolid(std::size_t cell) const { return solid_[cell] != 0; }
    bool isSolid(int i, int j, int k) const { return solid_[grid_.index(i, j, k)] != 0; }
    bool isSolidAt(const Eigen::Vector3d& r) const {
        const auto c = grid_.cellOf(r);
        return isSolid(c[0], c[1], c[2]);
    }
    std::size_t fluidCells() const { return fluidCells_; }
    // Fluid fraction of the box.
    double porosity() const { return static_cast<double>(fluidCells_) / static_cast<double>(grid_.size()); }

private:
    BackgroundGrid grid_;
    std::vector<std::uint8_t> solid_;
    std::size_t fluidCells_ = 0;
};

}  // namespace dpd
