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
    double forces = 0.0;  // computeForces: pair forces and body force
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
    // Forces at the current positions and velocities: pair forces (keyed to the current step's random
    // numbers) plus the body force, plus the forces of walls that act with forces (tunable slip).
    // Requires sortByCell() since the last move.
    void computeForces();
    // The same with the velocities predicted as v + predictorShift f (f the forces held on entry;
    // frozen particles keep theirs), in the pair loop's pass over the particles: v itself is left
    // alone. Only where the pair forces are the only velocity-dependent ones (see below); throws
    // std::logic_error otherwise.
    void computeForces(double predictorShift);
    // The same, the walls' friction reading the velocities given instead of the particles' own.
    void computeForces(const VelocityColumns& wallFriction);
    // Adds the bonds' spring forces (nothing without bonds); part of computeForces, and of the
    // conservative forces of integrators that split the pair force.
    void addBondForces();
    // What the last bond pass found: a broken bond (at or beyond the potential's length) stops a run.
    const BondPassResult& bondPass() const { return bondPass_; }
    // Whether any force but the pair forces depends on the velocities (walls' forces, e.g. friction).
    // (Taking back part of a bonded pair's DPD force is one: it reads the velocities.)
    bool hasVelocityDependentNonPairForces() const { return wallForces_ || bondedPairsCorrected(); }
    bool bondedPairsCorrected() const { return !bonds.empty() && !bondedPairs.keepsAll(); }
    // Each wall returns the fluid particles that crossed into it during the last move (call before
    // wrapping, that is before wrapPositions or sortByCell). Counts per wall, in the list's order.
    WallCounters applyWalls();
    // True if the point is inside the solid of any wall.
    bool isInsideSolid(double x, double y, double z) const { return walls.isInsideSolid({x, y, z}); }
    // Finishes what the walls left for the end of the step (bounce-forward crossings: mirrored and
    // reversed with the velocity the step gave them) and lets them record where the next step starts.
    // Every integrator calls it once the velocities of the step are complete. In a decomposed run it
    // first lets go of the ghosts the last sort took in (dropGhosts).
    void completeWalls();
    // In a decomposed run, the ghosts' forces made those their owners computed (nothing on one rank):
    // for a second pair loop in a step that reads them.
    void refreshGhostForces();
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
    // Every computeForces: the pair loop's predictor shift and the velocities the walls' friction reads
    // (null: the particles').
    void computeForces(double predictorShift, const VelocityColumns& wallFriction);
    WallStep wallStep();  // what the walls act on at this step
    void decompose();     // this rank's slab of the box (initialise, with several ranks)
    // Migration and ghosts before a decomposed run's sort, and the sort's order for them.
    void exchangeWithNeighbours();

    using PairKernel = void (*)(Particles&, const PairLoopContext&, const PairForceParameters&);
    CellList cells_;
    std::shared_ptr<const SlabDomain> domain_;
    bool ghostsHeld_ = false;  // the particles hold the neighbours' ghosts (from sortByCell to dropGhosts)
    std::size_t rotation_ = 0;  // one process's order of the particles is [rotation_, n) then [0, rotation_)
    PairRandom random_;
    std::vector<std::uint8_t> frozenOfSpecies_;
    PairKernel pairKernel_ = nullptr;
    std::vector<DeferredCrossing> deferredCrossings_;
    std::vector<long> frozenPerWall_;
    BondPassResult bondPass_;
    bool conservative_ = true;
    bool wallForces_ = false;  // some wall acts on the fluid with forces
    bool initialised_ = false;
    bool forcesLeftBySort_ = false;  // the last sort left the forces behind (SortForces::Leave)
    bool cellsFitPositions_ = false;
    std::vector<std::uint64_t> movedAfterSort_;
};

}  // namespace dpd
