#pragma once
// The continuum twin of a DPD case (docs/analysis.md 5, continuum comparison): what makeFoamCase puts into
// an OpenFOAM simpleFoam case, read from the DPD case and system/makeFoamCaseDict:
//
//   foamCase    simpleFoam;     // the OpenFOAM case to write, relative to the DPD case (default simpleFoam)
//   nu          4.06;           // the DPD fluid's measured kinematic viscosity, or instead
//   // nuFrom   "viscosity";    //   a DPD case (relative to this one) whose latest
//                               //   postProcessing/fitSlipLength/<time>/fit.dat has nu, or such a file;
//                               //   default: this case's own latest fit.dat. (-nu on the command line wins.)
//   slipLength  0;              // Navier slip length of the planar walls: a number, (lower upper), or
//                               //   fitted (slipLength of the same fit.dat as nu); default: the b a wall
//                               //   asks for in constant/dpdProperties (docs/walls.md 3.8), else 0 (no slip)
//   cellSize    0.25;           // mesh spacing along the axes where the flow varies (default cutoff / 4)
//   // cells    (1 1 40);       //   or the cell counts themselves
//   dimension   2;              // 2: one cell thick in y, empty front and back; 3; default 2 when
//                               //   nothing varies along y
//   box { min (..); max (..); } // default: the box of the latest time's (or 0/) particle snapshot
//   lines { centre { start (0 0 -5); end (0 0 5); nPoints 161; } }   // sampling lines; default one
//                               //   line across a planar channel, through the middle of the box
//   maxIterations 20000;        // SIMPLE iterations at most (endTime); default 20000
//   residual    1e-12;          // residualControl for p and U; default 1e-12
//
// Mesh: one block over the box; between two facing planar walls along an axis it spans only the fluid
// between them (wall patches, no slip or the Navier slip); every other axis is cyclic. Along a periodic
// axis where nothing varies (no geometry) it has one cell: the exact solution is uniform there, and one
// cell keeps it exactly so (no round-off cross-flow whose normalised residual never falls). A geometry
// block in constant/dpdProperties (image mask, gmsh) marks the cells whose centres are solid; the case's
// Allrun removes them (topoSet + subsetMesh, the exposed faces becoming the wall patch solidWalls), whose
// slip is the b the geometry wall asks for: partialSlip on the staircase of cell faces, each face
// slipping by b (|n_x| + |n_y| + |n_z|), n the smooth wall's normal there, so that the staircase, longer
// than the wall by that factor, holds the wall's friction for flow along its faces (docs/walls.md 3.9).
#include "core/Box.hpp"

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace dpd {

class Dictionary;

struct FoamWall {
    std::string name;           // the DPD wall's name: the patch name
    double position = 0.0;      // along the wall axis
    Eigen::Vector3d velocity{0, 0, 0};
    double slipLength = 0.0;    // Navier slip length; 0: no slip
};

// A face of the staircase a slipping geometry wall leaves: its centre in half cells from the mesh's
// corner (integers: 2 i + 1 at a cell's centre, 2 i at a face), and the Navier slip length it carries.
struct StaircaseFace {
    std::array<long, 3> halfCells{0, 0, 0};
    int axis = 0;               // the face's normal axis
    double slipLength = 0.0;
};

struct FoamLine {
    std::string name;
    Eigen::Vector3d start{0, 0, 0}, end{0, 0, 0};
    int nPoints = 2;
};

struct FoamCaseSpec {
    std::string dpdCase;                    // where it came from (for the record)
    Eigen::Vector3d lo{0, 0, 0}, hi{1, 1, 1};   // the mesh's extent
    std::array<int, 3> cells{1, 1, 1};
    int dimension = 3;                      // 2: y is one empty cell
    int wallAxis = -1;                      // the axis of the two planar walls, -1 when none
    FoamWall lower, upper;                  // wallAxis >= 0 only
    Box dpdBox;                             // the DPD box (checked by compareFVM)
    double nu = 0.0;
    std::string nuSource;                   // the number's origin: "command line", a file, ...
    Eigen::Vector3d g{0, 0, 0};             // body force per unit mass
    std::vector<FoamLine> lines;
    std::vector<std::size_t> solidCells;    // blockMesh cell labels (i + nx (j + ny k)) to remove
    double solidWallSlip = 0.0;             // the Navier slip length of the solidWalls patch (a geometry
                                            // wall's slipLength, docs/walls.md 3.9); 0: no slip
    std::vector<StaircaseFace> staircaseFaces;  // fluid-solid faces inside the block, when it slips
    std::string geometrySource;             // the mask or gmsh file, when there is one
    int maxIterations = 20000;
    double residual = 1e-12;
    std::string foamCase = "simpleFoam";    // relative to the DPD case

    bool isPeriodic(int axis) const { return axis != wallAxis && !(dimension == 2 && axis == 1); }
    double cellSize(int axis) const { return (hi[axis] - lo[axis]) / cells[axis]; }
    Eigen::Vector3d cellCentre(int i, int j, int k) const {
        return lo + Eigen::Vector3d((i + 0.5) * cellSize(0), (j + 0.5) * cellSize(1), (k + 0.5) * cellSize(2));
    }
};

// What the tool gathers besides the two dictionaries.
struct MakeFoamCaseInput {
    std::string caseDir = ".";
    Box snapshotBox;                        // used when the dictionary has no box
    std::string snapshotFile;               // where snapshotBox came from ("" when none was found)
    bool nuGiven = false;                   // -nu on the command line
    double nu = 0.0;
};

// Builds the spec from system/makeFoamCaseDict (dict; may be empty) and constant/dpdProperties.
// InputError naming the file, line and keyword for anything the continuum case cannot represent
// (oblique walls, a single wall, a reverse-Poiseuille force, variation along y in 2-D ...).
FoamCaseSpec makeFoamCaseSpec(const Dictionary& dict, const Dictionary& dpdProperties, const MakeFoamCaseInput& in);

// nu (and the slip lengths) of a fitSlipLength result: a fit.dat file, or a case directory whose latest
// postProcessing/fitSlipLength/<time>/fit.dat is used. IoError naming what is missing.
std::string findFitFile(const std::string& fileOrCase);

}  // namespace dpd
