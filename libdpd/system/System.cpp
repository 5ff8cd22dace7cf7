#include "system/System.hpp"

#include "forces/PairForceLoop.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

namespace dpd {

namespace {

using PairKernelFunction = void (*)(Particles&, const PairLoopContext&, const PairForceParameters&);

template <class Evaluator>
void pairKernel(Particles& p, const PairLoopContext& ctx, const PairForceParameters& params) {
    const Evaluator eval(params);
    accumulatePairForces(p, ctx, eval, params.cutoff);
}

template <unsigned kTerms>
PairKernelFunction pairKernelFor(const PairForceParameters& params) {
    return withDpdWeight(params, [](auto weight) -> PairKernelFunction {
        return &pairKernel<DpdPairTerms<kTerms, decltype(weight)>>;
    });
}

constexpr unsigned kAllTerms = kConservativeTerm | kDissipativeTerm | kRandomTerm;

// The terms the integrators ask for: the whole force (with or without its conservative term), and
// the conservative and dissipative terms alone. Null: no term left to compute.
PairKernelFunction pairKernelForTerms(unsigned terms, const PairForceParameters& params) {
    switch (terms) {
    case 0u: return nullptr;
    case kAllTerms: return pairKernelFor<kAllTerms>(params);
    case kDissipativeTerm | kRandomTerm: return pairKernelFor<kDissipativeTerm | kRandomTerm>(params);
    case kConservativeTerm: return pairKernelFor<kConservativeTerm>(params);
    case kDissipativeTerm: return pairKernelFor<kDissipativeTerm>(params);
    default: throw std::invalid_argument("System::computeForces: no pair loop for this set of terms");
    }
}

// Adds the seconds from construction to destruction to *total, when total is set.
class ScopedTimer {
public:
    explicit ScopedTimer(double* total) : total_(total) {
        if (total_) start_ = std::chrono::steady_clock::now();
    }
    ~ScopedTimer() {
        if (total_) *total_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    }

private:
    double* total_;
    std::chrono::steady_clock::time_point start_;
};

}  // namespace

void System::initialise() {
    if (forceParameters.cutoff <= 0.0) throw std::invalid_argument("the cutoff must be positive");
    if (forceParameters.dt <= 0.0) throw std::invalid_argument("deltaT must be positive");
    if (forceParameters.kT < 0.0) throw std::invalid_argument("kT must not be negative");
    frozenOfSpecies_.assign(species.size(), 0);
    for (int s = 0; s < species.size(); ++s) frozenOfSpecies_[s] = species[s].frozen ? 1 : 0;
    // Fluctuation-dissipation fixes sigma; frozen particles never interact with each other.
    PairTable table(species.size());
    for (int a = 0; a < species.size(); ++a)
        for (int b = a; b < species.size(); ++b) {
            PairCoeffs c = pairs(a, b);
            c.sigma = std::sqrt(2.0 * c.gamma * forceParameters.kT);
            if (species[a].frozen && species[b].frozen) c.interact = false;
            table.set(a, b, c);
        }
    pairs = table;
    random_ = PairRandom(seed);
    cells_.setup(box, forceParameters.cutoff);
    if (!bonds.empty() && !bondPotential) throw std::invalid_argument("bonds without a bond potential");
    bonds.locate(particles);  // every particle is here, in a decomposed run too (before decompose)
    if (ranks && ranks->parallel()) decompose();
    conservative_ = pairs.anyConservative();
    buildForceTerms();
    wholePairKernel_ = pairKernelForTerms(conservative_ ? kAllTerms : kAllTerms & ~kConservativeTerm, forceParameters);
    if (box.dimension == 2)
        for (std::size_t i = 0; i < particles.size(); ++i) {
            particles.ry[i] = 0.5 * (box.lo.y() + box.hi.y());
            particles.vy[i] = 0.0;
        }
    frozenPerWall_ = walls.assignFrozenVelocities(particles, frozenOfSpecies_);
    if (domain_) domain_->communicator().sum(frozenPerWall_.data(), frozenPerWall_.size());
    wrapPositions();
    walls.recordPositions(particles, frozenOfSpecies_);
    initialised_ = true;
}

double ghostReachFor(double cutoff, const BondPotential* bonds) {
    return bonds ? std::max(cutoff, bonds->maxLength()) : cutoff;
}

double System::ghostReach() const {
    return ghostReachFor(forceParameters.cutoff, bonds.empty() ? nullptr : bondPotential.get());
}

void System::decompose() {
    // Ghost planes reach as far as a pair force, and with chains as far as a bond: each rank's bond
    // pass finds the other bead of its own beads' bonds among its ghosts.
    const int ghostPlanes = SlabDecomposition::ghostPlanesFor(ghostReach(), cells_.cellSize().x());
    std::shared_ptr<SlabDomain> domain;
    if (slabPlanes.empty()) {
        domain = SlabDomain::balanced(*ranks, cells_, particles, frozenOfSpecies_, ghostPlanes);
    } else {
        std::vector<int> cuts{0};
        for (int n : slabPlanes) cuts.push_back(cuts.back() + n);
        if (cuts.back() != cells_.cellsPerAxis()[0] || static_cast<int>(slabPlanes.size()) != ranks->size())
            throw std::invalid_argument("slab planes per rank do not fit the ranks and the box's planes");
        domain = std::make_shared<SlabDomain>(*ranks, SlabDecomposition::fromCuts(cuts, ghostPlanes));
    }
    // Beyond the plane at the face only the beads are needed, by the bond pass (no solvent there).
    domain->setFarGhostSpecies(bonds.bondedSpecies());
    domain_ = std::move(domain);
    domain_->keepOwned(particles, cells_);
    cells_.setHomePlanes(domain_->homePlanes(), ghostPlanes);
    bonds.holdPartOnly();
}

void System::wrapPositions() {
    const ScopedTimer timer(stepTimes ? &stepTimes->wrap : nullptr);
    const long n = static_cast<long>(particles.size());
#pragma omp parallel for schedule(static)
    for (long i = 0; i < n; ++i) box.wrapPoint(particles.rx[i], particles.ry[i], particles.rz[i]);
}

void System::sortByCell(SortForces forces) {
    // A second sort would have to compose the two orders to find the forces again.
    if (forces == SortForces::Leave && forcesLeftBySort_)
        throw std::logic_error("System::sortByCell: the forces the last sort left behind were never computed again");
    if (domain_) {
        // The particles that left for other ranks go, those that came in join, the neighbours' planes
        // come as ghosts; then all of them are sorted together.
        exchangeWithNeighbours();
    }
    const ScopedTimer timer(stepTimes ? &stepTimes->sort : nullptr);
    cells_.sortParticles(particles, frozenOfSpecies_, forces);
    // The particles that left are past the last cell: gone. Forces left behind keep their length
    // until the pair loop has read them.
    if (domain_) particles.shorten(cells_.sortedCount(), forces == SortForces::Leave);
    if (!bonds.empty()) {
        bonds.locate(particles);
        if (domain_) {
            const auto [first, end] = domain_->ownRange(cells_);
            bonds.setOwned(first, end);
        }
    }
    forcesLeftBySort_ = forces == SortForces::Leave;
    cellsFitPositions_ = true;
    movedAfterSort_.clear();
    if (!inStep_) walls.recordPositions(particles, frozenOfSpecies_);
}

void System::exchangeWithNeighbours() {
    dropGhosts();
    const auto n = static_cast<std::uint32_t>(particles.size());
    // One process's order of this rank's particles as stored (dropGhosts may have rotated them).
    const auto r = static_cast<std::uint32_t>(rotation_);
    SlabDomain::Ranges own = r > 0 ? SlabDomain::Ranges{{r, n}, {0, r}} : SlabDomain::Ranges{{0, n}};
    Particles fromLower;
    std::vector<std::uint32_t> leavers;
    {
        const ScopedTimer timer(stepTimes ? &stepTimes->migrate : nullptr);
        domain_->migrate(particles, own, cells_, deferredCrossings_, bonds.empty() ? nullptr : &bonds, fromLower, leavers);
    }
    const ScopedTimer timer(stepTimes ? &stepTimes->ghosts : nullptr);
    const auto withHigher = static_cast<std::uint32_t>(particles.size());
    own.emplace_back(n, withHigher);  // those from higher ranks follow this rank's own
    domain_->addGhosts(fromLower, particles, own, cells_);
    const auto withGhosts = static_cast<std::uint32_t>(particles.size());
    particles.append(fromLower);
    // The sort's order: from lower ranks, own, from higher ranks, then ghosts (planes of their own).
    SlabDomain::Ranges visit{{withGhosts, static_cast<std::uint32_t>(particles.size())}};
    visit.insert(visit.end(), own.begin(), own.end());
    visit.emplace_back(withHigher, withGhosts);
    cells_.setVisitOrder(std::move(visit));
    cells_.setDiscarded(std::move(leavers));
    rotation_ = 0;
    ghostsHeld_ = true;
}

Particles System::orderedParticles() const { return rotation_ == 0 ? particles : particles.rotated(rotation_); }

void System::computeForces(const ForcePass& pass) {
    if (!initialised_) throw std::logic_error("System::computeForces called before initialise()");
    if (pass.predictorShift != 0.0 && (hasVelocityDependentNonPairForces() || pass.pairTerms != kAllTerms))
        throw std::logic_error("System::computeForces: a velocity predictor needs the whole pair force as the only one reading v");
    if (pass.addToHeld && forcesLeftBySort_)
        throw std::logic_error("System::computeForces: adding to the forces a sort left behind");
    const ScopedTimer timer(stepTimes ? &stepTimes->forces : nullptr);
    // The force list, in the order its terms are added.
    addPairForces(pass);
    if (pass.otherTerms) {
        for (const auto& term : forceTerms_) term->add(*this, pass);
    }
    if (pass.ghostsHoldOwnersForces) refreshGhostForces();
}

void System::addPairForces(const ForcePass& pass) {
    const auto stepKey = static_cast<std::uint64_t>(step);
    if (pass.pairTerms == kAllTerms && !pass.addToHeld) {
        // The whole pair force is written over the old forces (with a predictor after reading them,
        // through the sort's order where it left them behind): no pass clearing them first.
        const std::uint32_t* forceOrder = forcesLeftBySort_ ? cells_.order().data() : nullptr;
        const PairLoopContext ctx{cells_, pairs, random_, stepKey, {pass.predictorShift, &frozenOfSpecies_, forceOrder}, true};
        wholePairKernel_(particles, ctx, forceParameters);
        forcesLeftBySort_ = false;
        return;
    }
    if (!pass.addToHeld) {
        particles.clearForces();
        forcesLeftBySort_ = false;
    }
    const unsigned terms = conservative_ ? pass.pairTerms : pass.pairTerms & ~kConservativeTerm;
    const PairKernel kernel = pairKernelForTerms(terms, forceParameters);
    if (kernel) kernel(particles, PairLoopContext{cells_, pairs, random_, stepKey}, forceParameters);
}

void System::buildForceTerms() {
    forceTerms_.clear();
    forceTermTypes_.clear();
    velocityTerms_ = false;
    const ForceTermRegistry& registry = forceTermRegistry();
    for (const std::string& type : registry.names()) {
        std::shared_ptr<const ForceTerm> term = registry.make(type, *this);
        if (!term) continue;
        velocityTerms_ = velocityTerms_ || term->features().has(Feature::velocityForce);
        forceTerms_.push_back(std::move(term));
        forceTermTypes_.push_back(type);
    }
}

WallStep System::wallStep() {
    return {particles, frozenOfSpecies_, box, random_, static_cast<std::uint64_t>(step), forceParameters.kT,
            forceParameters.dt, deferredCrossings_, {}};
}

WallCounters System::applyWalls() {
    if (walls.empty()) return {};
    const ScopedTimer timer(stepTimes ? &stepTimes->walls : nullptr);
    WallStep s = wallStep();
    return walls.reflect(s);
}

WallCounters System::afterMove(SortForces forces) {
    inStep_ = true;
    advanceClock();
    const WallCounters counters = applyWalls();
    sortByCell(forces);
    return counters;
}

void System::endStep() {
    completeWalls();
    inStep_ = false;
}

void System::completeWalls() {
    dropGhosts();
    for (const DeferredCrossing& d : deferredCrossings_) movedAfterSort_.push_back(d.id);  // kept sorted by id
    walls.completeStep(particles, frozenOfSpecies_, box, deferredCrossings_);
}

void System::refreshGhostForces() {
    if (domain_ && ghostsHeld_) domain_->refreshGhostForces(particles, cells_);
}

void System::dropGhosts() {
    if (!ghostsHeld_) return;
    if (forcesLeftBySort_) throw std::logic_error("System::dropGhosts: the forces the last sort left behind were never computed");
    rotation_ = domain_->dropGhosts(particles, cells_);
    ghostsHeld_ = false;
    cellsFitPositions_ = false;
    if (!inStep_) walls.recordPositions(particles, frozenOfSpecies_);
}

std::size_t System::countMobile() const {
    std::size_t n = 0;
    for (std::size_t i = 0; i < particles.size(); ++i) n += isFrozen(i) ? 0 : 1;
    return n;
}

}  // namespace dpd
