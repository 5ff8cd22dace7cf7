#include "tools/SlipTensorTool.hpp"

#include "analysis/CorrelatedMean.hpp"
#include "core/Axis.hpp"
#include "core/Error.hpp"
#include "io/TimeDirectories.hpp"
#include "sampling/UsableBin.hpp"
#include "tools/FitMode.hpp"
#include "tools/FitModeParts.hpp"

#include <array>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <limits>
#include <optional>
#include <ostream>
#include <sstream>

namespace dpd {

namespace fs = std::filesystem;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The fit setup of one velocity component: the user's dictionary with the component set.
FitSlipLengthSetup componentSetup(const Dictionary& fitDict, const Dictionary& dpdProperties, const std::string& caseDir,
                                  int component) {
    Dictionary d = fitDict;
    d.setValue("component", std::string(axisLetter(component)));
    FitSlipLengthSetup s = readFitSlipLengthSetup(d, dpdProperties, caseDir);
    s.predictTunableSlip = false;  // the uniform wall's formula says nothing of stripes
    return s;
}

// The stripes' axis of the channel's striped walls (where both are striped, they must agree).
int stripesAxis(const FitSlipLengthSetup& s, const ProfileTableData& t, int axis) {
    const auto [lower, upper] = channelWalls(s, t, axis);
    int stripes = -1;
    for (const PlanarWallSettings* w : {lower, upper}) {
        if (!w->hasStripes) continue;
        if (stripes >= 0 && w->stripes.axis != stripes)
            s.dpdProperties.fail("walls", "the stripes of walls '" + lower->name + "' and '" + upper->name +
                                              "' run across different axes: the slip tensor needs one");
        stripes = w->stripes.axis;
    }
    if (stripes < 0)
        s.dpdProperties.fail("walls", "slipTensor measures striped walls, and walls '" + lower->name + "' and '" +
                                          upper->name + "' have no stripes (tunableSlip { ... stripes { ... } })");
    return stripes;
}

// The bins that hold fluid (enough particle-samples) between the walls.
std::vector<std::size_t> fluxRows(const ProfileTableData& t, double low, double high) {
    const std::vector<double>& y = t.column(t.axisName());
    const std::vector<double>* count = t.has("count") ? &t.column("count") : nullptr;
    std::vector<std::size_t> rows;
    for (std::size_t i = 0; i < y.size(); ++i)
        if (y[i] > low && y[i] < high && (!count || usableBin((*count)[i]))) rows.push_back(i);
    return rows;
}

// sum_i w_i u_i over the rows, in the mean profile and in every block that saw all of them.
MeasuredFlux binnedFlux(const ProfileTableData& t, int component, const TableBlocks& blocks,
                        const std::vector<std::size_t>& rows, const std::vector<double>& weights) {
    const std::string u = std::string("u") + axisLetter(component);
    const std::vector<double>& vel = t.column(u);
    const std::vector<double>& err = t.column(u + "Err");
    MeasuredFlux f;
    double variance = 0.0;
    for (std::size_t k = 0; k < rows.size(); ++k) {
        f.value += weights[k] * vel[rows[k]];
        variance += weights[k] * weights[k] * err[rows[k]] * err[rows[k]];
    }
    for (const auto& block : blocks.velocities) {
        double q = 0.0;
        bool complete = true;
        for (std::size_t k = 0; k < rows.size() && complete; ++k) {
            complete = rows[k] < block.size() && std::isfinite(block[rows[k]]);
            if (complete) q += weights[k] * block[rows[k]];
        }
        if (complete) f.blocks.push_back(q);
    }
    if (f.blocks.size() < 4) {
        f.blocks.clear();
        f.error = std::sqrt(variance);
    } else {
        f.error = correlatedStandardError(f.blocks);
    }
    return f;
}

// The flux across the force over the flux along it, and its error (from the blocks when both fluxes
// have the same ones: the ratio linearised block by block keeps their correlation).
void transverseRatio(SlipTensorResult& r) {
    const double c = std::cos(r.thetaDegrees * kPi / 180.0), s = std::sin(r.thetaDegrees * kPi / 180.0);
    const MeasuredFlux& p = r.fluxParallel;
    const MeasuredFlux& q = r.fluxPerpendicular;
    const double along = p.value * c + q.value * s, across = p.value * s - q.value * c;
    r.transverseFluxRatio = across / along;
    const double R = r.transverseFluxRatio;
    if (!p.blocks.empty() && p.blocks.size() == q.blocks.size()) {
        std::vector<double> linear;
        for (std::size_t k = 0; k < p.blocks.size(); ++k) {
            const double a = p.blocks[k] * c + q.blocks[k] * s, t = p.blocks[k] * s - q.blocks[k] * c;
            linear.push_back((t - R * a) / along);
        }
        r.transverseFluxRatioError = correlatedStandardError(linear);
    } else {
        r.transverseFluxRatioError =
            std::hypot((s - R * c) * p.error, (c + R * s) * q.error) / std::abs(along);
    }
}

std::string componentText(const SlipTensorResult& r, bool parallel) {
    const FitSlipLengthResult& f = parallel ? r.parallel : r.perpendicular;
    std::ostringstream os;
    os << std::setprecision(5);
    if (!(parallel ? r.parallelFitted : r.perpendicularFitted)) return "not driven (no force along it)";
    os << f.poiseuille.lower.slipLength << " +- " << f.poiseuille.lower.slipLengthErr << " (lower), "
       << f.poiseuille.upper.slipLength << " +- " << f.poiseuille.upper.slipLengthErr << " (upper), mean "
       << SlipTensorResult::wallsMean(f) << " +- " << SlipTensorResult::wallsMeanError(f) << "; nu "
       << f.poiseuille.nu << " +- " << f.poiseuille.nuErr;
    return os.str();
}

}  // namespace

