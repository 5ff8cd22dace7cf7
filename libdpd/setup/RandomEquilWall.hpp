#pragma once
// randomEquilWall: the initial state of a case with walls of any shape (docs/walls.md 3.2 steps 1-3),
// from the geometry block of constant/dpdProperties (GeometryDictionary) and
// system/randomEquilWallDict:
//
//   box           { min (-8 -1.5 -6); max (8 1.5 6); }   // the whole periodic box
//   fluid         { species fluid; density 4; }   // optional initialFlow { type poiseuille; axis z;
//                                                 // wallPositions (-20 20); } (setup/InitialFlow.hpp)
//   wall          { species wall; }          // a frozen species: the particles kept in the solid;
//                                            // optional thickness 1.5: a published wall's depth,
//                                            // whose particles are counted (not kept beyond 1 cutoff).
//                                            // Optional: without it the wall is smooth (a tunable-slip
//                                            // geometry wall, whose force stands in for the solid)
//   equilibration { time 5; deltaT 0.02; }   // DPD run of the filled box: one fluid, no walls,
//                                            // no body force, the integrator of dpdProperties
//   drivingAxis   x;     // optional: the axis the flow must cross (percolation check); default
//                        // every axis along which bodyForce of dpdProperties pushes; none: no check
//
// 1. flags the background grid solid or fluid; refuses a geometry with no fluid or no solid, and one
//    whose fluid does not percolate along the driving axis;
// 2. fills the whole box at the density (Maxwellian velocities at kT) and runs it to equilibrium;
// 3. freezes the particles in the solid within one cutoff of the fluid (exact distance to the
//    geometry's surface) as the wall species, at rest, and drops the deeper ones. The fluid keeps its
//    equilibrated velocities less their mean (no net momentum), plus the initial flow if one is
//    given. Ids are renumbered, fluid first. A geometry wall that acts behind the geometry's surface
//    (one asking for a slip length, docs/walls.md 3.9) keeps the fluid up to where it acts, and one
//    whose force repels the fluid (the tunable-slip layer's WCA) keeps it sigma in front, as
//    blockFrozenWall does.
#include "io/Snapshot.hpp"

#include <array>
#include <string>
#include <vector>

namespace dpd {

class Dictionary;
struct DpdModel;

struct RandomEquilWallReport {
    std::size_t filled = 0, fluid = 0, frozen = 0, dropped = 0;
    double thickness = 0.0;          // the wall entry's thickness (0: none given)
    double surfaceOffset = 0.0;      // the geometry wall acts this far behind the geometry's surface
    double fluidStartsBeyond = 0.0;  // and the fluid starts this far in front of where it acts
    std::size_t withinThickness = 0; // solid particles within it of the fluid (the published count)
    double gridPorosity = 0.0;       // fluid fraction of the background grid's cells
    double particlePorosity = 0.0;   // fluid / filled particles
    double equilibratedKT = 0.0;     // kinetic temperature at the end of the equilibration
    std::size_t equilibrationSteps = 0;
    std::vector<int> drivingAxes;    // axes checked for percolation
    std::array<int, 3> gridCells{1, 1, 1};
};

// dpdProperties: the dictionary of constant/dpdProperties (for its geometry block); model: the same
// file read by readDpdModel. Input errors are InputErrors naming file, line and keyword.
Snapshot buildRandomEquilWall(const Dictionary& dict, const Dictionary& dpdProperties, const DpdModel& model,
                              const std::string& caseDir, RandomEquilWallReport& report);

}  // namespace dpd
