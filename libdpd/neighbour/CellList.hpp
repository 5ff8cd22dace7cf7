#pragma once
// Cell lists with particles sorted by cell.
//
// The box is cut into cells no smaller than the cutoff along every active axis; the particle arrays
// are then reordered by cell (a stable counting sort), so the members of a cell are contiguous in
// memory and a cell's neighbours are few contiguous runs. Cells are numbered with x slowest, so a
// slab of constant x is one contiguous range of cells: the pair loop colours these slabs to run in
// parallel without races and with a summation order that does not depend on the thread count.
#include "core/Box.hpp"
#include "core/Particles.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace dpd {

class CellList {
public:
    // Lays out the grid for a box and cutoff. Throws std::invalid_argument if an active axis has fewer
    // than three cells (the half stencil would then meet the same neighbour twice).
    void setup(const Box& box, double cutoff);
    // Reorders the particles by cell and records where each cell starts.
    void sortParticles(Particles& p);

    const std::array<int, 3>& cellsPerAxis() const { return n_; }
    int cellIndex(int ix, int iy, int iz) const { return (ix * n_[1] + iy) * n_[2] + iz; }
    int numCells() const { return n_[0] * n_[1] * n_[2]; }
    // Particles of cell c are [cellStart(c), cellStart(c + 1)).
    std::uint32_t cellStart(int c) const { return start_[c]; }
    const Box& box() const { return box_; }
    const Eigen::Vector3d& cellSize() const { return size_; }

private:
    int axisCell(double x, int axis) const;
    Box box_;
    std::array<int, 3> n_{1, 1, 1};
    Eigen::Vector3d size_{1, 1, 1};
    Eigen::Vector3d invSize_{1, 1, 1};
    std::vector<std::uint32_t> start_;
    std::vector<std::uint32_t> cellOf_, order_;
};

}  // namespace dpd
