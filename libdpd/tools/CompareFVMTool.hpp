#pragma once
// compareFVM: the DPD profile against the OpenFOAM simpleFoam solution of its twin case (makeFoamCase),
// as set in the optional system/compareFVMDict:
//
//   foamCase   simpleFoam;      // the OpenFOAM case, relative to the DPD case (default: foamCase of
//                               // makeFoamCaseDict, else simpleFoam); -foamCase on the command line wins
//   profile    channelProfile;  // the DPD table postProcessing/profileBins/<time>/<profile>.dat; default:
//                               // the only table there
//   component  x;               // velocity component compared; default: the body force's direction
//   foamTime   latestTime;      // the OpenFOAM time; default its latest
//   fluidDensity 4;             // 2-D profiles: the DPD fluid's number density, for the superficial
//                               // velocity; default fluid/density of system/randomEquilWallDict or
//                               // system/blockFrozenWallDict
//
// Reads <foamCase>/constant/dpdCase (what makeFoamCase recorded: box, walls, g) and refuses a DPD case
// that no longer matches it; the cell centres <foamCase>/<foamTime>/C (postProcess -func
// writeCellCentres) and U; and the sampled lines <foamCase>/postProcessing/sampledLines/<foamTime>/.
// The field: U averaged over the fluid cells of each layer across the profile's axis, interpolated to
// the DPD bin centres inside the fluid (FieldComparison.hpp). Each line parallel to the profile's axis:
// interpolated along the line to the same centres.
//
// A 2-D profile (profileBins with axes (a b): the table's first two columns are bin axes): the mesh cells
// are gathered into the DPD bins (each bin: the mean over the fluid cells whose centres lie in it; the
// mesh should be at least as fine as the bins) and compared bin by bin over the fluid; each line
// parallel to one of the grid's axes is compared along the row of bins it runs through (the sampled
// line interpolated to the bins' centres, not across gaps where it crosses solid). The component may be
// a bin axis here. Darcy's law (foam/DarcyFlow.hpp) gives each side's porosity, superficial velocity
// and permeability over the grid's rectangle.
//
// Results: postProcessing/compareFVM/<time>/compare.dat (a dictionary: L2, Linf, meanVelocityRatio,
// noiseL2, meanVelocityDPD, meanVelocityFVM, points, and lines { <name> { ... } }; for a 2-D profile also
// porosityDPD, porosityFVM, superficialVelocityDPD(Err), superficialVelocityFVM, permeabilityDPD(Err),
// permeabilityFVM, permeabilityRatio) and profiles.dat (the DPD bin centres -- both coordinates for a
// 2-D profile --, uDPD, uDPDErr, uFVM and u_<line> per line, NaN off the line), for plotting.
#include "foam/DarcyFlow.hpp"
#include "foam/FieldComparison.hpp"

#include <iosfwd>
#include <map>
#include <string>
#include <vector>

namespace dpd {

struct CompareFVMOptions {
    std::string caseDir = ".";
    std::string time;
    bool latestTime = false;
    std::string foamCase;    // -foamCase
};

struct CompareFVMResult {
    std::string time;            // the DPD time
    std::string foamCase, foamTime, profileFile;
    int axis = 2, component = 0;
    int axis2 = -1;                      // the second bin axis of a 2-D profile; -1 for a 1-D one
    ComparisonMetrics field;
    std::map<std::string, ComparisonMetrics> lines;
    std::vector<std::string> skippedLines;   // not parallel to the profile's axis
    std::vector<double> x, uDPD, uDPDErr, uFVM;   // the compared points (uFVM NaN outside the fluid)
    std::vector<double> x2;              // 2-D profiles: the second coordinate of each point
    std::map<std::string, std::vector<double>> uLines;
    bool hasDarcy = false;               // 2-D profiles
    DarcyFlow darcyDPD, darcyFVM;
};

std::vector<CompareFVMResult> runCompareFVM(const CompareFVMOptions& options, std::ostream& out);

}  // namespace dpd
