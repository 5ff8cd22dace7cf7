#pragma once
// The bonds of a snapshot (polymer chains) in its HDF5 file, written only when there are bonds
// (M = number of bonds, N = number of particles):
//
//   /bonds/pairs              uint64  (M, 2)   the ids of the two bonded particles
//   /bonds/vector             float64 (M, 3)   r_second - r_first, not wrapped (core/Bonds.hpp)
//   /bonds/chain              int64   (M)      the chain of each bond
//   /particles/chain          int64   (N)      the chain of each particle, -1 outside chains
//   /xdmf/bondConnectivity    int64   (M, 2)   the rows of the two particles: ParaView draws the bonds
//                                              as line cells over the particle positions. Not read.
//
// Example:  f = h5py.File("0/particles.h5"); pairs = f["bonds/pairs"][:]; chain = f["particles/chain"][:]
#include "io/Hdf5File.hpp"
#include "io/Snapshot.hpp"

namespace dpd {

inline constexpr const char* bondPairsName = "bonds/pairs";
inline constexpr const char* bondVectorName = "bonds/vector";
inline constexpr const char* bondChainName = "bonds/chain";
inline constexpr const char* particleChainName = "particles/chain";
inline constexpr const char* bondConnectivityName = "xdmf/bondConnectivity";

// std::invalid_argument for bonds the reader would refuse (lengths, an id no particle has).
void checkBondsConsistent(const Snapshot& s);
void writeBonds(Hdf5Writer& file, const Snapshot& s);
// Reads the bonds when the file has them; IoError naming the file, dataset and row for a bond to a
// missing particle, a particle bonded to itself, a vector that is not finite or does not join the two
// positions (up to whole box lengths), or a particle in two chains.
void readBonds(const Hdf5Reader& file, Snapshot& s);

}  // namespace dpd
