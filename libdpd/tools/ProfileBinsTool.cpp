#include "tools/ProfileBinsTool.hpp"
#include "sampling/BlockStatistics.hpp"

#include "core/Axis.hpp"
#include "core/Error.hpp"
#include "io/Dictionary.hpp"
#include "io/Snapshot.hpp"
#include "io/TimeDirectories.hpp"
#include "sampling/BinLayoutDictionary.hpp"
#include "sampling/ProfileGrid.hpp"
#include "sampling/ProfileTable.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <ostream>
#include <sstream>

namespace dpd {

namespace fs = std::filesystem;

namespace {

// Bins whose centre is farther than margin from both ends; all bins when none is.
std::vector<std::size_t> centralBins(const BinProfile& p, double lo, double hi, double margin) {
    std::vector<std::size_t> keep;
    for (std::size_t b = 0; b < p.centre.size(); ++b)
        if (p.centre[b] - lo > margin && hi - p.centre[b] > margin) keep.push_back(b);
    if (keep.empty())
        for (std::size_t b = 0; b < p.centre.size(); ++b) keep.push_back(b);
    return keep;
}

struct Means {
    double density = 0.0, kT = 0.0;
    bool kTValid = false;
};

Means centralMeans(const BinProfile& p, const std::vector<std::size_t>& bins) {
    Means m;
    double weight = 0.0;
    for (std::size_t b : bins) {
        m.density += p.density[b];
        if (p.count[b] >= 3.0) {
            m.kT += p.count[b] * p.kT[b];
            weight += p.count[b];
        }
    }
    if (!bins.empty()) m.density /= static_cast<double>(bins.size());
    m.kTValid = weight > 0.0;
    m.kT = m.kTValid ? m.kT / weight : 0.0;
    return m;
}

std::vector<std::string> samplingFiles(const fs::path& timeDir) {
    std::vector<std::string> files;
    const fs::path dir = timeDir / "sampling";
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) return files;
    for (const auto& e : fs::directory_iterator(dir, ec))
        if (e.is_regular_file() && e.path().extension() == ".h5") files.push_back(e.path().string());
    std::sort(files.begin(), files.end());
    return files;
}

std::vector<TimeDirectory> selectedTimes(const ProfileBinsOptions& o) {
    try {
        return selectTimes(o.caseDir, o.time, o.latestTime);
    } catch (const std::runtime_error& e) {
        throw IoError(e.what());
    }
}

std::string relativeToCase(const std::string& path, const std::string& caseDir) {
    std::error_code ec;
    const fs::path rel = fs::relative(path, caseDir, ec);
    return ec || rel.empty() ? path : rel.string();
}

std::string withError(double value, double error, bool haveError) {
    std::ostringstream os;
    os << std::setprecision(6) << value;
    if (haveError) os << " +- " << std::setprecision(2) << error;
    return os.str();
}

}  // namespace

ProfileSummary summariseProfile(const BinProfile& p, double lo, double hi, double margin) {
    ProfileSummary s;
    s.samples = p.samples;
    s.blocksForErrors = p.blocksForErrors;
    const std::vector<std::size_t> bins = centralBins(p, lo, hi, margin);
    const Means m = centralMeans(p, bins);
    s.binsUsed = static_cast<int>(bins.size());
    s.density = m.density;
    s.kT = m.kT;
    return s;
}

ProfileSummary summariseBins(const StoredBins& bins, double margin) {
    const BinAccumulator& acc = bins.accumulator;
    const BinLayout& L = acc.layout();
    const BinProfile whole = computeProfile(acc, bins.crossSection, bins.dimension);
    ProfileSummary s = summariseProfile(whole, L.lo, L.hi, margin);
    if (whole.blocksForErrors < 2) return s;
    // The same means block by block: their spread is the honest error of correlated samples.
    const std::vector<std::size_t> central = centralBins(whole, L.lo, L.hi, margin);
    std::vector<double> density, kT;
    for (std::size_t k = 0; k < acc.blocks().size(); ++k) {
        if (acc.samplesPerBlock()[k] != acc.blockSamples()) continue;
        const BinAccumulator one = BinAccumulator::fromBlocks(L, acc.speciesMask(), acc.blockSamples(), {acc.blocks()[k]},
                                                              {acc.samplesPerBlock()[k]});
        const Means m = centralMeans(computeProfile(one, bins.crossSection, bins.dimension), central);
        density.push_back(m.density);
        if (m.kTValid) kT.push_back(m.kT);
    }
    s.densityErr = standardErrorOfMean(density);
    s.kTErr = standardErrorOfMean(kT);
    return s;
}

