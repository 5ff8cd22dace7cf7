#pragma once
// Accumulated bins on disk: <time>/sampling/<name>.h5, written whole or not at all.
//
// Layout (h5py: f["blocks"] has shape (nBlocks, nBins, 21)):
//   blocks           nBlocks x nBins x 21 doubles: per block and bin, count, sum vx vy vz,
//                    sum vx^2 vy^2 vz^2, sum x, sum x^2, sum vx x, vy x, vz x (x: offset from bin centre),
//                    sum vx vy, vx vz, vy vz, pair virial W_xx W_yy W_zz W_xy W_xz W_yz (zero
//                    unless stress is sampled)
//   samplesPerBlock  nBlocks int64
//   attributes: axis, nBins, lo, hi, blockSamples, dimension, crossSection, time, speciesMask,
//               stressFlowAxis (-1: no stress sampled), format = "dpdFoamLike-bins-2"
// Files of format "dpdFoamLike-bins-1" (12 fields, no stress) are still read.
#include "sampling/BinAccumulator.hpp"

#include <string>

namespace dpd {

struct StoredBins {
    BinAccumulator accumulator;
    int dimension = 3;
    double crossSection = 1.0;
    double time = 0.0;
};

void writeBins(const std::string& file, const BinAccumulator& acc, int dimension, double crossSection, double time);
StoredBins readBins(const std::string& file);  // IoError naming the file for a wrong layout

}  // namespace dpd
