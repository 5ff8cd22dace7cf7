#pragma once
// blockFrozenWall: the initial state of a planar channel (system/blockFrozenWallDict).
//
//   box    { min (-30 -1.5 -21); max (30 1.5 21); }   // the whole periodic box, walls included
//   fluid  { species fluid; density 4; initialFlow { type poiseuille; nu 0.277; } }
//                                                     // initialFlow optional: see setup/InitialFlow.hpp
//   wall                                              // frozen particles behind every wall of
//   {                                                 // constant/dpdProperties
//       species   wall;
//       lattice   fcc;          // fcc | simpleCubic | layers
//       density   4;            // fcc, simpleCubic
//       thickness 1;            // depth of the lattice behind each wall; default one cutoff. Points
//                               // deeper than one cutoff are left out (they never meet the fluid)
//                               // unless the wall's reflection is none
//       layers    (0.15 0.35 0.75);   // layers only: depths behind the wall
//       spacing   (0.5 1);            // layers only: in-plane spacing per in-plane axis
//   }
//
// Fluid fills the box outside the walls at random, with Maxwellian velocities at kT and no net
// momentum (plus the initial flow, if one is asked for); frozen particles move with their wall's velocity.
#include "io/Snapshot.hpp"
#include "setup/InitialFlow.hpp"

#include <string>
#include <vector>

namespace dpd {

class Dictionary;
struct DpdModel;

struct BlockFrozenWallReport {
    std::size_t fluid = 0;
    std::vector<std::size_t> frozenPerWall;   // built: within one cutoff of the fluid
    std::vector<std::size_t> latticePerWall;  // the lattice over the whole thickness
    std::vector<std::string> wallNames;
    double fluidVolume = 0.0;
    InitialFlow initialFlow;
};

Snapshot buildBlockFrozenWall(const Dictionary& dict, const DpdModel& model, BlockFrozenWallReport& report);

}  // namespace dpd
