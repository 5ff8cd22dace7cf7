#pragma once
// Which rank owns which planes of cells along x (docs/parallel.md 1). The cell list numbers cells with
// x slowest, so a rank's planes are one contiguous range of cells; rank r owns planes
// [first(r), first(r + 1)), in rank order. The cuts balance a weight per plane: its mobile
// particles plus kFrozenWeight for each frozen one (a frozen particle meets only the mobile ones).
#include <string>
#include <vector>

namespace dpd {

class SlabDecomposition {
public:
    static constexpr double kFrozenWeight = 0.3;

    // One rank owning every plane.
    explicit SlabDecomposition(int planes = 1) : cuts_{0, planes} {}
    // Cuts from the weights of the planes: rank r's range ends at the first plane where the running
    // weight reaches (r + 1) / ranks of the total, moved so that every rank owns at least minPlanes(ranks)
    // planes. Throws std::invalid_argument (saying how many planes the ranks need) when there are
    // too few planes.
    static SlabDecomposition balanced(const std::vector<double>& planeWeights, int ranks);
    // Given cuts (first plane of each rank, then the plane count): for tests and uneven slabs.
    static SlabDecomposition fromCuts(std::vector<int> cuts);
    // Two ranks would see the same neighbour plane as both ghost planes with one plane each; from
    // three on, one plane each is enough.
    static int minPlanes(int ranks) { return ranks == 2 ? 2 : 1; }

    int ranks() const { return static_cast<int>(cuts_.size()) - 1; }
    int planes() const { return cuts_.back(); }
    int first(int rank) const { return cuts_[rank]; }
    int end(int rank) const { return cuts_[rank + 1]; }
    int ownerOf(int plane) const;
    // The ranks' ranges as text ("0-5 | 6-11 | ..."), for the log.
    std::string describe() const;

private:
    std::vector<int> cuts_;
};

}  // namespace dpd
