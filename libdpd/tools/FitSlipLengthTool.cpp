#include "tools/FitSlipLengthTool.hpp"

#include "core/Axis.hpp"
#include "core/Error.hpp"
#include "io/TimeDirectories.hpp"
#include "sampling/BinAccumulatorFile.hpp"
#include "sampling/BinProfile.hpp"
#include "sampling/UsableBin.hpp"
#include "tools/FitMode.hpp"
#include "tools/FitModeParts.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <limits>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <tuple>
#include <utility>

namespace dpd {

namespace fs = std::filesystem;

namespace {

// A bin is usable when it saw particles (velocity defined) and, where errors exist, has one.
struct Points {
    FitPoints fit;
    std::vector<std::size_t> rows;  // the table rows of the points
    int withoutVelocity = 0;
    int withoutError = 0;
};

Points usablePoints(const ProfileTableData& t, int component) {
    const std::string u = std::string("u") + axisLetter(component);
    const std::vector<double>& y = t.column(t.axisName());
    const std::vector<double>& vel = t.column(u);
    const std::vector<double>& err = t.column(u + "Err");
    const std::vector<double>* count = t.has("count") ? &t.column("count") : nullptr;
    Points pts;
    std::vector<std::size_t> keep;
    bool anyError = false;
    for (std::size_t i = 0; i < y.size(); ++i) {
        if (count && !usableBin((*count)[i])) {
            ++pts.withoutVelocity;
            continue;
        }
        keep.push_back(i);
        if (err[i] != 0.0) anyError = true;
    }
    for (std::size_t i : keep) {
        if (anyError && err[i] == 0.0) {
            ++pts.withoutError;
            continue;
        }
        pts.fit.profile.y.push_back(y[i]);
        pts.fit.profile.u.push_back(vel[i]);
        pts.rows.push_back(i);
        if (anyError) pts.fit.profile.uErr.push_back(err[i]);
    }
    return pts;
}

// Fewest blocks for errors from the fit applied block by block (a covariance of three coefficients).
constexpr std::size_t kMinErrorBlocks = 4;

// Attaches the blocks in which every point saw particles (and their stress rows, when sampled); says
// why none are attached.
void attachBlocks(const TableBlocks& tableBlocks, Points& pts, FitSlipLengthResult& r) {
    Profile1D& profile = pts.fit.profile;
    const bool stress = tableBlocks.shearStress.size() == tableBlocks.velocities.size();
    for (std::size_t k = 0; k < tableBlocks.velocities.size(); ++k) {
        const auto& block = tableBlocks.velocities[k];
        std::vector<double> u;
        for (std::size_t row : pts.rows)
            if (row < block.size() && std::isfinite(block[row])) u.push_back(block[row]);
        if (u.size() != pts.rows.size()) continue;
        profile.blocks.push_back(std::move(u));
        if (stress) pts.fit.stressBlocks.push_back(tableBlocks.shearStress[k]);
    }
    if (profile.blocks.size() >= kMinErrorBlocks) return;
    if (!tableBlocks.velocities.empty())
        r.errorNote = std::to_string(profile.blocks.size()) + " complete blocks saw particles in every bin, fewer than " +
                      std::to_string(kMinErrorBlocks);
    profile.blocks.clear();
    pts.fit.stressBlocks.clear();
}

// gamma of the first pair of mobile species (NaN when there is none).
double firstMobileGamma(const DpdModel& m) {
    for (int i = 0; i < m.species.size(); ++i) {
        if (m.species[i].frozen) continue;
        for (int j = i; j < m.species.size(); ++j)
            if (!m.species[j].frozen && m.pairs.nSpecies() > j) return m.pairs(i, j).gamma;
    }
    return std::numeric_limits<double>::quiet_NaN();
}

// wallPositions (low high): the channel's walls when they belong to a geometry block.
void readWallPositions(FitSlipLengthSetup& s) {
    if (!s.dict.found("wallPositions")) return;
    s.hasWallPositions = true;
    std::tie(s.wallLow, s.wallHigh) = s.dict.getIncreasingPair("wallPositions", "lower", "upper");
}

}  // namespace

FitSlipLengthSetup readFitSlipLengthSetup(const Dictionary& dict, const Dictionary& dpdProperties, const std::string& caseDir) {
    FitSlipLengthSetup s;
    s.dict = dict;
    s.dpdProperties = dpdProperties;
    s.model = readDpdModel(dpdProperties, caseDir);
    const Dictionary& d = s.dict;
    d.checkKeys({"mode", "profile", "component", "exclude", "fitRange", "slipPredictionNu", "wallPositions", "superBlocks"});
    if (d.found("slipPredictionNu")) s.slipPredictionNu = d.getPositive<double>("slipPredictionNu");
    readWallPositions(s);

    const std::string mode = d.get<std::string>("mode");
    if (!fitModes().has(mode)) d.fail("mode", "unknown mode '" + mode + "' (expected " + fitModes().nameList() + ")");
    s.mode = fitModes().make(mode);

    s.profile = d.get<std::string>("profile");
    if (s.profile.empty() || s.profile.find('/') != std::string::npos)
        d.fail("profile", "expected the name of a table in postProcessing/profileBins/<time>/, without '.dat'");
    s.mode->read(s);
    s.superBlocks = readSuperBlockSetup(d);
    if (s.superBlocks.on() && s.mode->jackknifed(FitSlipLengthResult{}).empty())
        d.fail("superBlocks", "mode " + mode + " has no jackknife over super-blocks yet (mode poiseuille has)");
    return s;
}

namespace {

// The predicted slip length of tunable-slip channel walls, from the central density and nu (the
// dictionary's slipPredictionNu, else the fit's own).
void predictSlip(const FitSlipLengthSetup& s, const ProfileTableData& t, FitSlipLengthResult& r) {
    if (s.hasWallPositions) return;  // walls of a geometry: no tunable slip
    const auto [lower, upper] = channelWalls(s, t, r.axis);
    if (!lower->hasTunableSlip && !upper->hasTunableSlip) return;
    if (lower->asksSlipLength || upper->asksSlipLength) return;  // the ask is the prediction, from its point
    const bool given = s.slipPredictionNu > 0.0;
    const double measured = s.mode->measuredNu(r);
    const bool fitted = std::isfinite(measured);
    if (!given && !fitted)
        s.dict.fail("slipPredictionNu", "the walls have tunable slip but this fit measures no viscosity: give "
                                        "slipPredictionNu (or sample the stress) for the predicted slip length");
    const double nu = given ? s.slipPredictionNu : measured;
    try {
        r.slipPrediction = predictTunableSlip(*lower, *upper, r.densityCentral, nu,
                                              given ? s.dict.fileName() + " slipPredictionNu" : "fit");
    } catch (const std::invalid_argument& e) {
        s.dict.fail(given ? "slipPredictionNu" : "", std::string("no predicted slip length: ") + e.what());
    }
}

// The points with the velocities u of the table's rows (those with none left out), without blocks.
FitPoints withVelocities(const Points& pts, const std::vector<double>& u) {
    FitPoints points;
    const Profile1D& all = pts.fit.profile;
    for (std::size_t i = 0; i < pts.rows.size(); ++i) {
        if (!std::isfinite(u[pts.rows[i]])) continue;
        points.profile.y.push_back(all.y[i]);
        points.profile.u.push_back(u[pts.rows[i]]);
        if (!all.uErr.empty()) points.profile.uErr.push_back(all.uErr[i]);
    }
    return points;
}

// The jackknife over super-blocks (FitSuperBlocks.hpp): the points' profile of all super-blocks but one
// refitted in turn, without blocks, with the table's bin errors; the errors replace the blocks' when
// there are at least `minimum` super-blocks.
void jackknifeErrors(const FitSlipLengthSetup& s, const ProfileTableData& t, const Points& pts, const BlockSums& sums,
                     FitSlipLengthResult& r) {
    const SuperBlockSetup& sb = s.superBlocks;
    const double length = sb.length > 0.0 ? sb.length : sb.decayTimes * s.mode->decayTime(r);
    SuperBlockInfo& info = r.superBlocks;
    if (!(sums.blockTime > 0.0) || sums.counts.empty()) {
        info.note = "no complete sampling blocks";
        return;
    }
    if (!std::isfinite(length) || length <= 0.0) {
        info.note = "no decay time from this fit";
        return;
    }
    const int per = blocksPerSuperBlock(length, sums.blockTime);
    const int m = static_cast<int>(sums.counts.size()) / per;
    info.blocksPerSuperBlock = per;
    info.superBlockLength = per * sums.blockTime;
    if (m < sb.minimum) {
        info.note = std::to_string(sums.counts.size()) + " complete blocks of " + FitPrinter::num(sums.blockTime) +
                    " make " + std::to_string(m) + " super-blocks of " + FitPrinter::num(info.superBlockLength) +
                    ", fewer than " + std::to_string(sb.minimum) + ": sample longer";
        return;
    }
    std::vector<std::vector<double>> estimates;
    for (int left = 0; left < m; ++left) {
        FitSlipLengthResult one = r;
        s.mode->fit(s, t, withVelocities(pts, leaveOneOutVelocities(sums, per, m, left)), one);
        estimates.push_back(s.mode->jackknifed(one));
    }
    std::vector<double> errors;
    for (std::size_t q = 0; q < estimates.front().size(); ++q) {
        std::vector<double> values;
        for (const auto& e : estimates) values.push_back(e[q]);
        errors.push_back(jackknifeError(values));
    }
    s.mode->setJackknifeErrors(r, errors);
    info.superBlocks = m;
}

}  // namespace

FitSlipLengthResult fitSlipLength(const FitSlipLengthSetup& s, const ProfileTableData& t, const std::string& time,
                                  const TableBlocks& blocks) {
    const Dictionary& d = s.dict;
    FitSlipLengthResult r;
    r.mode = s.mode;
    r.time = time;
    r.profileFile = t.file;
    r.component = s.component;
    r.exclude = s.exclude;
    r.axis = axisFromLetter(t.axisName());
    if (r.axis < 0)
        throw IoError(t.file + ": the first column is '" + t.axisName() + "', not a bin axis x, y or z");
    if (r.axis == r.component)
        d.fail(d.found("component") ? "component" : "", std::string("the flow component ") + axisLetter(r.component) +
                                                            " is the axis of the profile " + t.file);
    r.g = s.model.bodyForce->value()[s.component];

    Points pts = usablePoints(t, s.component);
    r.errorNote = blocks.note;
    attachBlocks(blocks, pts, r);
    r.pointsUsed = static_cast<int>(pts.fit.profile.y.size());
    r.binsWithoutVelocity = pts.withoutVelocity;
    r.binsWithoutError = pts.withoutError;

    s.mode->fit(s, t, pts.fit, r);
    if (s.superBlocks.on()) jackknifeErrors(s, t, pts, blocks.sums, r);

    r.densityCentral = centralDensity(t);
    r.gamma = firstMobileGamma(s.model);
    r.nuKineticTheory = std::isfinite(r.gamma) && r.gamma > 0.0 && std::isfinite(r.densityCentral) && r.densityCentral > 0.0
                            ? kineticTheoryViscosity(s.model.kT, r.gamma, r.densityCentral, s.model.cutoff)
                            : std::numeric_limits<double>::quiet_NaN();
    if (s.mode->channel() && s.predictTunableSlip) predictSlip(s, t, r);
    return r;
}

Dictionary fitSlipLengthDictionary(const FitSlipLengthResult& r) {
    Dictionary d;
    d.setValue("mode", r.mode->name());
    if (!r.time.empty()) d.setValue("time", r.time);
    d.setValue("profile", r.profileFile);
    d.setValue("axis", std::string(axisLetter(r.axis)));
    d.setValue("component", std::string(axisLetter(r.component)));
    d.setValue("g", r.g);
    d.setValue("exclude", r.exclude);
    d.setValue("points", r.pointsUsed);
    const BlockErrorInfo& be = r.blockErrors;
    const SuperBlockInfo& sb = r.superBlocks;
    d.setValue("errors", sb.superBlocks > 0 ? "jackknife" : be.blocks > 0 ? "blocks" : "independentBins");
    if (sb.superBlocks > 0) {
        d.setValue("superBlocks", sb.superBlocks);
        d.setValue("blocksPerSuperBlock", sb.blocksPerSuperBlock);
        d.setValue("superBlockLength", sb.superBlockLength);
    }
    if (!sb.note.empty()) d.setValue("superBlocksNote", sb.note);
    if (be.blocks > 0) {
        d.setValue("errorBlocks", be.blocks);
        d.setValue("errorWindow", be.window);
        d.setValue("errorTau", be.tau);
        d.setValue("errorWindowFound", be.windowFound ? "yes" : "no");
    }
    r.mode->write(d, r);
    writeTunableSlipPrediction(d, r.slipPrediction);
    // An estimate for reference, not a measurement; "none" when it cannot be formed.
    if (std::isfinite(r.nuKineticTheory)) {
        d.setValue("nuKineticTheory", r.nuKineticTheory);
        d.setValue("densityKineticTheory", r.densityCentral);
        d.setValue("gammaKineticTheory", r.gamma);
    } else {
        d.setValue("nuKineticTheory", "none");
    }
    return d;
}

namespace {

// Where the printed errors come from: the jackknife over super-blocks, the blocks, or independent bins.
void printErrorSource(std::ostream& out, const FitSlipLengthResult& r) {
    const auto num = &FitPrinter::num;
    const BlockErrorInfo& be = r.blockErrors;
    const SuperBlockInfo& sb = r.superBlocks;
    if (sb.superBlocks > 0) {
        out << "    errors by jackknife over " << sb.superBlocks << " super-blocks of " << num(sb.superBlockLength)
            << " (" << sb.blocksPerSuperBlock << " sampling blocks each)\n";
        return;
    }
    if (!sb.note.empty()) out << "    no jackknife over super-blocks: " << sb.note << "\n";
    if (be.blocks > 0) {
        out << "    errors from the fit block by block: " << be.blocks << " blocks, correlation time " << num(be.tau)
            << " blocks (window " << be.window << ")\n";
        if (!be.windowFound)
            out << "    warning: the blocks stay correlated over a quarter of the run: the errors are uncertain "
                   "(sample longer)\n";
    } else
        out << "    errors with the bins taken as independent (too small where the bins fluctuate together): "
            << (r.errorNote.empty() ? "no blocks" : r.errorNote) << "\n";
}

}  // namespace

void printFitSlipLength(std::ostream& out, const FitSlipLengthResult& r) {
    const FitPrinter printer(out);
    const auto num = &FitPrinter::num;
    const std::string ax = axisLetter(r.axis);
    out << "Time = " << (r.time.empty() ? "?" : r.time) << "\n";
    out << "    profile " << r.profileFile << ": u" << axisLetter(r.component) << " across " << ax << ", "
        << r.pointsUsed << " bins";
    if (r.binsWithoutVelocity) out << ", " << r.binsWithoutVelocity << " without particles left out";
    if (r.binsWithoutError) out << ", " << r.binsWithoutError << " without an error bar left out";
    out << "\n    mode " << r.mode->name() << ", g = " << num(r.g) << ", exclude " << num(r.exclude) << "\n";
    printErrorSource(out, r);
    r.mode->print(printer, ax, r);
    if (r.slipPrediction.any) {
        const TunableSlipPrediction& sp = r.slipPrediction;
        const auto predicted = [&](int k) {
            return sp.tunable[k] ? num(sp.slipLength[k]) + " (alpha " + num(sp.alpha[k]) + ")" : std::string("none");
        };
        printer.row("slip length predicted", predicted(0), predicted(1));
        printer.row("", "(tunable slip, rho = " + num(sp.density) + ", nu = " + num(sp.nu) + " from " + sp.nuSource + ")");
    }
    if (std::isfinite(r.nuKineticTheory))
        printer.row("nu kinetic theory", num(r.nuKineticTheory),
                    "(estimate: rho = " + num(r.densityCentral) + ", gamma = " + num(r.gamma) + ")");
    else
        printer.row("nu kinetic theory", "none (no pair of mobile species or no density)");
}

TableBlocks readTableBlocks(const std::string& samplingFile, const ProfileTableData& t, int component) {
    TableBlocks b;
    const std::string name = fs::path(samplingFile).filename().string();
    if (!fs::exists(samplingFile)) {
        b.note = "no sampling file " + name + " beside the table's time";
        return b;
    }
    const StoredBins stored = readBins(samplingFile);
    const BinLayout& layout = stored.accumulator.layout();
    const std::vector<double>& centres = t.column(t.axisName());
    bool same = !layout.twoAxes() && layout.nBins == static_cast<int>(centres.size()) &&
                axisFromLetter(t.axisName()) == layout.axis;
    for (int i = 0; same && i < layout.nBins; ++i)
        same = std::abs(layout.centre(i) - centres[i]) <= 1e-9 * (1.0 + std::abs(centres[i]));
    if (!same) {
        b.note = "the bins of " + name + " are not the table's";
        return b;
    }
    b.velocities = blockVelocities(stored.accumulator, component);
    b.sums = {blockVelocitySums(stored.accumulator, component)};
    b.blockSamples = stored.accumulator.blockSamples();
    if (stored.accumulator.stressFlowAxis() >= 0)
        b.shearStress = blockShearStress(stored.accumulator, stored.crossSection, stored.dimension);
    if (b.velocities.empty()) b.note = name + " has no complete block";
    return b;
}

std::string profileTablePath(const std::string& caseDir, const std::string& time, const std::string& profile) {
    return (fs::path(caseDir) / "postProcessing" / "profileBins" / time / (profile + ".dat")).string();
}

TimesWithInput selectProfileTimes(const FitSlipLengthOptions& o, const Dictionary& dict, const std::string& profile) {
    const auto tableOf = [&](const TimeDirectory& t) { return profileTablePath(o.caseDir, t.name, profile); };
    return selectTimesWithInput(
        o.caseDir, o.time, o.latestTime, [&](const TimeDirectory& t) { return fs::exists(tableOf(t)); },
        [&](const TimeDirectory& t) {
            throw InputError(dict.fileName(), dict.lineOf("profile"), "profile",
                             "no profile table " + tableOf(t) + " (run profileBins first)");
        },
        [&](const std::vector<std::string>&) {
            throw InputError(dict.fileName(), dict.lineOf("profile"), "profile",
                             "no time of case '" + o.caseDir + "' has the profile table postProcessing/profileBins/<time>/" +
                                 profile + ".dat (run profileBins first)");
        });
}

std::vector<FitSlipLengthResult> runFitSlipLength(const FitSlipLengthOptions& o, std::ostream& out) {
    const fs::path caseDir(o.caseDir);
    const Dictionary dict = Dictionary::readFile((caseDir / "system" / "fitSlipLengthDict").string());
    const Dictionary props = Dictionary::readFile((caseDir / "constant" / "dpdProperties").string());
    const FitSlipLengthSetup setup = readFitSlipLengthSetup(dict, props, o.caseDir);
    const Dictionary control = setup.superBlocks.on() ? Dictionary::readFile((caseDir / "system" / "controlDict").string())
                                                    : Dictionary();

    const TimesWithInput selected = selectProfileTimes(o, dict, setup.profile);
    const auto tableOf = [&](const TimeDirectory& t) { return profileTablePath(o.caseDir, t.name, setup.profile); };
    std::vector<FitSlipLengthResult> results;
    for (const TimeDirectory& t : selected.times) {
        const ProfileTableData table = readProfileTable(tableOf(t));
        const fs::path sampling = caseDir / t.name / "sampling" / (setup.profile + ".h5");
        TableBlocks blocks = readTableBlocks(sampling.string(), table, setup.component);
        if (setup.superBlocks.on() && blocks.blockSamples > 0)
            blocks.sums.blockTime = samplingBlockTime(control, setup.profile, blocks.blockSamples, dict);
        results.push_back(fitSlipLength(setup, table, t.name, blocks));
        results.back().profileFile = (fs::path("postProcessing") / "profileBins" / t.name / (setup.profile + ".dat")).string();
    }
    for (const auto& t : selected.skipped) out << "Time = " << t << ": no profile table " << setup.profile << ".dat, skipped\n";
    for (const auto& r : results) {
        const fs::path dir = caseDir / "postProcessing" / "fitSlipLength" / r.time;
        std::error_code ec;
        fs::create_directories(dir, ec);
        if (ec) throw IoError("cannot create '" + dir.string() + "': " + ec.message());
        writeDictionaryFile((dir / "fit.dat").string(), fitSlipLengthDictionary(r));
    }
    for (const auto& r : results) {
        printFitSlipLength(out, r);
        out << "    written " << (fs::path("postProcessing") / "fitSlipLength" / r.time / "fit.dat").string() << "\n";
    }
    return results;
}

}  // namespace dpd
