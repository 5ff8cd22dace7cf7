#include "sampling/ChainStatistics.hpp"

#include "core/Axis.hpp"
#include "core/Error.hpp"
#include "io/AtomicFile.hpp"
#include "io/Dictionary.hpp"
#include "io/Hdf5File.hpp"
#include "io/TimeDirectories.hpp"
#include "parallel/RankChains.hpp"
#include "sampling/ChainShapes.hpp"
#include "system/System.hpp"

#include <filesystem>

namespace dpd {

namespace fs = std::filesystem;

namespace {

int activeAxis(const Dictionary& d, const std::string& key, const System& sys) {
    const int axis = d.getAxis(key);
    if (!sys.box.isActiveAxis(axis)) d.fail(key, "a 2-D scene has no y axis");
    return axis;
}

void resizeBins(ChainBinSums& b, std::size_t n) {
    for (auto* v : {&b.count, &b.gyration2, &b.span, &b.endToEndFlow2}) v->assign(n, 0.0);
}

std::vector<double> flatten(const std::vector<ChainSample>& samples) {
    std::vector<double> rows;
    for (const ChainSample& s : samples)
        rows.insert(rows.end(), {s.time, s.gyration2, s.endToEnd2, s.endToEndFlow, s.endToEndFlow2, s.span});
    return rows;
}

}  // namespace

std::unique_ptr<FunctionObject> ChainStatistics::New(const Dictionary& d, const std::string& name, const System& sys) {
    d.checkKeys({"type", "flowAxis", "startTime", "sampleInterval", "samplesPerBlock", "axis", "nBins", "min", "max"});
    if (sys.bonds.empty()) d.fail("type", "chainStatistics needs chains (the snapshot holds no bonds)");
    auto f = std::make_unique<ChainStatistics>();
    f->name_ = name;
    f->flowAxis_ = activeAxis(d, "flowAxis", sys);
    f->startTime_ = d.getOrDefault<double>("startTime", 0.0);
    f->sampleInterval_ = d.found("sampleInterval") ? d.getPositive<long>("sampleInterval") : 1;
    f->samplesPerBlock_ = d.found("samplesPerBlock") ? d.getPositive<long>("samplesPerBlock") : 20;
    if (d.found("axis")) {
        f->binAxis_ = activeAxis(d, "axis", sys);
        f->binMin_ = d.getOrDefault<double>("min", sys.box.lo[f->binAxis_]);
        f->binMax_ = d.getOrDefault<double>("max", sys.box.hi[f->binAxis_]);
        if (!(f->binMax_ > f->binMin_)) d.fail("max", "must exceed min");
        resizeBins(f->bins_, static_cast<std::size_t>(d.getPositive<long>("nBins")));
    } else if (d.found("nBins") || d.found("min") || d.found("max")) {
        d.fail(d.found("nBins") ? "nBins" : (d.found("min") ? "min" : "max"), "only with axis (bins by chain centre)");
    }
    return f;
}

void ChainStatistics::execute(const System& sys) {
    if (sys.time < startTime_ - 1e-9 * sys.dt()) return;
    if (sys.step % sampleInterval_ != 0) return;
    std::vector<ChainShape> shapes;
    if (const SlabDomain* domain = sys.domain()) {
        // The chains lie on several ranks: their bond vectors and heads are gathered on the first,
        // which samples them all (the others hold no samples).
        const Communicator& comm = domain->communicator();
        Bonds whole = bondsOnRoot(comm, sys.bonds.bonds(), sys.particles);
        const std::vector<Eigen::Vector3d> heads = positionsOnRoot(comm, chainHeadIds(sys.bonds), sys.particles);
        if (!comm.isRoot()) return;
        shapes = chainShapes(ChainBonds(std::move(whole)), heads, sys.box);
    } else {
        shapes = chainShapes(sys.bonds, sys.particles, sys.box);
    }
    ChainSample s;
    s.time = sys.time;
    const double n = static_cast<double>(shapes.size());
    for (const ChainShape& c : shapes) {
        const double along = c.endToEnd[flowAxis_];
        s.gyration2 += c.gyration2 / n;
        s.endToEnd2 += c.endToEnd.squaredNorm() / n;
        s.endToEndFlow += along / n;
        s.endToEndFlow2 += along * along / n;
        s.span += c.span[flowAxis_] / n;
        if (binAxis_ < 0) continue;
        const double x = (c.centre[binAxis_] - binMin_) / (binMax_ - binMin_);
        if (!(x >= 0.0 && x < 1.0)) continue;
        const auto k = static_cast<std::size_t>(x * bins_.count.size());
        bins_.count[k] += 1.0;
        bins_.gyration2[k] += c.gyration2;
        bins_.span[k] += c.span[flowAxis_];
        bins_.endToEndFlow2[k] += along * along;
    }
    samples_.push_back(s);
}

void ChainStatistics::write(const std::string& timeDir, const System& sys) const {
    if (samples_.empty()) return;
    const fs::path stateFile = fs::path(timeDir) / "chains" / (name_ + ".h5");
    fs::create_directories(stateFile.parent_path());
    Hdf5Writer file(stateFile.string());
    file.writeDoubles("series", flatten(samples_), {samples_.size(), kChainSampleColumns});
    if (binAxis_ >= 0)
        for (const auto& [name, v] : {std::pair{"binCount", &bins_.count}, {"binGyration2", &bins_.gyration2},
                                      {"binSpan", &bins_.span}, {"binEndToEndFlow2", &bins_.endToEndFlow2}})
            file.writeDoubles(name, *v);
    file.commit();
    // The user's table: postProcessing/<name>/<time>/, beside the time directory.
    const fs::path table = fs::path(timeDir).parent_path() / "postProcessing" / name_ / timeName(sys.time);
    writeTextFileAtomically((table / "chainStatistics.dat").string(), chainStatisticsTable(samples_, samplesPerBlock_, flowAxis_), true);
    if (binAxis_ >= 0)
        writeTextFileAtomically((table / "chainBins.dat").string(), chainBinsTable(bins_, binAxis_, binMin_, binMax_, flowAxis_), true);
}

void ChainStatistics::restore(const std::string& timeDir) {
    const fs::path stateFile = fs::path(timeDir) / "chains" / (name_ + ".h5");
    if (!fs::exists(stateFile)) return;
    const Hdf5Reader file(stateFile.string());
    std::vector<hsize_t> dims;
    const std::vector<double> rows = file.readDoubles("series", &dims);
    samples_.clear();
    for (std::size_t k = 0; k + kChainSampleColumns <= rows.size(); k += kChainSampleColumns)
        samples_.push_back({rows[k], rows[k + 1], rows[k + 2], rows[k + 3], rows[k + 4], rows[k + 5]});
    if (binAxis_ < 0) return;
    for (const auto& [name, v] : {std::pair{"binCount", &bins_.count}, {"binGyration2", &bins_.gyration2},
                                  {"binSpan", &bins_.span}, {"binEndToEndFlow2", &bins_.endToEndFlow2}}) {
        const std::vector<double> stored = file.readDoubles(name);
        if (stored.size() != v->size())
            throw IoError(stateFile.string() + ": dataset '" + name + "' has " + std::to_string(stored.size()) +
                          " bins, the function has " + std::to_string(v->size()));
        *v = stored;
    }
}

}  // namespace dpd
