#pragma once
// makeFoamCase: writes the OpenFOAM simpleFoam twin of a DPD case (FoamCaseSpec.hpp for the keywords of
// system/makeFoamCaseDict, which is optional; FoamCaseWriter.hpp for the files). The DPD box comes from
// the dictionary's box, else from the latest time's particle snapshot (0/ included).
#include "foam/FoamCaseSpec.hpp"

#include <iosfwd>
#include <string>

namespace dpd {

struct MakeFoamCaseOptions {
    std::string caseDir = ".";
    std::string dictFile;      // -dict: another dictionary than system/makeFoamCaseDict
    std::string output;        // -output: overrides foamCase of the dictionary
    bool nuGiven = false;      // -nu
    double nu = 0.0;
};

// Reads, checks and writes; returns the spec written. Nothing is written when the input is bad.
FoamCaseSpec runMakeFoamCase(const MakeFoamCaseOptions& options, std::ostream& out);

}  // namespace dpd
