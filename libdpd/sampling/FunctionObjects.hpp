#pragma once
// Run-time sampling declared in controlDict's `functions`, as OpenFOAM users declare function
// objects. One type so far:
//
//   channelProfile
//   {
//       type            binnedProfile;
//       axis            z;
//       nBins           80;
//       min             -20;        // default: the box
//       max             20;
//       species         (fluid);    // default: every species that is not frozen
//       startTime       100;        // samples from this time on (let the flow develop first)
//       sampleInterval  1;          // steps between samples
//       samplesPerBlock 1000;       // samples per block, for the error bars
//       stress          yes;        // optional: also the shear stress sigma_{flowAxis, axis} (kinetic
//       flowAxis        x;          // + virial) and the pressure (costs one pair traversal per sample)
//   }
//
// or on a 2-D grid of bins (no stress), with optional 1-D sections (sampling/BinLayoutDictionary.hpp):
//
//       axes (x z); nBins (160 80); min (-30 -15); max (30 15); sections (-25.5 0 25.5);
//
// At every write time the sums go to <time>/sampling/<name>.h5 (see BinAccumulatorFile.hpp), which
// profileBins turns into profiles.
#include "sampling/BinAccumulator.hpp"

#include <string>
#include <vector>

namespace dpd {

class Dictionary;
class System;

struct BinnedProfileFunction {
    std::string name;
    BinAccumulator accumulator;
    double startTime = 0.0;
    long sampleInterval = 1;
    double crossSection = 1.0;
    std::vector<double> sections;  // 2-D grids: where profileBins cuts 1-D profiles
};

class FunctionObjects {
public:
    // Reads and checks every entry; errors name controlDict, the line and the keyword.
    static FunctionObjects read(const Dictionary& functions, const System& sys);
    // Samples whatever is due after the step the system has just made.
    void execute(const System& sys);
    // Writes every accumulator under <timeDir>/sampling/.
    void write(const std::string& timeDir, const System& sys) const;
    // Carries sums accumulated before a restart on from <timeDir>/sampling/ (missing files are fine).
    void restore(const std::string& timeDir);
    std::size_t size() const { return profiles_.size(); }

private:
    std::vector<BinnedProfileFunction> profiles_;
};

}  // namespace dpd
