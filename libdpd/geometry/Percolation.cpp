#include "geometry/Percolation.hpp"

#include <limits>
#include <vector>

namespace dpd {

bool fluidPercolates(const SolidFlags& flags, int axis) {
    const BackgroundGrid& g = flags.grid();
    if (g.n[axis] == 1) return flags.fluidCells() > 0;
    constexpr int unvisited = std::numeric_limits<int>::min();
    std::vector<int> winding(g.size(), unvisited);  // periodic crossings along `axis` when first reached
    std::vector<std::size_t> stack;
    for (std::size_t seed = 0; seed < g.size(); ++seed) {
        if (flags.isSolid(seed) || winding[seed] != unvisited) continue;
        winding[seed] = 0;
        stack.assign(1, seed);
        while (!stack.empty()) {
            const std::size_t cell = stack.back();
            stack.pop_back();
            const auto c = g.cellIndices(cell);
            for (int a = 0; a < 3; ++a) {
                if (g.n[a] == 1) continue;
                for (const int step : {-1, 1}) {
                    auto nb = c;
                    nb[a] += step;
                    int crossing = 0;
                    if (nb[a] < 0 || nb[a] >= g.n[a]) {
                        crossing = a == axis ? step : 0;
                        nb[a] = BackgroundGrid::wrapIndex(nb[a], g.n[a]);
                    }
                    const std::size_t next = g.index(nb[0], nb[1], nb[2]);
                    if (flags.isSolid(next)) continue;
                    const int w = winding[cell] + crossing;
                    if (winding[next] == unvisited) {
                        winding[next] = w;
                        stack.push_back(next);
                    } else if (winding[next] != w) {
                        return true;
                    }
                }
            }
        }
    }
    return false;
}

}  // namespace dpd
