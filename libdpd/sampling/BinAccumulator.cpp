#include "sampling/BinAccumulator.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace dpd {

int BinLayout::binOf(double x) const {
    if (x < lo || x >= hi) return -1;
    const int b = static_cast<int>((x - lo) / width());
    return b < nBins ? b : nBins - 1;
}

int BinLayout::binOf2(double x) const {
    if (x < lo2 || x >= hi2) return -1;
    const int b = static_cast<int>((x - lo2) / width2());
    return b < nBins2 ? b : nBins2 - 1;
}

BinAccumulator::BinAccumulator(const BinLayout& layout, std::vector<std::uint8_t> speciesMask, long blockSamples)
    : layout_(layout), speciesMask_(std::move(speciesMask)), blockSamples_(blockSamples) {
    if (layout.nBins < 1) throw std::invalid_argument("nBins must be at least 1");
    if (!(layout.hi > layout.lo)) throw std::invalid_argument("the bin range must have hi > lo");
    if (layout.twoAxes() && (layout.nBins2 < 1 || !(layout.hi2 > layout.lo2) || layout.axis2 == layout.axis))
        throw std::invalid_argument("the second bin axis needs nBins2 >= 1, hi2 > lo2 and an axis of its own");
    if (blockSamples < 1) throw std::invalid_argument("a block must hold at least one sample");
}

namespace {

// Particle ranges of a sample: enough for the threads of a node to share (8), no range under ~4,000
// particles (the bins of a range are cleared and added for every sample), and their bins together no
// more than ~4 MB. A function of the two counts only, never of the number of threads.
std::size_t sampleRanges(std::size_t particles, std::size_t bins) {
    constexpr std::size_t kMostRanges = 8, kLeastParticles = 4096, kMostBytes = std::size_t{4} << 20;
    const std::size_t byMemory = std::max<std::size_t>(1, kMostBytes / (bins * sizeof(BinSums)));
    return std::max<std::size_t>(1, std::min({kMostRanges, particles / kLeastParticles, byMemory}));
}

}  // namespace

void BinAccumulator::addParticles(const Particles& p, std::size_t begin, std::size_t end, BinSums* bins) const {
    const ParticleArray<double>& r = p.position(layout_.axis);
    const ParticleArray<double>& r2 = p.position(layout_.twoAxes() ? layout_.axis2 : layout_.axis);
    for (std::size_t i = begin; i < end; ++i) {
        if (!speciesMask_[p.species[i]]) continue;
        const int b = layout_.binOf(r[i]);
        if (b < 0) continue;
        const int j = layout_.twoAxes() ? layout_.binOf2(r2[i]) : 0;
        if (j < 0) continue;
        bins[b + layout_.nBins * j].add(r[i] - layout_.centre(b), p.vx[i], p.vy[i], p.vz[i]);
    }
}

void BinAccumulator::sample(const Particles& p) {
    if (blocks_.empty() || samplesPerBlock_.back() == blockSamples_) {
        blocks_.emplace_back(layout_.binCount());
        samplesPerBlock_.push_back(0);
    }
    std::vector<BinSums>& block = blocks_.back();
    const std::size_t bins = block.size(), n = p.size();
    const std::size_t ranges = sampleRanges(n, bins);
    rangeSums_.assign(ranges * bins, BinSums{});
#pragma omp parallel for schedule(static)
    for (std::size_t k = 0; k < ranges; ++k) addParticles(p, n * k / ranges, n * (k + 1) / ranges, &rangeSums_[k * bins]);
    for (std::size_t k = 0; k < ranges; ++k)
        for (std::size_t b = 0; b < bins; ++b)
            for (int f = 0; f < BinSums::kFields; ++f) block[b].s[f] += rangeSums_[k * bins + b].s[f];
    ++samplesPerBlock_.back();
    ++samples_;
}

void BinAccumulator::addVirial(const std::vector<SymmetricTensor>& virial) {
    if (blocks_.empty() || virial.size() != blocks_.back().size())
        throw std::logic_error("BinAccumulator::addVirial: take a sample first, with one tensor per bin");
    std::vector<BinSums>& block = blocks_.back();
    for (std::size_t b = 0; b < virial.size(); ++b)
        for (int c = 0; c < 6; ++c) block[b].s[BinSums::kVirial + c] += virial[b][c];
}

std::vector<double> BinAccumulator::sums() const {
    std::vector<double> out;
    for (const auto& block : blocks_)
        for (const BinSums& b : block) out.insert(out.end(), b.s.begin(), b.s.end());
    return out;
}

void BinAccumulator::setSums(const std::vector<double>& sums) {
    std::size_t at = 0;
    for (auto& block : blocks_)
        for (BinSums& b : block) {
            if (at + BinSums::kFields > sums.size()) throw std::invalid_argument("BinAccumulator::setSums: too few sums");
            std::copy(sums.begin() + static_cast<long>(at), sums.begin() + static_cast<long>(at + BinSums::kFields), b.s.begin());
            at += BinSums::kFields;
        }
    if (at != sums.size()) throw std::invalid_argument("BinAccumulator::setSums: too many sums");
}

void BinAccumulator::clearSums() {
    for (auto& block : blocks_)
        for (BinSums& b : block) b.s.fill(0.0);
}

BinAccumulator BinAccumulator::fromBlocks(const BinLayout& layout, std::vector<std::uint8_t> speciesMask,
                                          long blockSamples, std::vector<std::vector<BinSums>> blocks,
                                          std::vector<long> samplesPerBlock) {
    BinAccumulator acc(layout, std::move(speciesMask), blockSamples);
    if (blocks.size() != samplesPerBlock.size()) throw std::invalid_argument("blocks and their sample counts differ in number");
    acc.blocks_ = std::move(blocks);
    acc.samplesPerBlock_ = std::move(samplesPerBlock);
    for (long s : acc.samplesPerBlock_) acc.samples_ += s;
    return acc;
}

}  // namespace dpd
