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

}  // namespace dpd
