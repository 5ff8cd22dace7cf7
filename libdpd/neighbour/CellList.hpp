#pragma once
// Cell lists with particles sorted by cell.
//
// The box is cut into cells no smaller than the cutoff along every active axis; the particle arrays
// are then reordered by cell (a stable counting sort), so the members of a cell are contiguous in
// memory and a cell's neighbours are few contiguous runs. Cells are numbered with x slowest, so a
// slab of constant x is one contiguous range of cells: the pair loop colours these slabs to run in
// parallel without races and with a summation order that does not depend on the thread count.
//
// Given which species are frozen, the sort also puts a cell's mobile particles before its frozen
// ones, so the pair loop can pass frozen-frozen pairs (which never interact) without visiting them.
#include "core/Box.hpp"
#include "core/Particles.hpp"
#include "neighbour/SortKeyBlocks.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace dpd {

// What a sort does with the particles' forces: move them along with the particles, or leave them in
// the order they had before the sort, for a caller whose next force computation writes over them
// (moving forces that are never read again is wasted bandwidth). The forces left behind can still be
// read through order().
enum class SortForces { Move, Leave };

class CellList {
public:
    // Lays out the grid for a box and cutoff. Throws std::invalid_argument if an active axis has fewer
    // than two cells (a box under two cutoffs long, where a pair could meet within the cutoff twice).
    // With two cells along an axis the stencil reaches the neighbouring cell twice, through its two
    // images, which the pair loop's cell offsets tell apart.
    void setup(const Box& box, double cutoff);
    // Wraps the positions into the box, reorders the particles by cell and records where each cell
    // starts. Every particle counts as mobile.
    void sortParticles(Particles& p, SortForces forces = SortForces::Move);
    // The same, with the mobile particles of each cell before the frozen ones (frozenOfSpecies[s] != 0
    // for a frozen species s).
    void sortParticles(Particles& p, const std::vector<std::uint8_t>& frozenOfSpecies,
                       SortForces forces = SortForces::Move);
    // For the next sort only (a decomposed run's, parallel/SlabDomain.hpp). setVisitOrder: the ranges of
    // particle indices [first, second), together covering the arrays, in the order the stable sort
    // takes them (one process's order of particles stored in another). setDiscarded: particles the
    // sort moves past the last cell (those that left for another rank); sortedCount() then says how
    // many remain in cells, and the caller shortens the arrays to it.
    void setVisitOrder(std::vector<std::pair<std::uint32_t, std::uint32_t>> ranges) { visit_ = std::move(ranges); }
    void setDiscarded(std::vector<std::uint32_t> indices) { discarded_ = std::move(indices); }
    std::size_t sortedCount() const { return start_[2 * static_cast<std::size_t>(numCells())]; }
    // The last sort's permutation: particle k of the sorted arrays was particle order()[k] before it.
    const ParticleArray<std::uint32_t>& order() const { return order_; }

    const std::array<int, 3>& cellsPerAxis() const { return n_; }
    int cellIndex(int ix, int iy, int iz) const { return (ix * n_[1] + iy) * n_[2] + iz; }
    int numCells() const { return n_[0] * n_[1] * n_[2]; }
    // Particles of cell c are [cellStart(c), cellStart(c + 1)); the mobile ones are
    // [cellStart(c), mobileEnd(c)), the frozen ones [mobileEnd(c), cellStart(c + 1)).
    std::uint32_t cellStart(int c) const { return start_[2 * c]; }
    std::uint32_t mobileEnd(int c) const { return start_[2 * c + 1]; }
    // Whether the last sort split the cells into mobile and frozen parts, and which species it took
    // as frozen.
    bool splitsFrozen() const { return !frozenOfSpecies_.empty(); }
    bool isFrozenSpecies(int s) const {
        return s < static_cast<int>(frozenOfSpecies_.size()) && frozenOfSpecies_[s] != 0;
    }
    // The cell index along `axis` of a coordinate inside the box (as the sort computes it).
    int axisCell(double x, int axis) const {
        const int c = static_cast<int>((x - box_.lo[axis]) * invSize_[axis]);
        // Positions are wrapped into [lo, hi); rounding can still give n at the very top.
        return std::min(std::max(c, 0), n_[axis] - 1);
    }
    const Box& box() const { return box_; }
    const Eigen::Vector3d& cellSize() const { return size_; }
    // The planes of cells (constant x index) whose cells a pair loop visits as home cells: all of them
    // (the default), or, for one rank of a decomposed run, its own and the one before (parallel/SlabDomain),
    // its particles lying in them and in ghostPlanes planes on either side of its own. The sort then
    // counts only the keys of the planes that can hold particles or be read (those, and one more on
    // either side), not the whole box's grid: the other planes' cell starts are left as they were,
    // and are not read.
    void setHomePlanes(std::vector<std::uint8_t> home, int ghostPlanes = 1);
    bool isHomePlane(int ix) const { return homePlanes_.empty() || homePlanes_[static_cast<std::size_t>(ix)] != 0; }
    // Bytes held (capacities of the cell starts, the sort keys and order, and the sort's scratch).
    std::size_t memoryBytes() const;

private:
    void sort(Particles& p, SortForces forces);
    // start_ and order_ from keyOf_ (a stable counting sort, in parallel).
    void countingSort();
    // The particle arrays put in order_ (inside a parallel region).
    void gatherVector(ParticleArray<double>& x, ParticleArray<double>& y, ParticleArray<double>& z);
    void gatherIdentity(Particles& p);

    Box box_;
    std::array<int, 3> n_{1, 1, 1};
    Eigen::Vector3d size_{1, 1, 1};
    Eigen::Vector3d invSize_{1, 1, 1};
    // start_[2c] is where cell c starts, start_[2c + 1] where its frozen part starts.
    std::vector<std::uint32_t> start_;
    std::vector<std::uint8_t> frozenOfSpecies_;
    std::vector<std::uint8_t> homePlanes_;  // empty: every plane
    int ghostPlanes_ = 1;
    // The sort's keys in ascending ranges [first, second), the discarded particles' key the last:
    // every key, or (with home planes) those of the planes near them.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> keyWindows_;
    void setKeyWindows();
    // For the next sort only: empty, every particle in array order, none discarded.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> visit_;
    std::vector<std::uint32_t> discarded_;
    // Kept between sorts, so a step allocates nothing.
    ParticleArray<std::uint32_t> keyOf_, order_, fill_;
    SortKeyBlocks keyBlocks_;  // keyOf_'s bounds per block, for the threads' passes over it
    std::array<ParticleArray<double>, 3> scratch_;
    ParticleArray<std::uint64_t> idScratch_;
    ParticleArray<std::uint8_t> speciesScratch_;
};

}  // namespace dpd
