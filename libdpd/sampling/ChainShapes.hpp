#pragma once
// The shape of each polymer chain (docs/methods.md section 4): end-to-end vector, radius of gyration
// and span along each axis, from the bond vectors (unwrapped, so a chain across the periodic boundary
// is whole), and the centre of mass in the box. Chains are linear: within a chain each bond starts at
// the bead where the one before it ends (the chain builder's order).
#include "core/Box.hpp"
#include "core/Particles.hpp"
#include "forces/ChainBonds.hpp"

#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace dpd {

struct ChainShape {
    long beads = 0;
    Eigen::Vector3d endToEnd{0, 0, 0};  // last bead minus first
    double gyration2 = 0.0;             // R_g^2 = mean |r - r_cm|^2 over the beads
    Eigen::Vector3d span{0, 0, 0};      // max - min of the bead coordinates along each axis
    Eigen::Vector3d centre{0, 0, 0};    // centre of mass, wrapped into the box
    double bondLength2 = 0.0;           // mean squared bond length
};

// One shape per chain, in chain order. std::invalid_argument for a chain whose bonds are not in
// order head to tail.
std::vector<ChainShape> chainShapes(const ChainBonds& bonds, const Particles& p, const Box& box);
// The same given the position of each chain's head (the first particle of its first bond), in chain
// order: for a decomposed run, whose heads lie on several ranks.
std::vector<ChainShape> chainShapes(const ChainBonds& bonds, const std::vector<Eigen::Vector3d>& heads, const Box& box);
// The ids of the chains' heads, in chain order.
std::vector<std::uint64_t> chainHeadIds(const ChainBonds& bonds);

}  // namespace dpd