BinAccumulator snapshotAccumulator(const Dictionary& d, const Snapshot& snap) {
    std::vector<std::string> keys = binLayoutKeys();
    keys.push_back("species");
    d.checkKeys(keys);
    const BinLayout layout = readBinLayout(d, snap.box);

    const std::size_t nSpecies = snap.speciesNames.size();
    std::vector<std::uint8_t> mask(nSpecies, 0);
    if (d.found("species")) {
        for (const std::string& name : d.get<std::vector<std::string>>("species")) {
            const auto it = std::find(snap.speciesNames.begin(), snap.speciesNames.end(), name);
            if (it == snap.speciesNames.end()) {
                std::string known;
                for (const auto& n : snap.speciesNames) known += (known.empty() ? "" : " ") + n;
                d.fail("species", "the snapshot has no species '" + name + "' (it has: " + known + ")");
            }
            mask[it - snap.speciesNames.begin()] = 1;
        }
    } else {
        for (std::size_t s = 0; s < nSpecies; ++s)
            mask[s] = (s < snap.speciesFrozen.size() && snap.speciesFrozen[s]) ? 0 : 1;
    }
    return BinAccumulator(layout, mask, 1);
}

BinProfile binSnapshot(const Dictionary& d, const Snapshot& snap, BinLayout* layoutOut) {
    BinAccumulator acc = snapshotAccumulator(d, snap);
    acc.sample(snap.particles);
    const double crossSection = binCrossSection(acc.layout(), snap.box);
    if (layoutOut) *layoutOut = acc.layout();
    return computeProfile(acc, crossSection, snap.box.dimension);
}

namespace {

std::vector<ProfileBinsItem> snapshotProfileBins(const ProfileBinsOptions& o) {
    const fs::path caseDir(o.caseDir);
    const Dictionary dict = Dictionary::readFile((caseDir / "system" / "profileBinsDict").string());
    std::vector<ProfileBinsItem> items;
    for (const TimeDirectory& t : selectedTimes(o)) {
        const std::string file = (caseDir / t.name / snapshotFileName).string();
        if (!fs::exists(file)) throw IoError("time directory '" + (caseDir / t.name).string() + "' has no " + snapshotFileName);
        const Snapshot snap = readSnapshot(file);
        ProfileBinsItem item;
        BinLayout layout;
        item.profile = binSnapshot(dict, snap, &layout);
        item.time = t.name;
        item.name = "snapshot";
        item.axisName = axisLetter(layout.axis);
        item.layout = layout;
        item.sections = readSections(dict, layout);
        item.source = file;
        item.output = (caseDir / "postProcessing" / "profileBins" / t.name / "snapshot.dat").string();
        item.summary = summariseProfile(item.profile, layout.lo, layout.hi, o.margin);
        items.push_back(std::move(item));
    }
    return items;
}

// The times with sampling files: a time written before sampling started has none.
TimesWithInput timesWithSampling(const ProfileBinsOptions& o) {
    const fs::path caseDir(o.caseDir);
    const std::string why = ": the solver writes them for the binnedProfile functions of system/controlDict; use -snapshot "
                            "to bin " + std::string(snapshotFileName) + " instead";
    try {
        return selectTimesWithInput(
            o.caseDir, o.time, o.latestTime, [&](const TimeDirectory& t) { return !samplingFiles(caseDir / t.name).empty(); },
            [&](const TimeDirectory& t) {
                throw IoError("time directory '" + (caseDir / t.name).string() + "' has no sampling files (sampling/*.h5)" + why);
            },
            [&](const std::vector<std::string>& without) {
                std::string names;
                for (const auto& n : without) names += (names.empty() ? "'" : "', '") + (caseDir / n).string();
                throw IoError("no sampling files (sampling/*.h5) in time director" +
                              std::string(without.size() == 1 ? "y " : "ies ") + names + "'" + why);
            });
    } catch (const IoError&) {
        throw;
    } catch (const std::runtime_error& e) {
        throw IoError(e.what());
    }
}

}  // namespace

