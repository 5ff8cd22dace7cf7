#pragma once
// Time-averaged profiles accumulated during a run, so long averages need no stored snapshots.
//
// The range [lo, hi) along one axis is cut into bins. Every sample adds, per bin, the particle count
// and the sums of v, v^2, the offset x from the bin centre, x^2 and v x. The offset sums let the
// temperature be measured about a mean velocity that varies linearly across the bin, so a sheared
// flow does not heat the measured kT by (du/dx)^2 (bin width)^2 / 12.
//
// With stress sampling on, every sample also adds the sums of the velocity cross products v_a v_b and
// the pair virial of the bin (PairVirial.hpp): the pressure tensor and the shear stress follow.
//
// Sums are kept in blocks of `blockSamples` samples; the spread of the block means gives honest
// error bars for correlated data (a block much longer than the correlation time is one independent
// measurement).
//
// A sample runs in parallel and gives the same sums on any number of threads: the particles are cut
// into a fixed number of index ranges (set by the particle and bin counts alone), each range summed
// into bins of its own, and those added to the block in range order.
#include "core/Box.hpp"
#include "core/Particles.hpp"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace dpd {

// The sums of one bin over one block of samples.
struct BinSums {
    static constexpr int kBasicFields = 12;  // what every profile has (format dpdFoamLike-bins-1)
    static constexpr int kFields = 21;
    static constexpr int kCross = 12;        // first of sum vx vy, vx vz, vy vz
    static constexpr int kVirial = 15;       // first of the virial xx yy zz xy xz yz
    // count, sum vx vy vz, sum vx^2 vy^2 vz^2, sum x, sum x^2, sum vx x, vy x, vz x,
    // sum vx vy, vx vz, vy vz, virial sums W_xx W_yy W_zz W_xy W_xz W_yz
    std::array<double, kFields> s{};
    void add(double x, double vx, double vy, double vz) {
        s[0] += 1.0;
        s[1] += vx; s[2] += vy; s[3] += vz;
        s[4] += vx * vx; s[5] += vy * vy; s[6] += vz * vz;
        s[7] += x; s[8] += x * x;
        s[9] += vx * x; s[10] += vy * x; s[11] += vz * x;
        s[12] += vx * vy; s[13] += vx * vz; s[14] += vy * vz;
    }
};

// Symmetric tensor components in the order xx yy zz xy xz yz.
using SymmetricTensor = std::array<double, 6>;
// Index of component (a, b) in a SymmetricTensor.
inline int tensorIndex(int a, int b) {
    if (a == b) return a;
    const int lo = a < b ? a : b, hi = a < b ? b : a;
    return lo == 0 ? (hi == 1 ? 3 : 4) : 5;
}

// Bins along one axis, or on a 2-D grid of two axes: then bin (i, j) -- i along `axis`, j along
// `axis2` -- is number i + nBins j, and the offsets x of the temperature's shear correction are
// along the first axis.
struct BinLayout {
    int axis = 2;
    int nBins = 1;
    double lo = 0.0, hi = 1.0;
    int axis2 = -1;  // -1: bins along `axis` only
    int nBins2 = 1;
    double lo2 = 0.0, hi2 = 1.0;
    double width() const { return (hi - lo) / nBins; }
    double centre(int b) const { return lo + (b + 0.5) * width(); }
    bool twoAxes() const { return axis2 >= 0; }
    int binCount() const { return nBins * (twoAxes() ? nBins2 : 1); }
    double width2() const { return twoAxes() ? (hi2 - lo2) / nBins2 : 1.0; }
    double centre2(int j) const { return lo2 + (j + 0.5) * width2(); }
    // Bin index along the first axis, or -1 outside [lo, hi).
    int binOf(double coordinate) const;
    // Bin index along the second axis, or -1 outside [lo2, hi2).
    int binOf2(double coordinate) const;
};

class BinAccumulator {
public:
    BinAccumulator() = default;
    BinAccumulator(const BinLayout& layout, std::vector<std::uint8_t> speciesMask, long blockSamples);

    // Adds one sample of the particles whose species is in the mask.
    void sample(const Particles& p);
    // Adds the pair virial per bin (binCount() tensors) to the sample just taken.
    void addVirial(const std::vector<SymmetricTensor>& virial);
    // The flow axis of the shear stress reported, or -1 when no stress is sampled.
    int stressFlowAxis() const { return stressFlowAxis_; }
    void setStressFlowAxis(int axis) { stressFlowAxis_ = axis; }
    const BinLayout& layout() const { return layout_; }
    long samples() const { return samples_; }
    long blockSamples() const { return blockSamples_; }
    // Completed blocks, then the one in progress (if it has samples), each binCount() x kFields.
    const std::vector<std::vector<BinSums>>& blocks() const { return blocks_; }
    const std::vector<long>& samplesPerBlock() const { return samplesPerBlock_; }
    const std::vector<std::uint8_t>& speciesMask() const { return speciesMask_; }
    // Every block's sums in one array (block by block, bin by bin, field by field), and back: a
    // decomposed run adds its ranks' sums this way. setSums takes an array of the same length.
    std::vector<double> sums() const;
    void setSums(const std::vector<double>& sums);
    // Zero sums, the blocks and their sample counts kept.
    void clearSums();
    // Restores an accumulator from stored blocks (restart, post-processing).
    static BinAccumulator fromBlocks(const BinLayout& layout, std::vector<std::uint8_t> speciesMask, long blockSamples,
                                     std::vector<std::vector<BinSums>> blocks, std::vector<long> samplesPerBlock);

private:
    BinLayout layout_;
    std::vector<std::uint8_t> speciesMask_;
    long blockSamples_ = 1000;
    long samples_ = 0;
    int stressFlowAxis_ = -1;
    std::vector<std::vector<BinSums>> blocks_;
    std::vector<long> samplesPerBlock_;
    std::vector<BinSums> rangeSums_;  // scratch of sample(): one set of bins per particle range

    // The sums of particles [begin, end) into `bins` (binCount() of them).
    void addParticles(const Particles& p, std::size_t begin, std::size_t end, BinSums* bins) const;
};

}  // namespace dpd
