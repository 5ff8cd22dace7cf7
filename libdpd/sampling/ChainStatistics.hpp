#pragma once
// The chainStatistics function object: the shape of the polymer chains over time (docs/methods.md 4),
//
//   chains
//   {
//       type            chainStatistics;
//       flowAxis        x;          // the extension is measured along it
//       startTime       100;
//       sampleInterval  50;         // steps between samples
//       samplesPerBlock 20;         // samples per block, for the error bars
//       axis x; nBins 12; min -30; max 30;   // optional: averages by where a chain's centre lies
//   }
//
// Each sample averages over the chains: R_g^2, R_ee^2, the end-to-end vector's component along the
// flow and its square, and the span along the flow (max - min bead coordinate, the chain's extension).
// At every write time the whole series and the bin sums go to <time>/chains/<name>.h5 (what a restart
// carries on from), and the table, with each mean and its block standard error in the header, to
// postProcessing/<name>/<time>/chainStatistics.dat (and chainBins.dat with bins).
#include "sampling/FunctionObject.hpp"

#include <Eigen/Core>
#include <vector>

namespace dpd {

// One sample: means over the chains.
struct ChainSample {
    double time = 0.0;
    double gyration2 = 0.0;
    double endToEnd2 = 0.0;
    double endToEndFlow = 0.0;   // <R_ee . e_flow>: the chains' net orientation along the flow
    double endToEndFlow2 = 0.0;  // <(R_ee . e_flow)^2>
    double span = 0.0;           // <max - min of the bead coordinates along the flow>
};
inline constexpr int kChainSampleColumns = 6;

// Sums per bin of chain centres: count, R_g^2, span along the flow, (R_ee . e_flow)^2.
struct ChainBinSums {
    std::vector<double> count, gyration2, span, endToEndFlow2;
};

class ChainStatistics : public FunctionObject {
public:
    static std::unique_ptr<FunctionObject> New(const Dictionary& d, const std::string& name, const System& sys);

    std::unique_ptr<FunctionObject> clone() const override { return std::make_unique<ChainStatistics>(*this); }
    const std::string& name() const override { return name_; }
    void execute(const System& sys) override;
    void write(const std::string& timeDir, const System& sys) const override;
    void restore(const std::string& timeDir) override;

    // In a decomposed run the first rank samples every chain (gathered there) and the others none:
    // nothing to add over the ranks.
    Capabilities capabilities() const override { return {}; }

    const std::vector<ChainSample>& samples() const { return samples_; }

private:
    std::string name_;
    int flowAxis_ = 0;
    double startTime_ = 0.0;
    long sampleInterval_ = 1;
    long samplesPerBlock_ = 20;
    int binAxis_ = -1;  // -1: no bins
    double binMin_ = 0.0, binMax_ = 0.0;
    ChainBinSums bins_;
    std::vector<ChainSample> samples_;
};

// The text of chainStatistics.dat: a header with each mean and its block standard error (from the
// complete blocks of samplesPerBlock samples; no error with fewer than two), then one row per sample.
std::string chainStatisticsTable(const std::vector<ChainSample>& samples, long samplesPerBlock, int flowAxis);
// The text of chainBins.dat: bin centre, chain-samples, mean R_g^2, span and (R_ee . e_flow)^2.
std::string chainBinsTable(const ChainBinSums& bins, int axis, double lo, double hi, int flowAxis);

}  // namespace dpd