double SlipTensorResult::wallsMean(const FitSlipLengthResult& r) {
    return 0.5 * (r.poiseuille.lower.slipLength + r.poiseuille.upper.slipLength);
}

double SlipTensorResult::wallsMeanError(const FitSlipLengthResult& r) {
    return 0.5 * std::hypot(r.poiseuille.lower.slipLengthErr, r.poiseuille.upper.slipLengthErr);
}

double SlipTensorResult::slipParallel() const { return parallelFitted ? wallsMean(parallel) : kNaN; }

double SlipTensorResult::slipPerpendicular() const { return perpendicularFitted ? wallsMean(perpendicular) : kNaN; }

double SlipTensorResult::slipEffective() const {
    const double c = std::cos(thetaDegrees * kPi / 180.0), s = std::sin(thetaDegrees * kPi / 180.0);
    if (!perpendicularFitted) return slipParallel();
    if (!parallelFitted) return slipPerpendicular();
    return slipParallel() * c * c + slipPerpendicular() * s * s;
}

double SlipTensorResult::slipEffectiveError() const {
    const double c = std::cos(thetaDegrees * kPi / 180.0), s = std::sin(thetaDegrees * kPi / 180.0);
    if (!perpendicularFitted) return wallsMeanError(parallel);
    if (!parallelFitted) return wallsMeanError(perpendicular);
    return std::hypot(wallsMeanError(parallel) * c * c, wallsMeanError(perpendicular) * s * s);
}

