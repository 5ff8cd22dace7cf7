#pragma once
// Particle snapshots: one HDF5 file per time directory (<case>/<time>/particles.h5), plus an XDMF
// companion (particles.xmf) so that ParaView opens the particles directly.
//
// HDF5 layout ("dpdFoamLike-snapshot-1"; N = number of particles; arrays are row-major, so h5py
// gives numpy arrays of the shapes below):
//
//   /particles/position   float64 (N, 3)   x y z; in 2-D (x-z plane) y is 0
//   /particles/velocity   float64 (N, 3)
//   /particles/force      float64 (N, 3)   force per unit mass at this time; restarts of the
//                                          Groot-Warren scheme need f(t)
//   /particles/id         uint64  (N)      permanent particle identity
//   /particles/species    int32   (N)      index into the speciesNames attribute
//   /xdmf/connectivity    int32 or int64 (N)   0..N-1, one vertex cell per particle: ParaView's
//                                          Xdmf3 reader builds cells only from explicit
//                                          connectivity. Ignored by readSnapshot.
//
//   root attributes:
//     format         string        "dpdFoamLike-snapshot-1"
//     time           float64
//     step           int64
//     dimension      int64         2 or 3
//     boxLo, boxHi   float64 (3)
//     speciesNames   strings (nSpecies)   variable-length UTF-8
//     speciesFrozen  int64 (nSpecies)     1 = frozen (wall) species, 0 = mobile
//
//   bonds (polymer chains), only where there are some: io/SnapshotBonds.hpp
//
// Example:  f = h5py.File("0.5/particles.h5"); r = f["particles/position"][:]; t = f.attrs["time"]
#include "core/Bonds.hpp"
#include "core/Box.hpp"
#include "core/Particles.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace dpd {

inline constexpr const char* snapshotFileName = "particles.h5";
inline constexpr const char* snapshotXdmfFileName = "particles.xmf";
inline constexpr const char* snapshotFormat = "dpdFoamLike-snapshot-1";

struct Snapshot {
    Box box;
    Particles particles;                     // forces are stored too
    std::vector<std::string> speciesNames;   // index = Particles::species value
    std::vector<bool> speciesFrozen;         // same length as speciesNames; empty means none frozen
    double time = 0.0;
    std::int64_t step = 0;
    Bonds bonds;                             // empty without polymer chains
};

// Writes <timeDir>/particles.h5 and <timeDir>/particles.xmf (Polyvertex topology; attributes
// velocity, force, species, id). Each file is written whole or not at all (temporary file +
// rename); the .h5 goes first so the .xmf never points at a missing file. Creates timeDir if
// missing and replaces existing files. An inconsistent snapshot (array lengths, species index
// without a name) is std::invalid_argument; a file that cannot be written is IoError.
void writeSnapshot(const std::string& timeDir, const Snapshot& s);

// Reads a file written by writeSnapshot and validates it: shapes, the format tag, species
// indices below the number of species. Anything wrong is an IoError naming file and dataset.
Snapshot readSnapshot(const std::string& h5File);

}  // namespace dpd
