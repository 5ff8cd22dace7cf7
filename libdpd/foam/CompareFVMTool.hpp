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
//
// Reads <foamCase>/constant/dpdCase (what makeFoamCase recorded: box, walls, g) and refuses a DPD case
// that no longer matches it; the cell centres <foamCase>/<foamTime>/C (postProcess -func
// writeCellCentres) and U; and the sampled lines <foamCase>/postProcessing/sampledLines/<foamTime>/.
// The field: U averaged over the fluid cells of each layer across the profile's axis, interpolated to
// the DPD bin centres inside the fluid (FieldComparison.hpp). Each line parallel to the profile's axis:
// interpolated along the line to the same centres.
//
// Results: postProcessing/compareFVM/<time>/compare.dat (a dictionary: L2, Linf, meanVelocityRatio,
// noiseL2, meanVelocityDPD, meanVelocityFVM, points, and lines { <name> { ... } }) and profiles.dat (the
// DPD bin centres, uDPD, uDPDErr, uFVM and u_<line> per line), for plotting.
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
    ComparisonMetrics field;
    std::map<std::string, ComparisonMetrics> lines;
    std::vector<std::string> skippedLines;   // not parallel to the profile's axis
    std::vector<double> x, uDPD, uDPDErr, uFVM;   // the compared points (uFVM NaN outside the fluid)
    std::map<std::string, std::vector<double>> uLines;
};

std::vector<CompareFVMResult> runCompareFVM(const CompareFVMOptions& options, std::ostream& out);

}  // namespace dpd
