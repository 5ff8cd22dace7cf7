#pragma once
// Polymer chains in a run decomposed over ranks (docs/parallel.md section 6). Every rank holds every
// bond, but a pass follows only the bonds of the rank's own beads (forces/ChainBonds::here), so a
// bond's vector is current on the ranks of its two beads alone. What the ranks share about chains:
// a bead's bond vectors go with it when it changes rank (SlabDomain::migrate); one pass's result is
// the same on every rank; the whole run's bonds and chain heads are gathered on the first rank for
// a snapshot or the chains' shapes.
#include "core/Bonds.hpp"
#include "core/Particles.hpp"
#include "forces/ChainBonds.hpp"
#include "parallel/Communicator.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace dpd {

// Where each particle of `own` lies, by id, for ids up to maxId (kNotHeld for the others).
inline constexpr std::uint32_t kNotHeld = 0xffffffffu;
std::vector<std::uint32_t> indexById(const Particles& own, std::uint64_t maxId);
// The largest particle id of the bonds.
std::uint64_t maxBondedId(const Bonds& bonds);

// One bond's vector as it travels between ranks.
struct BondVectorRecord {
    std::uint64_t bond;  // its index in ChainBonds::bonds()
    double x, y, z;
};

// Appends the vectors of the bonds of particle `id` to `out` and adds their number to `count`.
void appendBondVectors(const ChainBonds& bonds, std::uint64_t id, std::vector<char>& out, std::uint64_t& count);
// Takes n records from `at` into the bonds' vectors.
void takeBondVectors(const char* at, std::uint64_t n, ChainBonds& bonds);

// A pass's result as one process would find it, the same on every rank: the longest bond, and the
// first broken bond over the ranks (its length from a rank that held both its particles, else
// kUnseenBondLength).
BondPassResult agreedOverRanks(const Communicator& comm, const BondPassResult& mine);

// On the root, `bonds` (which every rank holds whole) with each vector from the rank that owns the
// bond's first particle (`own`: this rank's particles); elsewhere `bonds` as given.
Bonds bondsOnRoot(const Communicator& comm, const Bonds& bonds, const Particles& own);

// On the root, the positions of the particles `ids`, in that order (each is owned by one rank, `own`
// this rank's particles); elsewhere empty.
std::vector<Eigen::Vector3d> positionsOnRoot(const Communicator& comm, const std::vector<std::uint64_t>& ids,
                                             const Particles& own);

}  // namespace dpd