std::vector<ProfileBinsItem> computeProfileBins(const ProfileBinsOptions& o, std::vector<std::string>* skipped) {
    if (o.snapshot) return snapshotProfileBins(o);
    const fs::path caseDir(o.caseDir);
    const TimesWithInput selected = timesWithSampling(o);
    std::vector<ProfileBinsItem> items;
    for (const TimeDirectory& t : selected.times)
        for (const std::string& file : samplingFiles(caseDir / t.name)) {
            const StoredBins bins = readBins(file);
            ProfileBinsItem item;
            item.time = t.name;
            item.name = fs::path(file).stem().string();
            item.axisName = axisLetter(bins.accumulator.layout().axis);
            item.layout = bins.accumulator.layout();
            item.sections = bins.sections;
            item.source = file;
            item.output = (caseDir / "postProcessing" / "profileBins" / t.name / (item.name + ".dat")).string();
            item.profile = computeProfile(bins.accumulator, bins.crossSection, bins.dimension);
            item.summary = summariseBins(bins, o.margin);
            items.push_back(std::move(item));
        }
    if (skipped) *skipped = selected.skipped;
    return items;
}

void writeProfileBins(const std::vector<ProfileBinsItem>& items) {
    for (const auto& item : items) {
        if (!item.layout.twoAxes()) {
            writeProfileTable(item.output, item.axisName, item.profile);
            continue;
        }
        writeProfileTable(item.output, item.axisName, item.profile, axisLetter(item.layout.axis2));
        const fs::path dir = fs::path(item.output).parent_path();
        writeProfileImage((dir / (item.name + ".vti")).string(), item.layout, item.profile);
        for (const double x : item.sections)
            writeProfileTable((dir / sectionFileName(item.name, item.layout, x)).string(), axisLetter(item.layout.axis2),
                              profileSection(item.layout, item.profile, x));
    }
}

void printProfileBins(std::ostream& out, const std::vector<ProfileBinsItem>& items, const std::string& caseDir) {
    std::string lastTime;
    for (const auto& item : items) {
        if (item.time != lastTime) out << "Time = " << item.time << "\n";
        lastTime = item.time;
        const ProfileSummary& s = item.summary;
        const bool errors = s.blocksForErrors >= 2;
        out << "    " << item.name << ": ";
        if (item.layout.twoAxes())
            out << item.layout.nBins << " x " << item.layout.nBins2 << " bins on " << item.axisName << "-"
                << axisLetter(item.layout.axis2) << ", ";
        else out << item.profile.centre.size() << " bins along " << item.axisName << ", ";
        out
            << s.samples << (s.samples == 1 ? " sample, " : " samples, ");
        if (errors) out << s.blocksForErrors << " blocks for the errors\n";
        else out << "no error bars (fewer than 2 complete blocks)\n";
        out << "        central " << s.binsUsed << " bins: density " << withError(s.density, s.densityErr, errors)
            << ", kT " << withError(s.kT, s.kTErr, errors) << "\n";
        out << "        written " << relativeToCase(item.output, caseDir)
            << (item.layout.twoAxes() ? " and " + item.name + ".vti beside it, " + std::to_string(item.sections.size()) + " section(s)" : "")
            << "\n";
    }
}

std::vector<ProfileBinsItem> runProfileBins(const ProfileBinsOptions& options, std::ostream& out) {
    std::vector<std::string> skipped;
    std::vector<ProfileBinsItem> items = computeProfileBins(options, &skipped);
    writeProfileBins(items);
    for (const auto& t : skipped) out << "Time = " << t << ": no sampling files, skipped\n";
    printProfileBins(out, items, options.caseDir);
    return items;
}

}  // namespace dpd
