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
//               stressFlowAxis (-1: no stress sampled), format = "dpdFoamLike-bins-2";
//               for a 2-D grid of bins also axis2, nBins2, lo2, hi2 (then the second dimension of
//               blocks is nBins x nBins2, bin (i, j) at i + nBins j), and optionally sections
//               (positions along the first axis where profileBins cuts 1-D profiles along the second)
// Files of format "dpdFoamLike-bins-1" (12 fields, no stress) are still read.
#include "sampling/BinAccumulator.hpp"

#include <string>
#include <vector>

namespace dpd {

struct StoredBins {
    BinAccumulator accumulator;
    int dimension = 3;
    double crossSection = 1.0;
    double time = 0.0;
    std::vector<double> sections;  // 2-D grids: where to cut 1-D profiles (positions along the first axis)
};

void writeBins(const std::string& file, const BinAccumulator& acc, int dimension, double crossSection, double time,
               const std::vector<double>& sections = {});
StoredBins readBins(const std::string& file);  // IoError naming the file for a wrong layout

}  // namespace dpd
