#pragma once
// Everything that evolves in a run: box, particles, interactions, external forces and walls, and the
// clock. Integrators move it; the case reader builds it; monitors and samplers read it.
#include "core/Box.hpp"
#include "core/Particles.hpp"
#include "core/Species.hpp"
#include "forces/BodyForce.hpp"
#include "forces/BondPotential.hpp"
#include "forces/BondedPairs.hpp"
#include "forces/ChainBonds.hpp"
#include "forces/DpdPairForce.hpp"
#include "neighbour/CellList.hpp"
#include "parallel/SlabDomain.hpp"
#include "system/ForcePass.hpp"
#include "system/ForceTerm.hpp"
#include "random/PairRandom.hpp"
#include "walls/WallList.hpp"

#include <cstdint>
#include <vector>

namespace dpd {

struct PairLoopContext;

// Seconds spent in the parts of a step that System does itself, summed over the steps while a
// System's stepTimes points here (dpdBenchmark's breakdown; off, and free, by default).
struct StepTimes {
    double wrap = 0.0;    // wrapPositions (a step's wrapping is done by sortByCell)
    double sort = 0.0;    // sortByCell
    double forces = 0.0;  // computeForces: the pair force and the force terms after it
    double walls = 0.0;   // applyWalls
    double migrate = 0.0; // a decomposed run's particles sent to the ranks they moved to (in sortByCell)
    double ghosts = 0.0;  // and the neighbours' planes taken in as ghosts (in sortByCell)
};

// How far from its slab a decomposed run's rank needs ghosts: the cutoff, or with bonds (a potential
// given) the longest bond when that is longer.
double ghostReachFor(double cutoff, const BondPotential* bonds);

class System {
public:
    Box box;
    Particles particles;
    SpeciesTable species;
    PairTable pairs;
    PairForceParameters forceParameters;  // cutoff, weight exponent, kT, dt
    std::uint64_t seed = 1;
    std::shared_ptr<const BodyForce> bodyForce = noBodyForce();
    WallList walls;  // in the order they act: the planar walls, then a wall of any shape (geometry)
    ChainBonds bonds;  // polymer chains; empty without
    std::shared_ptr<const BondPotential> bondPotential;  // the bonds' spring; needed when there are bonds
    BondedPairs bondedPairs;  // how much of the DPD pair force bonded particles feel
    std::int64_t step = 0;
    double time = 0.0;
    StepTimes* stepTimes = nullptr;  // when set, the methods below add their times to it
    // The ranks that run this system together: with more than one, initialise() cuts the box in
    // slabs along x and keeps this rank's particles (parallel/SlabDomain.hpp); null or one rank: all.
    const Communicator* ranks = nullptr;
    std::vector<int> slabPlanes;  // cell planes along x per rank, in rank order; empty: balanced

    // Call once the fields above are set: lays out the cells, fixes sigma from fluctuation-
    // dissipation, marks frozen pairs as non-interacting, picks the pair evaluator that does just
    // the terms this scene uses, and gives the frozen particles behind each wall the wall's velocity.
    void initialise();

    bool isFrozen(std::size_t i) const { return frozenOfSpecies_[particles.species[i]] != 0; }
    const std::vector<std::uint8_t>& frozenOfSpecies() const { return frozenOfSpecies_; }
    const PairRandom& random() const { return random_; }
    // How many frozen particles each wall owns (moves with its velocity), as set by initialise().
    const std::vector<long>& frozenPerWall() const { return frozenPerWall_; }
    const CellList& cells() const { return cells_; }
    // Whether the particles are stored as the last sort put them in cells (not once a decomposed run
    // dropped its ghosts); those whose crossings completed at the end of the step have moved since
    // (their ids, increasing: movedAfterSort).
    bool cellsFitPositions() const { return cellsFitPositions_; }
    const std::vector<std::uint64_t>& movedAfterSort() const { return movedAfterSort_; }
    // This rank's slab of a decomposed run; null when one rank runs the whole box.
    const SlabDomain* domain() const { return domain_.get(); }
    // The ranks' sums of a count (the count itself on one rank).
    long sumOverRanks(long n) const { return domain_ ? domain_->communicator().sum(n) : n; }
    bool usesConservativeForce() const { return conservative_; }
    // How far from its slab a decomposed run's rank needs ghosts (ghostReachFor).
    double ghostReach() const;
    double dt() const { return forceParameters.dt; }

