#include "parallel/SlabDecomposition.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace dpd {

SlabDecomposition SlabDecomposition::balanced(const std::vector<double>& planeWeights, int ranks, int ghostPlanes) {
    const int planes = static_cast<int>(planeWeights.size());
    const int least = minPlanes(ranks, ghostPlanes);
    if (ranks < 1) throw std::invalid_argument("a decomposition needs at least one rank");
    if (planes < ranks * least)
        throw std::invalid_argument("the box has " + std::to_string(planes) + " planes of cells along x (one cutoff or more " +
                                    "each); " + std::to_string(ranks) + " ranks need at least " +
                                    std::to_string(ranks * least) +
                                    (ghostPlanes > 1 ? " (" + std::to_string(ghostPlanes) + " ghost planes a side for the bonds)" : "") +
                                    ": use fewer ranks or a longer box along x");
    const double total = std::accumulate(planeWeights.begin(), planeWeights.end(), 0.0);
    std::vector<int> cuts(ranks + 1, 0);
    cuts[ranks] = planes;
    double running = 0.0;
    int plane = 0;
    for (int r = 1; r < ranks; ++r) {
        const double target = total * r / ranks;
        // The plane after which the running weight first reaches the target, kept within the room the
        // ranks before and after need.
        while (plane < planes && running + planeWeights[plane] <= target) running += planeWeights[plane++];
        if (plane < planes && target - running > running + planeWeights[plane] - target) running += planeWeights[plane++];
        const int lowest = cuts[r - 1] + least, highest = planes - (ranks - r) * least;
        const int cut = std::clamp(plane, lowest, highest);
        for (; plane < cut; ++plane) running += planeWeights[plane];
        for (; plane > cut; --plane) running -= planeWeights[plane - 1];
        cuts[r] = cut;
    }
    return fromCuts(cuts, ghostPlanes);
}

SlabDecomposition SlabDecomposition::fromCuts(std::vector<int> cuts, int ghostPlanes) {
    if (cuts.size() < 2 || cuts.front() != 0) throw std::invalid_argument("slab cuts must start at plane 0");
    if (ghostPlanes < 1) throw std::invalid_argument("a slab needs at least one ghost plane a side");
    const int ranks = static_cast<int>(cuts.size()) - 1;
    for (int r = 0; r < ranks; ++r)
        if (cuts[r + 1] - cuts[r] < minPlanes(ranks, ghostPlanes))
            throw std::invalid_argument("slab cuts: rank " + std::to_string(r) + " owns " + std::to_string(cuts[r + 1] - cuts[r]) +
                                        " planes; each of " + std::to_string(ranks) + " ranks needs at least " +
                                        std::to_string(minPlanes(ranks, ghostPlanes)));
    SlabDecomposition d;
    d.cuts_ = std::move(cuts);
    d.ghostPlanes_ = ghostPlanes;
    return d;
}

int SlabDecomposition::ghostPlanesFor(double reach, double cellWidth) {
    if (!(reach > 0.0 && cellWidth > 0.0)) throw std::invalid_argument("ghost planes need a positive reach and cell width");
    return std::max(1, static_cast<int>(std::ceil(reach / cellWidth)));
}

int SlabDecomposition::ownerOf(int plane) const {
    return static_cast<int>(std::upper_bound(cuts_.begin(), cuts_.end(), plane) - cuts_.begin()) - 1;
}

std::string SlabDecomposition::describe() const {
    std::string s;
    for (int r = 0; r < ranks(); ++r) {
        if (r > 0) s += " | ";
        s += std::to_string(first(r)) + "-" + std::to_string(end(r) - 1);
    }
    return s;
}

}  // namespace dpd
