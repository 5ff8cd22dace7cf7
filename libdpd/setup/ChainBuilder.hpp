#pragma once
// Polymer chains put into a built case (docs/methods.md section 4): nChain random walks of ChainLen
// beads, each bond length drawn from the Boltzmann distribution of the case's bond potential (the
// chains start with their equilibrium bond statistics), every bead clear of the walls and grains by a
// set distance. Each bead takes the place of the nearest fluid particle, which becomes the bead (its
// velocity kept): the density and temperature stay as built.
#include "core/Box.hpp"
#include "forces/BondPotential.hpp"
#include "io/Snapshot.hpp"

#include <cstdint>
#include <functional>
#include <string>

namespace dpd {

class Dictionary;

struct ChainSettings {
    long chains = 0;               // nChain
    long length = 0;               // ChainLen: beads per chain
    std::string beadSpecies;       // the species the beads become (mobile)
    std::string fluidSpecies;      // the species whose particles become beads
    double clearance = 0.5;        // the least distance from a bead to a solid
    std::uint64_t seed = 1;
    double kT = 1.0;               // of the bond-length distribution

    // system/insertChainsDict: chains, length, species, replace, clearance, seed. Errors name the keyword.
    static ChainSettings read(const Dictionary& d, double kT);
};

struct ChainReport {
    long beads = 0;
    long restarts = 0;         // walks started again after a dead end next to a solid
    double meanBondLength = 0.0;
    double largestMove = 0.0;  // the farthest a fluid particle was moved to become a bead
};

// Distance from a point to the nearest solid (positive in the fluid; +infinity without walls).
using ClearanceFunction = std::function<double(const Eigen::Vector3d&)>;

// Adds the chains to the snapshot's particles and bonds. std::invalid_argument when the snapshot
// already holds bonds, a species is missing, or there are not enough fluid particles or room.
ChainReport insertChains(Snapshot& s, const ChainSettings& settings, const BondPotential& bond,
                         const ClearanceFunction& clearance);

}  // namespace dpd
