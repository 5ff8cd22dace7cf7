#pragma once
// The fluctuation-dissipation step of Shardlow's splitting (T. Shardlow, SIAM J. Sci. Comput. 24,
// 1267, 2003): the dissipative and random forces of each pair, on their own, over a time dt, at fixed
// positions, applied pair after pair.
#include <cstdint>

namespace dpd {

class System;

// Advances the velocities of every interacting pair by the exact solution of the pair's
// Ornstein-Uhlenbeck process over dt (see ShardlowSweep.cpp), pair after pair in the fixed order of
// integrators/PairSweep.hpp. `sweep` (>= 0) numbers the sweeps made within one step, so that each
// draws its own random numbers. Requires sortByCell() since the last move.
void shardlowSweep(System& sys, double dt, std::uint32_t sweep);

}  // namespace dpd
