#include "sampling/BinnedProfile.hpp"

#include "parallel/Communicator.hpp"

#include "io/Dictionary.hpp"
#include "sampling/BinAccumulatorFile.hpp"
#include "sampling/BinLayoutDictionary.hpp"
#include "sampling/PairVirial.hpp"
#include "system/System.hpp"

#include <filesystem>

namespace dpd {

namespace {

int readAxis(const Dictionary& d, const System& sys, const std::string& key = "axis") {
    const int axis = d.getAxis(key);
    if (!sys.box.isActiveAxis(axis)) d.fail(key, "a 2-D scene has no y axis");
    return axis;
}

std::vector<std::uint8_t> readSpeciesMask(const Dictionary& d, const System& sys) {
    std::vector<std::uint8_t> mask(sys.species.size(), 0);
    if (!d.found("species")) {
        for (int s = 0; s < sys.species.size(); ++s) mask[s] = sys.species[s].frozen ? 0 : 1;
        return mask;
    }
    for (const std::string& name : d.get<std::vector<std::string>>("species")) {
        const int idx = sys.species.indexOf(name);
        if (idx < 0) d.fail("species", "unknown species '" + name + "'");
        mask[idx] = 1;
    }
    return mask;
}

}  // namespace

std::unique_ptr<FunctionObject> BinnedProfile::New(const Dictionary& d, const std::string& name, const System& sys) {
    std::vector<std::string> keys = binLayoutKeys();
    keys.insert(keys.end(), {"type", "species", "startTime", "sampleInterval", "samplesPerBlock", "stress", "flowAxis"});
    d.checkKeys(keys);
    const BinLayout layout = readBinLayout(d, sys.box);
    auto f = std::make_unique<BinnedProfile>();
    f->name_ = name;
    f->startTime_ = d.getOrDefault<double>("startTime", 0.0);
    f->sampleInterval_ = d.found("sampleInterval") ? d.getPositive<long>("sampleInterval") : 1;
    const long perBlock = d.found("samplesPerBlock") ? d.getPositive<long>("samplesPerBlock") : 1000;
    f->accumulator_ = BinAccumulator(layout, readSpeciesMask(d, sys), perBlock);
    f->sections_ = readSections(d, layout);
    if (d.getOrDefault<bool>("stress", false)) {
        if (layout.twoAxes()) d.fail("stress", "the stress is sampled on bins along one axis only");
        const int flow = readAxis(d, sys, "flowAxis");
        if (flow == layout.axis) d.fail("flowAxis", "the flow axis must differ from the bin axis (the shear stress is sigma_flow,axis)");
        f->accumulator_.setStressFlowAxis(flow);
    } else if (d.found("flowAxis")) {
        d.fail("flowAxis", "only with stress yes");
    }
    f->crossSection_ = binCrossSection(layout, sys.box);
    return f;
}

Capabilities BinnedProfile::capabilities() const {
    if (accumulator_.stressFlowAxis() < 0) return {};
    return {{},
            {{{Feature::pairForceTakenBack}, "cannot sample the stress (the pair virial would count the terms taken back)", "stress"},
             {{Feature::severalRanks, Feature::movesAlongXAfterSort},
              "cannot sample the stress on several ranks beside a wall whose crossings, completed after the step's sort, can "
              "carry particles past a slab's face",
              "stress"}}};
}

void BinnedProfile::execute(const System& sys) {
    if (sys.time < startTime_ - 1e-9 * sys.dt()) return;
    if (sys.step % sampleInterval_ != 0) return;
    accumulator_.sample(sys.particles);
    if (accumulator_.stressFlowAxis() >= 0) accumulator_.addVirial(binnedPairVirial(sys, accumulator_.layout(), virialWork_));
}

void BinnedProfile::write(const std::string& timeDir, const System& sys) const {
    if (accumulator_.samples() == 0) return;
    const std::string file = (std::filesystem::path(timeDir) / "sampling" / (name_ + ".h5")).string();
    writeBins(file, accumulator_, sys.box.dimension, crossSection_, sys.time, sections_);
}

void BinnedProfile::sumOverRanks(const Communicator& comm) {
    std::vector<double> sums = accumulator_.sums();
    comm.sum(sums.data(), sums.size());
    accumulator_.setSums(sums);
}

void BinnedProfile::keepRestoredSums(bool keep) {
    if (!keep) accumulator_.clearSums();
}

void BinnedProfile::restore(const std::string& timeDir) {
    const auto file = std::filesystem::path(timeDir) / "sampling" / (name_ + ".h5");
    if (!std::filesystem::exists(file)) return;
    StoredBins stored = readBins(file.string());
    accumulator_ = std::move(stored.accumulator);
}

}  // namespace dpd
