#pragma once
// The standard fluid with polymer chains (benchmarks and tests): chains of FENE springs (H 6, r_max 3)
// put in by the chain builder, the beads a species of their own ("polymer") with the fluid's pair
// coefficients for every pair.
#include "forces/BondedPairs.hpp"
#include "setup/StandardFluid.hpp"

namespace dpd {

struct ChainedFluidSettings {
    StandardFluidSettings fluid;
    long chains = 10;
    long length = 10;
    std::uint64_t chainSeed = 5;
    BondedPairs bondedPairs;
};

// Initialised, sorted, forces computed.
System makeChainedFluid(const ChainedFluidSettings& s);

}  // namespace dpd
