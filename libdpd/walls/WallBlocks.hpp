#pragma once
// Passes of a planar wall over all particles go block by block, and look at particles one by one
// (species, rule, forces, counters) only in the blocks where one lies closer to the wall than the
// wall acts (behind it, in its bounce layer, within its tunable-slip reach): a test of a whole block
// that the compiler vectorises. Few blocks hold one: those near the wall, and those of the walls' own
// frozen particles.
#include "core/Particles.hpp"
#include "walls/PlanarWallSettings.hpp"

namespace dpd {

inline constexpr long kWallBlock = 16;

// Whether any of particles [begin, end) is less than `reach` in front of wall w (or behind it).
inline bool anyWithin(const PlanarWallSettings& w, const Particles& p, long begin, long end, double reach) {
    bool any = false;
    for (long i = begin; i < end; ++i) any |= w.signedDistance(p.rx[i], p.ry[i], p.rz[i]) < reach;
    return any;
}

}  // namespace dpd
