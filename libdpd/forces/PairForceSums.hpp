#pragma once
// The pair forces summed per particle while the pair loop runs, before they go to the particles.
//
// Each particle's sum is one 32-byte entry (x, y, z and a fourth lane that keeps entries aligned to
// a vector), so a pair adds its force to each of its two particles with one four-lane read-modify-
// write. Into the particles' separate fx, fy, fz arrays it took six scalar ones, and consecutive
// pairs often share a particle, each waiting for the store before it: measured on the search's own
// pair order, 4.0 ns a pair into the separate arrays against 1.8-2.3 ns into the entries. The sums go
// to the particles in one pass at the end of the loop, which leaves them zero for the next.
#include "core/Particles.hpp"

#include <cstddef>
#include <vector>

namespace dpd {

struct alignas(32) ForceSum {
    double x = 0.0, y = 0.0, z = 0.0, unused = 0.0;
};

class PairForceSums {
public:
    // n entries, all zero (they are zero between loops: handTo clears what it has handed on).
    ForceSum* prepare(std::size_t n);
    // The sums added to p's forces (or written over them with `replace`), then cleared.
    void handTo(Particles& p, bool replace);
    std::size_t capacityBytes() const { return sums_.capacity() * sizeof(ForceSum); }

private:
    ParticleArray<ForceSum> sums_;
};

// The pair loop's sums: one set per process (pair loops run one at a time).
PairForceSums& sharedPairForceSums();

}  // namespace dpd