SlipTensorResult slipTensor(const Dictionary& fitDict, const Dictionary& dpdProperties, const std::string& caseDir,
                            const ProfileTableData& t,
                            const std::string& samplingFile, const std::string& time) {
    if (fitDict.get<std::string>("mode") != "poiseuille")
        fitDict.fail("mode", "slipTensor fits the Poiseuille flow of each component: mode poiseuille");
    if (fitDict.found("component"))
        fitDict.fail("component", "slipTensor fits both components in the walls' plane: leave component out");
    SlipTensorResult r;
    r.time = time;
    r.profileFile = t.file;
    r.axis = axisFromLetter(t.axisName());
    if (r.axis < 0) throw IoError(t.file + ": the first column is '" + t.axisName() + "', not a bin axis x, y or z");

    const Eigen::Vector3d g = readDpdModel(dpdProperties, caseDir).bodyForce->value();
    const int a1 = (r.axis + 1) % 3, a2 = (r.axis + 2) % 3;
    if (g[a1] == 0.0 && g[a2] == 0.0)
        dpdProperties.fail("bodyForce", "no force in the walls' plane drives the channel");
    // One fit setup per driven in-plane axis, read once.
    std::array<std::optional<FitSlipLengthSetup>, 3> setups;
    for (int a : {a1, a2})
        if (g[a] != 0.0) setups[a] = componentSetup(fitDict, dpdProperties, caseDir, a);
    const FitSlipLengthSetup& first = setups[a1] ? *setups[a1] : *setups[a2];
    r.perpendicularAxis = stripesAxis(first, t, r.axis);
    if (r.perpendicularAxis == r.axis)
        dpdProperties.fail("walls", "the stripes run across the walls' normal " + t.axisName() + ": give an axis in the walls' plane");
    r.parallelAxis = 3 - r.axis - r.perpendicularAxis;
    r.gParallel = g[r.parallelAxis];
    r.gPerpendicular = g[r.perpendicularAxis];
    r.thetaDegrees = std::atan2(r.gPerpendicular, r.gParallel) * 180.0 / kPi;

    const bool sampled = fs::exists(samplingFile);
    const auto blocksOf = [&](int component) { return sampled ? readTableBlocks(samplingFile, t, component) : TableBlocks{}; };
    const TableBlocks parallelBlocks = blocksOf(r.parallelAxis), perpendicularBlocks = blocksOf(r.perpendicularAxis);
    if ((r.parallelFitted = setups[r.parallelAxis].has_value()))
        r.parallel = fitSlipLength(*setups[r.parallelAxis], t, time, parallelBlocks);
    if ((r.perpendicularFitted = setups[r.perpendicularAxis].has_value()))
        r.perpendicular = fitSlipLength(*setups[r.perpendicularAxis], t, time, perpendicularBlocks);

    // Fluxes per unit width: the bins' volume flux weighted by their density over the centre's.
    const ChannelBounds bounds = channelBounds(first, t, r.axis);
    r.densityCentral = centralDensity(t);
    const std::vector<std::size_t> rows = fluxRows(t, bounds.low, bounds.high);
    const std::vector<double>& y = t.column(t.axisName());
    const std::vector<double>& density = t.column("density");
    const double width = y.size() > 1 ? (y.back() - y.front()) / static_cast<double>(y.size() - 1) : 0.0;
    std::vector<double> weights;
    for (std::size_t row : rows) weights.push_back(density[row] / r.densityCentral * width);
    r.binsInFlux = static_cast<int>(rows.size());
    r.fluxParallel = binnedFlux(t, r.parallelAxis, parallelBlocks, rows, weights);
    r.fluxPerpendicular = binnedFlux(t, r.perpendicularAxis, perpendicularBlocks, rows, weights);
    transverseRatio(r);
    return r;
}

Dictionary slipTensorDictionary(const SlipTensorResult& r) {
    Dictionary d;
    // An undriven component's fit is "none" (a dictionary stores no NaN).
    const auto setNumber = [&](const char* key, double value) {
        if (std::isfinite(value)) d.setValue(key, value);
        else d.setValue(key, "none");
    };
    d.setValue("mode", "slipTensor");
    if (!r.time.empty()) d.setValue("time", r.time);
    d.setValue("profile", r.profileFile);
    d.setValue("axis", std::string(axisLetter(r.axis)));
    d.setValue("axisParallel", std::string(axisLetter(r.parallelAxis)));
    d.setValue("axisPerpendicular", std::string(axisLetter(r.perpendicularAxis)));
    d.setValue("gParallel", r.gParallel);
    d.setValue("gPerpendicular", r.gPerpendicular);
    d.setValue("theta", r.thetaDegrees);
    const auto walls = [&](const char* key, bool fitted, const FitSlipLengthResult& f, bool errors) {
        const WallFitResult& lo = f.poiseuille.lower;
        const WallFitResult& up = f.poiseuille.upper;
        if (fitted)
            d.setValue(key, std::vector<double>{errors ? lo.slipLengthErr : lo.slipLength,
                                                errors ? up.slipLengthErr : up.slipLength});
        else
            d.setValue(key, std::vector<std::string>{"none", "none"});
    };
    walls("slipParallel", r.parallelFitted, r.parallel, false);
    walls("slipParallelError", r.parallelFitted, r.parallel, true);
    walls("slipPerpendicular", r.perpendicularFitted, r.perpendicular, false);
    walls("slipPerpendicularError", r.perpendicularFitted, r.perpendicular, true);
    setNumber("slipParallelMean", r.slipParallel());
    setNumber("slipParallelMeanError", r.parallelFitted ? SlipTensorResult::wallsMeanError(r.parallel) : kNaN);
    setNumber("slipPerpendicularMean", r.slipPerpendicular());
    setNumber("slipPerpendicularMeanError",
               r.perpendicularFitted ? SlipTensorResult::wallsMeanError(r.perpendicular) : kNaN);
    setNumber("slipEffective", r.slipEffective());
    setNumber("slipEffectiveError", r.slipEffectiveError());
    setNumber("nuParallel", r.parallelFitted ? r.parallel.poiseuille.nu : kNaN);
    setNumber("nuParallelError", r.parallelFitted ? r.parallel.poiseuille.nuErr : kNaN);
    setNumber("nuPerpendicular", r.perpendicularFitted ? r.perpendicular.poiseuille.nu : kNaN);
    setNumber("nuPerpendicularError", r.perpendicularFitted ? r.perpendicular.poiseuille.nuErr : kNaN);
    d.setValue("fluxParallel", r.fluxParallel.value);
    d.setValue("fluxParallelError", r.fluxParallel.error);
    d.setValue("fluxPerpendicular", r.fluxPerpendicular.value);
    d.setValue("fluxPerpendicularError", r.fluxPerpendicular.error);
    d.setValue("fluxErrors", r.fluxParallel.blocks.empty() ? "independentBins" : "blocks");
    d.setValue("transverseFluxRatio", r.transverseFluxRatio);
    d.setValue("transverseFluxRatioError", r.transverseFluxRatioError);
    d.setValue("densityCentral", r.densityCentral);
    d.setValue("binsInFlux", r.binsInFlux);
    return d;
}

