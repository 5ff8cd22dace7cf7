#pragma once
// Passes of a wall over all particles go a chunk of particles at a time: the shape first marks the
// particles of the chunk that may lie closer to the wall than the wall acts (behind it, in its bounce
// layer, within its tunable-slip reach) -- for a plane a test the compiler vectorises -- and only
// those are looked at one by one (species, rule, forces, counters). Few are: those near the wall.
#include "core/Particles.hpp"
#include "walls/WallShape.hpp"
#include "walls/WallStep.hpp"

#include <algorithm>
#include <cstdint>

namespace dpd {

inline constexpr long kWallChunk = 1024;  // particles the shape marks in one call

// visit(i) for every particle i of a mobile species (frozenOfSpecies[s] == 0) the shape marks within
// `reach`, in parallel; returns the sum of the counts visit returns.
template <class Visit>
WallCount forParticlesNear(const WallShape& shape, const Particles& p, const std::vector<std::uint8_t>& frozenOfSpecies,
                           double reach, const Visit& visit) {
    const long n = static_cast<long>(p.size());
    long returned = 0, crossed = 0, inside = 0;
#pragma omp parallel for reduction(+ : returned, crossed, inside) schedule(static)
    for (long c = 0; c < n; c += kWallChunk) {
        const long end = std::min(c + kWallChunk, n);
        std::uint8_t near[kWallChunk];
        shape.markWithin(p, c, end, reach, frozenOfSpecies, near);
        WallCount counts;
        for (long i = c; i < end; ++i)
            if (near[i - c] && !frozenOfSpecies[p.species[i]]) visit(static_cast<std::size_t>(i), counts);
        returned += counts.returned;
        crossed += counts.crossed;
        inside += counts.leftInside;
    }
    return {returned, crossed, inside};
}

}  // namespace dpd
