#include "neighbour/CellList.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace dpd {

void CellList::setup(const Box& box, double cutoff) {
    box_ = box;
    const Eigen::Vector3d L = box.length();
    for (int a = 0; a < 3; ++a) {
        if (!box.isActiveAxis(a)) {
            n_[a] = 1;
            size_[a] = L[a];
            invSize_[a] = 0.0;  // every particle in cell 0 along the inactive axis
            continue;
        }
        n_[a] = static_cast<int>(std::floor(L[a] / cutoff));
        if (n_[a] < 3)
            throw std::invalid_argument("the box must be at least three cutoffs long along axis " +
                                        std::string(1, "xyz"[a]) + " (it is " + std::to_string(L[a]) + ")");
        size_[a] = L[a] / n_[a];
        invSize_[a] = 1.0 / size_[a];
    }
    start_.assign(numCells() + 1, 0);
}

int CellList::axisCell(double x, int axis) const {
    const int c = static_cast<int>((x - box_.lo[axis]) * invSize_[axis]);
    // Positions are wrapped into [lo, hi); rounding can still give n at the very top.
    return std::min(std::max(c, 0), n_[axis] - 1);
}

void CellList::sortParticles(Particles& p) {
    const std::size_t n = p.size();
    cellOf_.resize(n);
    std::fill(start_.begin(), start_.end(), 0);
    for (std::size_t i = 0; i < n; ++i) {
        const int c = cellIndex(axisCell(p.rx[i], 0), axisCell(p.ry[i], 1), axisCell(p.rz[i], 2));
        cellOf_[i] = static_cast<std::uint32_t>(c);
        ++start_[c + 1];
    }
    for (int c = 0; c < numCells(); ++c) start_[c + 1] += start_[c];
    // Stable counting sort: particles keep their relative order inside a cell, so the layout (and
    // with it the summation order of forces) is a function of the state alone.
    order_.resize(n);
    std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
    for (std::size_t i = 0; i < n; ++i) order_[fill[cellOf_[i]]++] = static_cast<std::uint32_t>(i);
    p.permute(order_);
}

}  // namespace dpd
