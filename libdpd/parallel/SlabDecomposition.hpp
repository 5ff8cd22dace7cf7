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
    // weight reaches (r + 1) / ranks of the total, moved so that every rank owns at least
    // minPlanes(ranks, ghostPlanes) planes. Throws std::invalid_argument (saying how many planes the
    // ranks need) when there are too few planes.
    static SlabDecomposition balanced(const std::vector<double>& planeWeights, int ranks, int ghostPlanes = 1);
    // Given cuts (first plane of each rank, then the plane count): for tests and uneven slabs.
    static SlabDecomposition fromCuts(std::vector<int> cuts, int ghostPlanes = 1);
    // A rank's ghost planes on either side all come from its neighbour there, so each slab holds
    // at least ghostPlanes planes; with two ranks the one neighbour's slab must hold both sides'
    // ghost planes without sharing one (twice as many).
    static int minPlanes(int ranks, int ghostPlanes = 1) { return ranks == 2 ? 2 * ghostPlanes : ghostPlanes; }
    // The planes of ghosts a slab needs on either side to find every particle within `reach` (the
    // cutoff, or a bond's maximum length when longer) of its own: whole planes of width cellWidth.
    static int ghostPlanesFor(double reach, double cellWidth);

    int ranks() const { return static_cast<int>(cuts_.size()) - 1; }
    int planes() const { return cuts_.back(); }
    int first(int rank) const { return cuts_[rank]; }
    int end(int rank) const { return cuts_[rank + 1]; }
    int ownerOf(int plane) const;
    int ghostPlanes() const { return ghostPlanes_; }
    // The ranks' ranges as text ("0-5 | 6-11 | ..."), for the log.
    std::string describe() const;

private:
    std::vector<int> cuts_;
    int ghostPlanes_ = 1;
};

}  // namespace dpd