void printSlipTensor(std::ostream& out, const SlipTensorResult& r) {
    out << std::setprecision(5);
    out << "Time = " << (r.time.empty() ? "?" : r.time) << "\n"
        << "    profile " << r.profileFile << ": across " << axisLetter(r.axis) << ", stripes along "
        << axisLetter(r.parallelAxis) << " (across " << axisLetter(r.perpendicularAxis) << "); force at theta = "
        << r.thetaDegrees << " degrees to the stripes (g " << r.gParallel << " along, " << r.gPerpendicular
        << " across)\n"
        << "    b_par  " << componentText(r, true) << "\n"
        << "    b_perp " << componentText(r, false) << "\n"
        << "    b_eff(theta) " << r.slipEffective() << " +- " << r.slipEffectiveError() << " (mean of the walls)\n"
        << "    flux per unit width along the stripes " << r.fluxParallel.value << " +- " << r.fluxParallel.error
        << ", across them " << r.fluxPerpendicular.value << " +- " << r.fluxPerpendicular.error << " ("
        << r.binsInFlux << " bins, errors " << (r.fluxParallel.blocks.empty() ? "with the bins independent" : "from the blocks")
        << ")\n"
        << "    transverse flux ratio (across the force / along it) " << r.transverseFluxRatio << " +- "
        << r.transverseFluxRatioError << "\n";
}

std::vector<SlipTensorResult> runSlipTensor(const FitSlipLengthOptions& o, std::ostream& out) {
    const fs::path caseDir(o.caseDir);
    const Dictionary dict = Dictionary::readFile((caseDir / "system" / "fitSlipLengthDict").string());
    const Dictionary props = Dictionary::readFile((caseDir / "constant" / "dpdProperties").string());
    const std::string profile = dict.get<std::string>("profile");
    const TimesWithInput selected = selectProfileTimes(o, dict, profile);
    std::vector<SlipTensorResult> results;
    for (const TimeDirectory& t : selected.times) {
        const ProfileTableData table = readProfileTable(profileTablePath(o.caseDir, t.name, profile));
        const fs::path sampling = caseDir / t.name / "sampling" / (profile + ".h5");
        results.push_back(slipTensor(dict, props, o.caseDir, table, sampling.string(), t.name));
        results.back().profileFile = (fs::path("postProcessing") / "profileBins" / t.name / (profile + ".dat")).string();
    }
    for (const auto& t : selected.skipped) out << "Time = " << t << ": no profile table " << profile << ".dat, skipped\n";
    for (const auto& r : results) {
        const fs::path dir = caseDir / "postProcessing" / "slipTensor" / r.time;
        std::error_code ec;
        fs::create_directories(dir, ec);
        if (ec) throw IoError("cannot create '" + dir.string() + "': " + ec.message());
        writeDictionaryFile((dir / "fit.dat").string(), slipTensorDictionary(r));
        printSlipTensor(out, r);
        out << "    written " << (fs::path("postProcessing") / "slipTensor" / r.time / "fit.dat").string() << "\n";
    }
    return results;
}

}  // namespace dpd
