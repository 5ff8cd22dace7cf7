#pragma once
// Traversal of all interacting pairs through the cell list, in parallel and deterministically.
//
// Each cell meets half of its neighbours (the 13-cell half stencil in 3-D, 4 in 2-D) whose x offset
// is 0 or +1, so processing the slab of cells at x index ix writes forces only into slabs ix and
// ix + 1. Slabs are done in colours: all even slabs (in parallel), then all odd slabs, then the last
// slab when the count is odd. No two threads ever write the same particle, and every particle
// receives its contributions in an order fixed by the cell layout alone: forces, and so trajectories,
// are bit-identical on any number of threads.
#include "core/Particles.hpp"
#include "core/Species.hpp"
#include "forces/DpdPairForce.hpp"
#include "neighbour/CellList.hpp"
#include "random/PairRandom.hpp"

#include <cstdint>
#include <vector>

namespace dpd {

struct StencilEntry {
    int dx, dy, dz;
};

// Half stencil: the cell itself first, then neighbours with dx = +1, or dx = 0 and dy = +1, or
// dx = dy = 0 and dz = +1. Along an inactive (2-D) axis only offset 0 is kept.
std::vector<StencilEntry> halfStencil(const Box& box);

struct PairLoopContext {
    const CellList& cells;
    const PairTable& table;
    const PairRandom& random;
    std::uint64_t step;
};

template <class Evaluator>
void accumulatePairForces(Particles& p, const PairLoopContext& ctx, const Evaluator& eval, double cutoff);

}  // namespace dpd

#include "forces/PairForceLoop.tpp"
