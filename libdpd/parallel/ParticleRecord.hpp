#pragma once
// One particle as bytes on the wire between ranks: everything a rank holds of it (the particle
// arrays' fields, the forces included: the Groot-Warren predictor and a restart read them).
#include "core/Particles.hpp"

#include <cstdint>
#include <vector>

namespace dpd {

struct ParticleRecord {
    double r[3], v[3], f[3];
    std::uint64_t id;
    std::uint8_t species;
};

// Appends particle i of p to the bytes.
void appendRecord(const Particles& p, std::size_t i, std::vector<char>& bytes);
// Writes particle i of p at `to` (sizeof(ParticleRecord) bytes).
void writeRecord(const Particles& p, std::size_t i, char* to);
// Appends `count` records read from `from` to p's arrays.
void appendRecords(const char* from, std::size_t count, Particles& p);

}  // namespace dpd
