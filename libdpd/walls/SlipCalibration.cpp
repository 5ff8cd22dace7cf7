#include "walls/SlipCalibration.hpp"

#include "core/Error.hpp"
#include "io/Dictionary.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <stdexcept>

namespace dpd {

namespace {

bool sameNumber(double x, double y) { return std::abs(x - y) <= 1e-9 * std::max({std::abs(x), std::abs(y), 1e-300}); }

std::string numberText(double x) {
    std::ostringstream s;
    s.precision(12);
    s << x;
    return s.str();
}

// "fluid/a 25 against 0" where the two differ, else empty.
std::string differs(const std::string& entry, double mine, double theirs) {
    return sameNumber(mine, theirs) ? std::string() : entry + " " + numberText(mine) + " against " + numberText(theirs);
}

}  // namespace

void SlipCalibrationKey::setWallModel(const TunableSlipParameters& wall) {
    zc = wall.zc;
    epsilon = wall.epsilon;
    sigma = wall.sigma;
    behindA = wall.behindA;
    behindDensity = wall.behindDensity;
    tangentialOnly = wall.tangentialOnly;
}

std::string SlipCalibrationKey::firstDifference(const SlipCalibrationKey& o) const {
    const std::pair<const char*, std::pair<double, double>> numbers[] = {
        {"fluid/density", {density, o.density}}, {"fluid/a", {a, o.a}},          {"fluid/gamma", {gamma, o.gamma}},
        {"fluid/kT", {kT, o.kT}},                {"fluid/cutoff", {cutoff, o.cutoff}},
        {"fluid/dimension", {dimension, o.dimension}},                           {"step/deltaT", {dt, o.dt}},
        {"wall/zc", {zc, o.zc}},                 {"wall/epsilon", {epsilon, o.epsilon}},
        {"wall/sigma", {sigma, o.sigma}},        {"wall/fluidBehind/a", {behindA, o.behindA}},
        {"wall/fluidBehind/density", {behindDensity, o.behindDensity}}};
    for (const auto& [entry, values] : numbers) {
        const std::string d = differs(entry, values.first, values.second);
        if (!d.empty()) return d;
    }
    if (integrator != o.integrator) return "step/integrator '" + integrator + "' against '" + o.integrator + "'";
    if (tangentialOnly != o.tangentialOnly)
        return std::string("wall/friction ") + (tangentialOnly ? "tangential" : "full") + " against " +
               (o.tangentialOnly ? "tangential" : "full");
    return {};
}

void SlipCalibrationKey::writeTo(Dictionary& d) const {
    Dictionary& fluid = d.subDictOrCreate("fluid");
    fluid.setValue("density", density);
    fluid.setValue("a", a);
    fluid.setValue("gamma", gamma);
    fluid.setValue("kT", kT);
    fluid.setValue("cutoff", cutoff);
    fluid.setValue("dimension", dimension);
    Dictionary& step = d.subDictOrCreate("step");
    step.setValue("deltaT", dt);
    step.setValue("integrator", integrator);
    Dictionary& wall = d.subDictOrCreate("wall");
    wall.setValue("zc", zc);
    wall.setValue("epsilon", epsilon);
    wall.setValue("sigma", sigma);
    wall.setValue("friction", tangentialOnly ? "tangential" : "full");
    Dictionary& behind = wall.subDictOrCreate("fluidBehind");
    behind.setValue("a", behindA);
    behind.setValue("density", behindDensity);
}

SlipCalibrationKey SlipCalibrationKey::read(const Dictionary& d) {
    SlipCalibrationKey k;
    const Dictionary& fluid = d.subDict("fluid");
    fluid.checkKeys({"density", "a", "gamma", "kT", "cutoff", "dimension"});
    k.density = fluid.getPositive<double>("density");
    k.a = fluid.getNonNegative<double>("a");
    k.gamma = fluid.getPositive<double>("gamma");
    k.kT = fluid.getPositive<double>("kT");
    k.cutoff = fluid.getPositive<double>("cutoff");
    k.dimension = fluid.get<int>("dimension");
    if (k.dimension != 2 && k.dimension != 3) fluid.fail("dimension", "must be 2 or 3");
    const Dictionary& step = d.subDict("step");
    step.checkKeys({"deltaT", "integrator"});
    k.dt = step.getPositive<double>("deltaT");
    k.integrator = step.get<std::string>("integrator");
    const Dictionary& wall = d.subDict("wall");
    wall.checkKeys({"zc", "epsilon", "sigma", "friction", "fluidBehind"});
    k.zc = wall.getPositive<double>("zc");
    k.epsilon = wall.getNonNegative<double>("epsilon");
    k.sigma = wall.getPositive<double>("sigma");
    const std::string friction = wall.get<std::string>("friction");
    if (friction != "full" && friction != "tangential") wall.fail("friction", "expected full or tangential, not '" + friction + "'");
    k.tangentialOnly = friction == "tangential";
    const Dictionary& behind = wall.subDict("fluidBehind");
    behind.checkKeys({"a", "density"});
    k.behindA = behind.getNonNegative<double>("a");
    k.behindDensity = behind.getNonNegative<double>("density");
    return k;
}

SlipCalibration::SlipCalibration(SlipCalibrationKey key, std::vector<SlipCalibrationPoint> points, double wallOffset,
                                 double wallOffsetError, std::string source)
    : key_(std::move(key)), points_(std::move(points)), wallOffset_(wallOffset), wallOffsetError_(wallOffsetError),
      source_(std::move(source)) {
    if (points_.size() < 2) throw std::invalid_argument("a slip calibration needs two frictions at least");
    for (const SlipCalibrationPoint& p : points_)
        if (!(p.gammaL > 0.0 && std::isfinite(p.slipLength) && p.slipLengthError >= 0.0 && std::isfinite(p.slipLengthError)))
            throw std::invalid_argument("a slip calibration's gammaL must be positive and its slip lengths and errors finite");
    std::sort(points_.begin(), points_.end(), [](const auto& x, const auto& y) { return x.gammaL < y.gammaL; });
    for (std::size_t k = 1; k < points_.size(); ++k)
        if (!(points_[k].slipLength < points_[k - 1].slipLength))
            throw std::invalid_argument("a slip calibration's slip length must fall as gammaL rises (gammaL " +
                                        numberText(points_[k - 1].gammaL) + " and " + numberText(points_[k].gammaL) + ")");
    if (!(std::isfinite(wallOffset_) && wallOffsetError_ >= 0.0 && std::isfinite(wallOffsetError_)))
        throw std::invalid_argument("a slip calibration's wall offset and its error must be finite");
}

CalibratedFriction SlipCalibration::frictionFor(double b) const {
    if (!(b >= smallestSlip() && b <= largestSlip()))
        throw std::out_of_range("slip length " + numberText(b) + " outside the calibrated range " +
                                numberText(smallestSlip()) + " to " + numberText(largestSlip()) + " (" + source_ + ")");
    std::size_t k = 0;
    while (points_[k + 1].slipLength > b) ++k;  // points_[k].b >= b >= points_[k + 1].b
    const SlipCalibrationPoint& hi = points_[k];
    const SlipCalibrationPoint& lo = points_[k + 1];
    const double t = (b - hi.slipLength) / (lo.slipLength - hi.slipLength);
    const double inverse = (1.0 - t) / hi.gammaL + t / lo.gammaL;
    return {1.0 / inverse, (1.0 - t) * hi.slipLengthError + t * lo.slipLengthError, wallOffset_};
}

CalibratedFriction SlipCalibration::wallFor(double b) const {
    if (!(b >= 0.0 && b <= largestSlip()))
        throw std::out_of_range("slip length " + numberText(b) + " outside the calibrated range 0 to " +
                                numberText(largestSlip()) + " (" + source_ + ")");
    if (b >= smallestSlip()) return frictionFor(b);
    const SlipCalibrationPoint& stiffest = points_.back();
    return {stiffest.gammaL, stiffest.slipLengthError, wallOffset_ - (stiffest.slipLength - b)};
}

SlipCalibration SlipCalibration::read(const Dictionary& d) {
    d.checkKeys({"fluid", "step", "wall", "wallOffset", "wallOffsetError", "gammaL", "slipLength", "slipLengthError", "madeBy"});
    const std::vector<double> gammas = d.get<std::vector<double>>("gammaL");
    const std::vector<double> slips = d.get<std::vector<double>>("slipLength");
    const std::vector<double> errors = d.get<std::vector<double>>("slipLengthError");
    if (slips.size() != gammas.size()) d.fail("slipLength", "must list one slip length per gammaL");
    if (errors.size() != gammas.size()) d.fail("slipLengthError", "must list one error per gammaL");
    std::vector<SlipCalibrationPoint> points;
    for (std::size_t k = 0; k < gammas.size(); ++k) points.push_back({gammas[k], slips[k], errors[k]});
    try {
        return SlipCalibration(SlipCalibrationKey::read(d), std::move(points), d.get<double>("wallOffset"),
                               d.getNonNegative<double>("wallOffsetError"), d.fileName());
    } catch (const std::invalid_argument& e) {
        d.fail("gammaL", e.what());
    }
}

void SlipCalibration::writeTo(Dictionary& d) const {
    key_.writeTo(d);
    d.setValue("wallOffset", wallOffset_);
    d.setValue("wallOffsetError", wallOffsetError_);
    std::vector<double> gammas, slips, errors;
    for (const SlipCalibrationPoint& p : points_) {
        gammas.push_back(p.gammaL);
        slips.push_back(p.slipLength);
        errors.push_back(p.slipLengthError);
    }
    d.setValue("gammaL", gammas);
    d.setValue("slipLength", slips);
    d.setValue("slipLengthError", errors);
    d.setValue("madeBy", source_);
}

SlipCalibration findSlipCalibration(const std::vector<std::string>& files, const SlipCalibrationKey& key) {
    std::string tried;
    for (const std::string& file : files) {
        if (!std::filesystem::exists(file)) continue;
        const SlipCalibration c = SlipCalibration::read(Dictionary::readFile(file));
        const std::string difference = key.firstDifference(c.key());
        if (difference.empty()) return c;
        tried += "\n    " + file + ": " + difference;
    }
    throw std::runtime_error("no slip calibration for this fluid and wall model" +
                             (tried.empty() ? std::string(" (no calibration file found)") : ":" + tried));
}

namespace {

// The regular files of a directory, in name order (none when it is not one).
std::vector<std::string> filesIn(const std::filesystem::path& dir) {
    namespace fs = std::filesystem;
    std::vector<std::string> files;
    std::error_code error;
    if (dir.empty() || !fs::is_directory(dir, error)) return files;
    for (const fs::directory_entry& e : fs::directory_iterator(dir, error))
        if (e.is_regular_file()) files.push_back(e.path().string());
    std::sort(files.begin(), files.end());
    return files;
}

}  // namespace

std::vector<std::string> slipCalibrationFiles(const std::string& caseDir) {
    namespace fs = std::filesystem;
    std::vector<std::string> files{(fs::path(caseDir) / "constant" / "slipCalibration").string()};
    fs::path cache;
    if (const char* dir = std::getenv("DPD_SLIP_CALIBRATIONS"); dir && *dir) cache = dir;
    else if (const char* home = std::getenv("HOME"); home && *home) cache = fs::path(home) / ".cache" / "dpdFoamLike" / "slipCalibrations";
    for (const std::string& f : filesIn(cache)) files.push_back(f);
    // The calibrations the project ships, made by its tutorials' Allruns (etc/slipCalibrations/README).
    if (const char* project = std::getenv("DPD_PROJECT_DIR"); project && *project)
        for (const std::string& f : filesIn(fs::path(project) / "etc" / "slipCalibrations"))
            if (fs::path(f).filename() != "README") files.push_back(f);
    return files;
}

}  // namespace dpd
