#pragma once
// Particles on the wire as columns: a count, then each field of all of them in turn (positions,
// velocities, forces, ids, species). The ghosts a rank takes in every step go into the ends of its
// arrays one copy per field, where a record per particle (ParticleRecord) was scattered field by
// field over eleven arrays (at 256,000 particles a rank, 0.38 ms a step to take them in, now 0.25).
#include "core/Particles.hpp"

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace dpd {

// Particles to send, in order: the arrays that hold each, and its index there.
using ParticleRefs = std::vector<std::pair<const Particles*, std::uint32_t>>;

// The bytes of `count` particles as columns (a multiple of eight).
std::size_t columnBytes(std::size_t count);
// Writes the listed particles as columns at `to`; returns the end of what it wrote.
char* writeColumns(const ParticleRefs& list, char* to);
// Appends to p the particles of the columns at `from`; returns the end of what it read.
const char* appendColumns(const char* from, Particles& p);

}  // namespace dpd
