#pragma once
// Traversal of all interacting pairs through the cell list, in parallel and deterministically.
//
// Each cell meets half of its neighbours (the 13-cell half stencil in 3-D, 4 in 2-D) whose x offset
// is 0 or +1, so processing the slab of cells at x index ix writes forces only into slabs ix and
// ix + 1. Slabs are done in colours: all even slabs (in parallel), then all odd slabs, then the last
// slab when the count is odd. No two threads ever write the same particle, and every particle
// receives its contributions in an order fixed by the cell layout alone: forces, and so trajectories,
// are bit-identical on any number of threads.
//
// Inside a slab the work goes by rows of cells (ix, iy fixed) in three passes (PairForceLoop.tpp):
// find the pairs within the cutoff (in single precision on cell-local positions, PairInputs.hpp;
// the candidates of each home cell are the half stencil's columns along z, the four beside the home
// column staged once per row, PairSearch.hpp), evaluate the force of each in a loop the compiler
// vectorises (random numbers included; the force itself in double precision), then add the forces
// to per-particle sums in the order the pairs were found (PairForceSums.hpp), which go to the
// particles at the end.
// Frozen-frozen pairs are not even visited when the cell list keeps frozen particles apart.
#include "core/Particles.hpp"
#include "core/Species.hpp"
#include "forces/DpdPairForce.hpp"
#include "forces/PairInputs.hpp"
#include "neighbour/CellList.hpp"
#include "random/PairRandom.hpp"

#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <vector>

namespace dpd {

struct StencilEntry {
    int dx, dy, dz;
};

// The half stencil as columns along z: cells (dx, dy, dzFirst) ... (dx, dy, dzFirst + cells - 1)
// of the home cell's neighbours, so that each column's cells follow each other in memory (but where
// the column wraps through the box along z). The home column (0, 0) holds the home cell and the one
// above it; the others (dx = +1, or dx = 0 and dy = +1) three cells each.
struct StencilColumn {
    int dx, dy, dzFirst, cells;
};
std::vector<StencilColumn> halfStencilColumns(const Box& box);

// Half stencil: the cell itself first, then neighbours with dx = +1, or dx = 0 and dy = +1, or
// dx = dy = 0 and dz = +1. Along an inactive (2-D) axis only offset 0 is kept.
std::vector<StencilEntry> halfStencil(const Box& box);

// Groot and Warren's predicted velocities v~ = v + shift f, made by the pair loop as it reads the
// velocities (no pass of their own over the particles, and v itself is left alone): with shift != 0
// the pair forces see v + shift f for the particles of every species not marked frozen (a frozen
// particle keeps its wall's velocity), f being the forces the particles hold when the loop starts,
// and the loop then *replaces* the forces with the pair forces instead of adding to them.
struct VelocityPredictor {
    double shift = 0.0;
    const std::vector<std::uint8_t>* frozenOfSpecies = nullptr;  // null or all zero: nothing frozen
    // Null, or the last sort's order where it left the forces behind (SortForces::Leave): then
    // particle k's force f is p.f[forceOrder[k]].
    const std::uint32_t* forceOrder = nullptr;
};

struct PairLoopContext {
    const CellList& cells;
    const PairTable& table;
    const PairRandom& random;
    std::uint64_t step;
    VelocityPredictor predictor{};
    // The pair forces written over p.f instead of added to it (always so with a predictor): for a
    // caller whose forces start from the pair forces, which then needs no pass clearing them.
    bool replaceForces = false;
};

// What an evaluator needs beyond the separation. An evaluator that declares
// `static constexpr bool kUsesRandom = false` is passed zeta = 0 and the loop draws no random numbers;
// one that declares `kUsesVelocity = false` is passed rDotV = 0 and the loop gathers no velocities.
// Without the declaration both are computed.
template <class E, class = void>
struct EvaluatorUsesRandom : std::true_type {};
template <class E>
struct EvaluatorUsesRandom<E, std::void_t<decltype(E::kUsesRandom)>> : std::bool_constant<E::kUsesRandom> {};
template <class E, class = void>
struct EvaluatorUsesVelocity : std::true_type {};
template <class E>
struct EvaluatorUsesVelocity<E, std::void_t<decltype(E::kUsesVelocity)>> : std::bool_constant<E::kUsesVelocity> {};

// Adds to p.f the force of every interacting pair closer than the cutoff (or, with ctx.replaceForces
// or ctx.predictor's shift != 0, replaces p.f with those forces, see VelocityPredictor). The evaluator gives the
// force over r for one pair: double forceOverR(double r2, double rDotV, const PairCoeffs&, double zeta),
// zeta being ctx.random.pairUniform(step, id_i, id_j). The particles must be sorted by ctx.cells.
template <class Evaluator>
void accumulatePairForces(Particles& p, const PairLoopContext& ctx, const Evaluator& eval, double cutoff);

// Bytes held by the pair loop: its per-thread pair buffers (all threads together), its inputs and its force sums.
std::size_t pairLoopScratchBytes();

}  // namespace dpd

#include "forces/PairForceLoop.tpp"
