#pragma once
// The binnedProfile function object: density, velocity, kT (and optionally the shear stress and
// pressure) in bins along one axis or on a 2-D grid, accumulated in blocks for error bars:
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
#include "sampling/PairVirial.hpp"
#include "sampling/FunctionObject.hpp"

#include <vector>

namespace dpd {

class BinnedProfile : public FunctionObject {
public:
    // Reads and checks its sub-dictionary; errors name the file, the line and the keyword.
    static std::unique_ptr<FunctionObject> New(const Dictionary& d, const std::string& name, const System& sys);

    std::unique_ptr<FunctionObject> clone() const override { return std::make_unique<BinnedProfile>(*this); }
    const std::string& name() const override { return name_; }
    void execute(const System& sys) override;
    void write(const std::string& timeDir, const System& sys) const override;
    void restore(const std::string& timeDir) override;
    // Each rank samples its own particles (with the stress, the pairs of its own planes:
    // sampling/PairVirial.hpp); the sums are added over the ranks. The stress is the pair virial of
    // the whole pair force, on the pairs as sorted.
    Capabilities capabilities() const override;
    void sumOverRanks(const Communicator& comm) override;
    void keepRestoredSums(bool keep) override;

private:
    std::string name_;
    BinAccumulator accumulator_;
    PairVirialWork virialWork_;  // a decomposed run's stress traversal, kept between samples
    double startTime_ = 0.0;
    long sampleInterval_ = 1;
    double crossSection_ = 1.0;
    std::vector<double> sections_;  // 2-D grids: where profileBins cuts 1-D profiles
};

}  // namespace dpd
