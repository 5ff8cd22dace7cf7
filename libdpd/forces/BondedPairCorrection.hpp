#pragma once
// bondedPairs none or weighted (forces/BondedPairs.hpp): after the pair loop has added the whole DPD
// force for every pair, takes back from each bonded pair within the cutoff the part that is left out,
// evaluated as the loop did (minimum image, the pair's random number of this step). The loop works
// with single-precision separations, so what remains of a removed force is round-off (~1e-7 of it).
#include "core/Box.hpp"
#include "core/Particles.hpp"
#include "core/Species.hpp"
#include "forces/BondedPairs.hpp"
#include "forces/ChainBonds.hpp"
#include "forces/DpdPairForce.hpp"
#include "random/PairRandom.hpp"

#include <cstdint>

namespace dpd {

struct BondedPairScene {
    const PairTable& pairs;
    const PairForceParameters& parameters;
    const PairRandom& random;
    std::uint64_t step;
};

void correctBondedPairs(const ChainBonds& bonds, const BondedPairs& rule, const BondedPairScene& scene,
                        const Box& box, Particles& p);

}  // namespace dpd
