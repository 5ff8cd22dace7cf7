#pragma once
// Profiles from accumulated bin sums: number density, mean velocity and kinetic temperature about
// the local mean flow, each with a standard error from the spread of block means.
#include "sampling/BinAccumulator.hpp"

#include <vector>

namespace dpd {

struct BinProfile {
    std::vector<double> centre;
    std::vector<double> density, densityErr;
    std::vector<double> ux, uy, uz, uxErr, uyErr, uzErr;
    std::vector<double> kT, kTErr;
    std::vector<double> count;  // particle-samples in the bin (all blocks)
    long samples = 0;
    int blocksForErrors = 0;  // complete blocks used for the error bars (0: no error bars)
};

// crossSection: the measure of a bin's face (volume / length along the axis; area / length in 2-D),
// so that density = count / (samples x width x crossSection). `dimension` sets which velocity
// components count in the temperature (x and z in 2-D).
BinProfile computeProfile(const BinAccumulator& acc, double crossSection, int dimension);

}  // namespace dpd
