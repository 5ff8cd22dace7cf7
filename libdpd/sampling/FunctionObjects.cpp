#include "sampling/FunctionObjects.hpp"

#include "io/Dictionary.hpp"
#include "system/System.hpp"
#include "sampling/BinAccumulatorFile.hpp"
#include "sampling/BinLayoutDictionary.hpp"
#include "sampling/PairVirial.hpp"

#include <cmath>
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

BinnedProfileFunction readBinnedProfile(const Dictionary& d, const std::string& name, const System& sys) {
    std::vector<std::string> keys = binLayoutKeys();
    keys.insert(keys.end(), {"type", "species", "startTime", "sampleInterval", "samplesPerBlock", "stress", "flowAxis"});
    d.checkKeys(keys);
    const BinLayout layout = readBinLayout(d, sys.box);
    BinnedProfileFunction f;
    f.name = name;
    f.startTime = d.getOrDefault<double>("startTime", 0.0);
    f.sampleInterval = d.found("sampleInterval") ? d.getPositive<long>("sampleInterval") : 1;
    const long perBlock = d.found("samplesPerBlock") ? d.getPositive<long>("samplesPerBlock") : 1000;
    f.accumulator = BinAccumulator(layout, readSpeciesMask(d, sys), perBlock);
    f.sections = readSections(d, layout);
    if (d.getOrDefault<bool>("stress", false)) {
        if (layout.twoAxes()) d.fail("stress", "the stress is sampled on bins along one axis only");
        const int flow = readAxis(d, sys, "flowAxis");
        if (flow == layout.axis) d.fail("flowAxis", "the flow axis must differ from the bin axis (the shear stress is sigma_flow,axis)");
        f.accumulator.setStressFlowAxis(flow);
    } else if (d.found("flowAxis")) {
        d.fail("flowAxis", "only with stress yes");
    }
    f.crossSection = binCrossSection(layout, sys.box);
    return f;
}

}  // namespace

FunctionObjects FunctionObjects::read(const Dictionary& functions, const System& sys) {
    FunctionObjects out;
    for (const std::string& name : functions.keys()) {
        if (!functions.isDict(name)) functions.fail(name, "each function object is a sub-dictionary");
        const Dictionary& d = functions.subDict(name);
        const std::string type = d.get<std::string>("type");
        if (type != "binnedProfile") d.fail("type", "unknown function object type '" + type + "' (expected binnedProfile)");
        out.profiles_.push_back(readBinnedProfile(d, name, sys));
    }
    return out;
}

void FunctionObjects::execute(const System& sys) {
    for (auto& f : profiles_) {
        if (sys.time < f.startTime - 1e-9 * sys.dt()) continue;
        if (sys.step % f.sampleInterval != 0) continue;
        f.accumulator.sample(sys.particles);
        if (f.accumulator.stressFlowAxis() >= 0) f.accumulator.addVirial(binnedPairVirial(sys, f.accumulator.layout()));
    }
}

void FunctionObjects::write(const std::string& timeDir, const System& sys) const {
    for (const auto& f : profiles_) {
        if (f.accumulator.samples() == 0) continue;
        const std::string file = (std::filesystem::path(timeDir) / "sampling" / (f.name + ".h5")).string();
        writeBins(file, f.accumulator, sys.box.dimension, f.crossSection, sys.time, f.sections);
    }
}

void FunctionObjects::restore(const std::string& timeDir) {
    for (auto& f : profiles_) {
        const auto file = std::filesystem::path(timeDir) / "sampling" / (f.name + ".h5");
        if (!std::filesystem::exists(file)) continue;
        StoredBins stored = readBins(file.string());
        f.accumulator = std::move(stored.accumulator);
    }
}

}  // namespace dpd
