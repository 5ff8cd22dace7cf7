#pragma once
// Profiles from accumulated bin sums: number density, mean velocity and kinetic temperature about
// the local mean flow, each with a standard error from the spread of block means; with stress
// sampling, the shear stress and the pressure.
//
// Stress: the pressure tensor of a bin of volume V over M samples is
//   P_ab = rho cov(v_a, v_b) + W_ab / (M V),
// the kinetic part about the local mean flow (the velocity's linear variation across the bin taken
// out, as for kT) plus the pair virial W (PairVirial.hpp). The stress is sigma = -P, so that in a
// Newtonian shear flow sigma_xz = eta du_x/dz; the pressure is the trace of P over the dimension.
#include "sampling/BinAccumulator.hpp"

#include <string>
#include <vector>

namespace dpd {

// The stress of one bin: the shear component sigma_{flow, axis}, its kinetic and virial parts, and
// the pressure.
struct StressPoint {
    double shear = 0.0, shearErr = 0.0;
    double shearKinetic = 0.0, shearKineticErr = 0.0;
    double shearVirial = 0.0, shearVirialErr = 0.0;
    double pressure = 0.0, pressureErr = 0.0;
};

// One entry per bin; for a 2-D grid of bins, bin (i, j) is entry i + nBins j and centre2 holds the
// bin centres along the second axis.
struct BinProfile {
    std::vector<double> centre;
    std::vector<double> centre2;  // empty for bins along one axis
    std::vector<double> density, densityErr;
    std::vector<double> ux, uy, uz, uxErr, uyErr, uzErr;
    std::vector<double> kT, kTErr;
    std::vector<double> count;  // particle-samples in the bin (all blocks)
    long samples = 0;
    int blocksForErrors = 0;  // complete blocks used for the error bars (0: no error bars)
    bool hasStress = false;
    std::string stressName;           // the shear component's column name, e.g. sigmaxz
    std::vector<StressPoint> stress;  // per bin, when hasStress
};

// The name of the shear stress component (flow axis, bin axis), indices in increasing order: sigmaxz.
std::string shearStressName(int flowAxis, int binAxis);

// crossSection: the measure of a bin's face (volume / length along the axis; area / length in 2-D),
// so that density = count / (samples x width x crossSection); for a 2-D grid of bins, the box's
// extent along the remaining axis (volume / (length1 x length2); 1 in a 2-D scene), and the bin
// measure is width x width2 x crossSection. `dimension` sets which velocity
// components count in the temperature (x and z in 2-D).
BinProfile computeProfile(const BinAccumulator& acc, double crossSection, int dimension);

// The mean velocity component `component` of every bin in each complete block (NaN where the block saw
// too few samples in the bin): the profile block by block, for fits that need the covariance of the
// bins (analysis/Profile1D.hpp).
std::vector<std::vector<double>> blockVelocities(const BinAccumulator& acc, int component);

// The particle-samples and sums of velocity component `component` of every bin in each complete block
// (the blocks of blockVelocities): for profiles of blocks joined together.
struct BlockVelocitySums {
    std::vector<std::vector<double>> counts, velocitySums;
};
BlockVelocitySums blockVelocitySums(const BinAccumulator& acc, int component);

// The shear stress sigma_{flow, axis} of every bin in each complete block (stress sampling on; the
// same blocks as blockVelocities).
std::vector<std::vector<double>> blockShearStress(const BinAccumulator& acc, double crossSection, int dimension);

}  // namespace dpd
