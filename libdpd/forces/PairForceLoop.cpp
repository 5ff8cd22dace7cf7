#include "forces/PairForceLoop.hpp"

namespace dpd {

std::vector<StencilEntry> halfStencil(const Box& box) {
    const bool y = box.isActiveAxis(1);
    std::vector<StencilEntry> s{{0, 0, 0}};
    for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz)
            if (y || dy == 0) s.push_back({1, dy, dz});
    if (y)
        for (int dz = -1; dz <= 1; ++dz) s.push_back({0, 1, dz});
    s.push_back({0, 0, 1});
    return s;
}

std::vector<StencilColumn> halfStencilColumns(const Box& box) {
    std::vector<StencilColumn> columns{{0, 0, 0, 2}};
    const bool y = box.isActiveAxis(1);
    for (int dy = -1; dy <= 1; ++dy)
        if (y || dy == 0) columns.push_back({1, dy, -1, 3});
    if (y) columns.push_back({0, 1, -1, 3});
    return columns;
}

}  // namespace dpd