    // Brings every position back into the box.
    void wrapPositions();
    // Brings every position back into the box and reorders the particles by cell (call after moving,
    // before computing forces). With SortForces::Leave the forces stay in the order before the sort,
    // for an integrator whose next computeForces() writes over them (a predictor reads them through
    // the sort's order); until then they belong to no particle in particular. Throws
    // std::logic_error for a second Leave before the forces were computed again.
    void sortByCell(SortForces forces = SortForces::Move);
    // The forces of the current positions and velocities that the pass asks for (system/ForcePass.hpp;
    // by default all of them): the DPD pair force (keyed to the current step's random numbers), then
    // the registered force terms this scene has (system/ForceTermTypes.cpp: the bonded pairs' share
    // taken back, the body force, the bonds' springs, the walls' forces), added in that order. Requires sortByCell() since the last move. Throws std::logic_error
    // for a predictor where a force besides the pair force reads the velocities, or a pass that adds
    // to forces a sort left behind.
    void computeForces(const ForcePass& pass = ForcePass::whole());
    // What the last bond pass found: a broken bond (at or beyond the potential's length) stops a run.
    const BondPassResult& bondPass() const { return bondPass_; }
    void recordBondPass(const BondPassResult& found) { bondPass_ = found; }
    // Whether any force term after the pair force reads the velocities (walls' friction, the bonded
    // pairs' share of the dissipative force taken back); known once initialise() built the terms.
    bool hasVelocityDependentNonPairForces() const { return velocityTerms_; }
    // The registered types of the force terms this scene has, in the order they are added.
    const std::vector<std::string>& forceTermTypes() const { return forceTermTypes_; }
    // What the walls act on at this step.
    WallStep wallStep();
    // The boundary phase once the particles have moved: the clock moves on one step, each wall
    // returns the fluid particles that crossed into it (before wrapping: a particle that crossed a
    // wall lying on a box face is mirrored back, not carried round to the far side), then sortByCell
    // (a decomposed run's migration and ghosts included), ready for new forces. Counts per wall, in
    // the list's order.
    WallCounters afterMove(SortForces forces);
    // The boundary phase once the step's velocities are complete: the walls finish what they left for
    // the end of the step (bounce-forward crossings: mirrored and reversed with the velocity the step
    // gave them) and record where the next step starts; a decomposed run first lets go of the ghosts
    // the last sort took in (dropGhosts).
    void endStep();
    // True if the point is inside the solid of any wall.
    bool isInsideSolid(double x, double y, double z) const { return walls.isInsideSolid({x, y, z}); }
    // In a decomposed run, drops the neighbours' particles that the last sortByCell added for the pair
    // forces, so that the particles are this rank's own again (nothing on one rank). The particles
    // may then be stored out of one process's order (rotated: what does not depend on their order
    // reads `particles`; what does, a snapshot, reads orderedParticles()).
    void dropGhosts();
    // The particles in the order one process would hold them (a copy).
    Particles orderedParticles() const;
    // Moves the clock on by one step.
    void advanceClock() { ++step; time += forceParameters.dt; }

    // Diagnostics.
    std::size_t countMobile() const;

private:
    // The registered force terms this scene has (computeForces adds them after the pair force).
    void buildForceTerms();
    // The pair terms the pass asks for, written over the forces held or added to them.
    void addPairForces(const ForcePass& pass);
    WallCounters applyWalls();
    void completeWalls();
    void refreshGhostForces();
    void decompose();     // this rank's slab of the box (initialise, with several ranks)
    // Migration and ghosts before a decomposed run's sort, and the sort's order for them.
    void exchangeWithNeighbours();

    using PairKernel = void (*)(Particles&, const PairLoopContext&, const PairForceParameters&);
    CellList cells_;
    std::shared_ptr<const SlabDomain> domain_;
    bool ghostsHeld_ = false;  // the particles hold the neighbours' ghosts (from sortByCell to dropGhosts)
    // Between afterMove and endStep. A reorder outside a step has the walls record the particles'
    // positions again, in their new order (WallShape::recordPositions).
    bool inStep_ = false;
    std::size_t rotation_ = 0;  // one process's order of the particles is [rotation_, n) then [0, rotation_)
    PairRandom random_;
    std::vector<std::uint8_t> frozenOfSpecies_;
    PairKernel wholePairKernel_ = nullptr;  // every term this scene uses (no conservative one where a = 0)
    std::vector<DeferredCrossing> deferredCrossings_;
    std::vector<long> frozenPerWall_;
    BondPassResult bondPass_;
    bool conservative_ = true;
    std::vector<std::shared_ptr<const ForceTerm>> forceTerms_;  // after the pair force, in the registry's order
    std::vector<std::string> forceTermTypes_;
    bool velocityTerms_ = false;  // some term reads the velocities
    bool initialised_ = false;
    bool forcesLeftBySort_ = false;  // the last sort left the forces behind (SortForces::Leave)
    bool cellsFitPositions_ = false;
    std::vector<std::uint64_t> movedAfterSort_;
};

}  // namespace dpd
