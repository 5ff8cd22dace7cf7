#pragma once
// Lattices of frozen wall particles behind a planar wall (docs/walls.md section 3.1).
//
// The lattice fills the slab of depth `thickness` behind the plane. Along the in-plane axes the
// spacing is adjusted slightly so that a whole number of cells fits the periodic box (the wall is
// then seamless across the boundary); the density actually built is reported.
#include "core/Box.hpp"
#include "walls/PlanarWallSettings.hpp"

#include <Eigen/Core>
#include <string>
#include <vector>

namespace dpd {

struct FrozenLatticeSettings {
    std::string lattice = "fcc";       // fcc | simpleCubic | layers
    double density = 3.0;              // fcc and simpleCubic (per area in 2-D)
    double thickness = 1.0;            // depth behind the plane that is filled (one cutoff is all that matters)
    std::vector<double> layerDepths;   // layers: distances behind the plane
    std::vector<double> layerSpacing;  // layers: in-plane spacing, one per in-plane active axis (increasing axis order)
    bool staggered = false;            // layers: every second layer shifted by half a cell along each in-plane axis
};

// Positions of the frozen particles behind an axis-aligned wall. Throws std::invalid_argument with a
// plain message for an oblique wall or impossible settings.
std::vector<Eigen::Vector3d> frozenLattice(const Box& box, const PlanarWallSettings& wall, const FrozenLatticeSettings& s);

}  // namespace dpd
