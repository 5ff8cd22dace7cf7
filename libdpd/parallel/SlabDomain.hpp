#pragma once
// A rank's part of a run decomposed in slabs along x (docs/parallel.md): the particles of its planes
// of cells ("owned"), and for the pair loop copies of its neighbours' particles in the plane on
// either side ("ghosts", one cutoff wide; with chains the beads of as many planes as a bond can reach,
// for the bond pass: SlabDecomposition::ghostPlanes). Every rank keeps the whole box's cell grid (the grid is
// global, its cells outside the slab and its ghost planes stay empty), so a rank's pair loop visits
// its own planes' cells and the plane before them as home cells, in the single rank's colour order,
// and each owned particle receives its forces in the order a single rank gives them: trajectories
// do not depend on the number of ranks (nor of threads). Nothing goes back: the ghosts' forces are
// thrown away (each rank does the pairs across its lower face again: the duplicated work).
//
// The order of a rank's particles is the single rank's order restricted to them: the cell sort is
// stable, so particles that come in are sorted as if a single rank held them (from lower ranks first,
// then the rank's own, then from higher ranks: each rank's range of cells follows the one before),
// and ghosts are sent in their owner's order.
#include "core/Box.hpp"
#include "core/Particles.hpp"
#include "forces/ChainBonds.hpp"
#include "neighbour/CellList.hpp"
#include "parallel/Communicator.hpp"
#include "parallel/ParticleColumns.hpp"
#include "parallel/SlabDecomposition.hpp"
#include "walls/Wall.hpp"

#include <cstdint>
#include <memory>
#include <vector>

namespace dpd {

class SlabDomain {
public:
    SlabDomain(const Communicator& comm, SlabDecomposition slabs);
    // The slabs of a run on comm's ranks, balanced over the particles as read (every rank holds all
    // of them before keepOwned), cells laid out by `cells`.
    static std::shared_ptr<SlabDomain> balanced(const Communicator& comm, const CellList& cells, const Particles& p,
                                                const std::vector<std::uint8_t>& frozenOfSpecies, int ghostPlanes = 1);
    // The species (1 per species index) whose particles go as ghosts over all the ghost planes, the
    // chains' beads; the others only over the plane at the face, all that the pair loop reads.
    void setFarGhostSpecies(const std::vector<std::uint8_t>& species);

    const Communicator& communicator() const { return *comm_; }
    const SlabDecomposition& slabs() const { return slabs_; }
    int firstPlane() const { return slabs_.first(comm_->rank()); }
    int endPlane() const { return slabs_.end(comm_->rank()); }
    // The ranks of the slabs before and after this one (periodically; one rank with two ranks).
    int rankBelow() const;
    int rankAbove() const;
    // The planes whose cells this rank's pair loop visits as home cells: its own and the one before.
    std::vector<std::uint8_t> homePlanes() const;

    // Keeps only this rank's particles, in their order (at the start, where every rank read all).
    void keepOwned(Particles& p, const CellList& cells) const;
    // Index ranges of the particle arrays, in the order one process would hold the particles.
    using Ranges = std::vector<std::pair<std::uint32_t, std::uint32_t>>;

    // Sends the particles that moved out of this rank's planes (with their deferred wall crossings,
    // and with chains the vectors of their bonds, which the new owner's next bond pass follows) to
    // their owners, in the order `own` gives, and takes in those that came; no ghosts may be held.
    // The leavers stay in p, their indices in `leavers` (the sort discards them: CellList::setDiscarded).
    // Those from higher ranks are appended to p; those from lower ranks, which one process holds
    // before this rank's own, go to fromLower (appended after the ghosts, they lead the sort's order).
    void migrate(Particles& p, const Ranges& own, const CellList& cells, std::vector<DeferredCrossing>& deferred,
                 ChainBonds* bonds, Particles& fromLower, std::vector<std::uint32_t>& leavers) const;
    // Appends to p copies of the neighbours' particles in the ghost planes next to this rank's; this rank's
    // particles are `fromLower` and then p's ranges `own`, in one process's order: the ranges migrate
    // scanned, then the last, those migrate appended from higher ranks.
    void addGhosts(const Particles& fromLower, Particles& p, const Ranges& own, const CellList& cells) const;
    // After the pair forces, the ghosts' forces made whole: each rank sends the forces of its first
    // and last planes, which its neighbours hold as ghosts in the same order (the sort's), for a
    // second pair loop in the step that reads the ghosts' forces (velocity Verlet's).
    void refreshGhostForces(Particles& p, const CellList& cells) const;
    // After a sort, this rank's own particles: [first, second) of the sorted arrays.
    std::pair<std::size_t, std::size_t> ownRange(const CellList& cells) const;
    // After a sort that held ghosts, [ghosts below][own][ghosts above]: keeps the own particles and
    // returns r such that one process's order of them is [r, size) then [0, r). The own particles
    // that fit go into the lower ghosts' places (as many as there were ghosts below) rather than the
    // whole slab moving down; r = 0 when nothing was moved.
    std::size_t dropGhosts(Particles& p, const CellList& cells) const;
    // For a sampler that runs between steps, when no ghosts are held: a copy of this rank's particles
    // `own` with copies of the next rank's first plane appended (taken at their current positions),
    // all that a traversal of the pairs of this rank's own planes reads (the half stencil goes up
    // along x): each pair of the box is then traversed by one rank.
    Particles withPlaneAbove(const Particles& own, const CellList& cells) const;
    // Every rank's particles on the root, in rank order: the single rank's order (elsewhere: empty).
    Particles gather(const Particles& p) const;
    // The same on every rank.
    Particles gatherToAll(const Particles& p) const;

private:
    // Every rank's particles in rank order, on the root or (everywhere) on every rank.
    Particles gatherParticles(const Particles& p, bool everywhere) const;

    const Communicator* comm_;
    SlabDecomposition slabs_;
    std::vector<std::uint8_t> farGhostSpecies_;  // by species index, 256 entries
    // What migrate found of the particles it kept, for addGhosts: those in the slab's first and last
    // planes (in one process's order).
    mutable std::vector<std::uint32_t> firstPlaneOwn_, lastPlaneOwn_;
    mutable ParticleRefs firstPlaneRefs_, lastPlaneRefs_;  // addGhosts' lists of what it sends, kept between steps
    // Kept between steps, so that a step allocates (and the kernel clears) no new pages for them.
    mutable std::vector<char> sendBelow_, sendAbove_, receiveBelow_, receiveAbove_;
};

}  // namespace dpd
