#pragma once
// fitSlipLength's errors by jackknife over super-blocks (docs/analysis.md 5.2), as set in
// system/fitSlipLengthDict:
//
//   superBlocks
//   {
//       length      1200;   // time units a super-block spans (to the nearest sampling block), or
//       decayTimes  2;      // that many of the channel's slowest decay time d^2 / (pi^2 nu) (nu the fit's)
//       minimum     5;      // fewest super-blocks for a jackknife (default 5)
//   }
//
// Why: a channel's bins fluctuate together with its slowest flow mode, which outlives the sampling
// blocks; consecutive blocks are joined into super-blocks long against it (the latest ones kept, the
// earliest, nearest the start, left out), the profile of all but one super-block is fitted in turn with
// the table's bin errors, and the spread of those fits gives the errors (the jackknife). With fewer than
// `minimum` super-blocks the errors stay the sampling blocks' and fit.dat says why.
#include "io/Dictionary.hpp"
#include "sampling/BinProfile.hpp"

#include <string>
#include <vector>

namespace dpd {

struct SuperBlockSetup {
    bool on() const { return length > 0.0 || decayTimes > 0.0; }  // the entry was given
    double length = 0.0;      // > 0: length given
    double decayTimes = 0.0;  // > 0: decayTimes given
    int minimum = 5;
};

// Reads the optional superBlocks sub-dictionary (InputError naming the file, line and keyword).
SuperBlockSetup readSuperBlockSetup(const Dictionary& fitDict);

// The complete sampling blocks of a table's rows (particle-samples and sums of the fitted velocity
// component, block by block in time order) and the time a block spans.
struct BlockSums : BlockVelocitySums {
    double blockTime = 0.0;
};

// How the blocks were joined and what the jackknife gave (superBlocks 0: no jackknife, note says why).
struct SuperBlockInfo {
    int superBlocks = 0;
    int blocksPerSuperBlock = 0;
    double superBlockLength = 0.0;
    std::string note;
};

// The time a sampling block of function object `profile` spans: samplesPerBlock x its sampleInterval
// (default 1) x deltaT, from the case's system/controlDict (InputError at superBlocks when the function
// object is not there).
double samplingBlockTime(const Dictionary& controlDict, const std::string& profile, long blockSamples,
                         const Dictionary& fitDict);

// Blocks per super-block for super-blocks about `length` long (ties to even, at least 1).
int blocksPerSuperBlock(double length, double blockTime);

// The jackknife standard error of an estimate from its values with each of m super-blocks left out.
double jackknifeError(const std::vector<double>& leaveOneOut);

// The mean velocity of every row with super-block `left` left out, over the last m x per blocks (NaN
// where the rest saw no particle).
std::vector<double> leaveOneOutVelocities(const BlockSums& b, int per, int m, int left);

}  // namespace dpd
