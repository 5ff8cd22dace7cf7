#include "geometry/SolidFlags.hpp"

#include "geometry/SolidGeometry.hpp"

namespace dpd {

SolidFlags::SolidFlags(const BackgroundGrid& grid, const SolidGeometry& geometry) : grid_(grid), solid_(grid.size()) {
    const auto cells = static_cast<long>(grid_.size());
#pragma omp parallel for schedule(static)
    for (long c = 0; c < cells; ++c) {
        const auto ijk = grid_.cellIndices(static_cast<std::size_t>(c));
        solid_[c] = geometry.isSolid(grid_.centre(ijk[0], ijk[1], ijk[2])) ? 1 : 0;
    }
    for (const auto s : solid_) fluidCells_ += s ? 0 : 1;
}

}  // namespace dpd
