#include "tools/FitSlipLengthTool.hpp"

#include "core/Axis.hpp"
#include "core/Error.hpp"
#include "io/TimeDirectories.hpp"
#include "sampling/UsableBin.hpp"
#include "sampling/BinProfile.hpp"

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

const char* modeName(FitSlipLengthMode m) {
    switch (m) {
        case FitSlipLengthMode::poiseuille: return "poiseuille";
        case FitSlipLengthMode::reversePoiseuille: return "reversePoiseuille";
        case FitSlipLengthMode::couette: return "couette";
    }
    return "unknown";
}

// The component along which the walls slide (couette default): the one axis with a nonzero wall
// velocity component, -1 when there is not exactly one.
int wallSlidingAxis(const DpdModel& m) {
    int axis = -1, count = 0;
    for (int a = 0; a < 3; ++a) {
        bool moving = false;
        for (const PlanarWall& w : m.walls.walls()) moving = moving || w.velocity[a] != 0.0;
        if (moving) { axis = a; ++count; }
    }
    return count == 1 ? axis : -1;
}

// The two planar walls facing each other across the profile's axis, lower first.
std::pair<const PlanarWall*, const PlanarWall*> channelWalls(const FitSlipLengthSetup& s, const ProfileTableData& t,
                                                              int axis) {
    std::vector<const PlanarWall*> walls;
    for (const PlanarWall& w : s.model.walls.walls())
        if (w.normalAxis() == axis) walls.push_back(&w);
    if (walls.size() != 2)
        s.dpdProperties.fail("walls", std::string("mode ") + modeName(s.mode) +
                                          " needs exactly two planar walls with normals along " + t.axisName() +
                                          " (the axis of " + t.file + "), found " + std::to_string(walls.size()));
    if (walls[0]->point[axis] > walls[1]->point[axis]) std::swap(walls[0], walls[1]);
    const PlanarWall& lower = *walls[0];
    const PlanarWall& upper = *walls[1];
    if (!(lower.normal[axis] > 0.0 && upper.normal[axis] < 0.0 && upper.point[axis] > lower.point[axis]))
        s.dpdProperties.fail("walls", "walls '" + lower.name + "' and '" + upper.name +
                                          "' do not face each other across a channel along " + t.axisName());
    return {walls[0], walls[1]};
}

// The channel's two walls along the profile's axis, as the fits need them: the planar walls of
// dpdProperties, or the positions wallPositions gives (the solid of a geometry block, at rest).
struct ChannelBounds {
    double low = 0.0, high = 0.0;                  // wall positions along the axis
    double velocityLow = 0.0, velocityHigh = 0.0;  // the walls' velocities along the fitted component
};

ChannelBounds channelBounds(const FitSlipLengthSetup& s, const ProfileTableData& t, int axis) {
    if (!s.hasWallPositions) {
        const auto [lower, upper] = channelWalls(s, t, axis);
        return {lower->point[axis], upper->point[axis], lower->velocity[s.component], upper->velocity[s.component]};
    }
    for (const PlanarWall& w : s.model.walls.walls())
        if (w.normalAxis() == axis)
            s.dict.fail("wallPositions", "the case has planar walls with normals along " + t.axisName() + " ('" +
                                             w.name + "' in " + s.dpdProperties.fileName() +
                                             "): their positions are used; wallPositions is for the walls of a "
                                             "geometry block");
    return {s.wallLow, s.wallHigh, 0.0, 0.0};
}

std::string vectorText(const Eigen::Vector3d& v) {
    std::ostringstream os;
    os << "(" << v.x() << " " << v.y() << " " << v.z() << ")";
    return os.str();
}

// A bin is usable when it saw particles (velocity defined) and, where errors exist, has one.
struct Points {
    Profile1D profile;
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
        pts.profile.y.push_back(y[i]);
        pts.profile.u.push_back(vel[i]);
        if (anyError) pts.profile.uErr.push_back(err[i]);
    }
    return pts;
}

// The bins' range: first centre - half a bin to last centre + half a bin.
void binRange(const ProfileTableData& t, double& lo, double& hi) {
    const std::vector<double>& c = t.column(t.axisName());
    if (c.size() < 2) throw IoError(t.file + ": a profile needs at least 2 bins to tell its range");
    const double w = (c.back() - c.front()) / static_cast<double>(c.size() - 1);
    if (!(w > 0.0)) throw IoError(t.file + ": the bin centres of column '" + t.axisName() + "' do not increase");
    lo = c.front() - 0.5 * w;
    hi = c.back() + 0.5 * w;
}

double centralDensity(const ProfileTableData& t);

[[noreturn]] void fitFailed(const FitSlipLengthSetup& s, const ProfileTableData& t, const std::invalid_argument& e) {
    const Dictionary& d = s.dict;
    const std::string key = d.found("fitRange") ? "fitRange" : d.found("exclude") ? "exclude" : "";
    throw InputError(d.fileName(), key.empty() ? 0 : d.lineOf(key), key,
                     "cannot fit the profile " + t.file + ": " + e.what());
}

void fitCouetteMode(const FitSlipLengthSetup& s, const ProfileTableData& t, const Profile1D& profile,
                    FitSlipLengthResult& r) {
    const ChannelBounds walls = channelBounds(s, t, r.axis);
    const double fitLow = s.hasFitRange ? s.fitLow : walls.low + s.exclude;
    const double fitHigh = s.hasFitRange ? s.fitHigh : walls.high - s.exclude;
    try {
        r.couette = fitCouette(profile, walls.low, walls.high, fitLow, fitHigh, walls.velocityLow, walls.velocityHigh);
        r.stressColumn = shearStressName(s.component, r.axis);
        r.hasStress = t.has(r.stressColumn) && t.has(r.stressColumn + "Err");
        if (r.hasStress)
            r.stress = viscosityFromStress(t.column(t.axisName()), t.column(r.stressColumn), t.column(r.stressColumn + "Err"),
                                           r.couette, centralDensity(t));
    } catch (const std::invalid_argument& e) {
        fitFailed(s, t, e);
    }
}

// Count-weighted mean density of the bins in the central half of the bin range.
double centralDensity(const ProfileTableData& t) {
    double lo, hi;
    binRange(t, lo, hi);
    const double a = lo + 0.25 * (hi - lo), b = hi - 0.25 * (hi - lo);
    const std::vector<double>& y = t.column(t.axisName());
    const std::vector<double>& rho = t.column("density");
    const std::vector<double>* count = t.has("count") ? &t.column("count") : nullptr;
    double sum = 0.0, weight = 0.0;
    for (std::size_t i = 0; i < y.size(); ++i) {
        if (y[i] < a || y[i] > b) continue;
        const double w = count ? (*count)[i] : 1.0;
        sum += w * rho[i];
        weight += w;
    }
    return weight > 0.0 ? sum / weight : std::numeric_limits<double>::quiet_NaN();
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


// The component fitted: as given, or the one axis the walls slide along.
int couetteComponent(const FitSlipLengthSetup& s) {
    const Dictionary& d = s.dict;
    if (d.found("component")) return d.getAxis("component");
    const int a = wallSlidingAxis(s.model);
    if (a < 0)
        d.fail("component", "not given, and the walls of " + s.dpdProperties.fileName() +
                                " do not slide along exactly one axis: say which velocity component to fit");
    return a;
}

// wallPositions (low high): the channel's walls when they belong to a geometry block.
void readWallPositions(FitSlipLengthSetup& s) {
    if (!s.dict.found("wallPositions")) return;
    s.hasWallPositions = true;
    std::tie(s.wallLow, s.wallHigh) = s.dict.getIncreasingPair("wallPositions", "lower", "upper");
}

void readCouetteSetup(FitSlipLengthSetup& s) {
    const Dictionary& d = s.dict;
    if (s.model.bodyForce.active())
        s.dpdProperties.fail("bodyForce", "mode couette (" + d.fileName() + ") fits a line: it needs no body force");
    s.component = couetteComponent(s);
    if (d.found("fitRange")) {
        if (d.found("exclude")) d.fail("fitRange", "give either fitRange or exclude, not both");
        s.hasFitRange = true;
        std::tie(s.fitLow, s.fitHigh) = d.getIncreasingPair("fitRange", "low", "high");
    }
    s.exclude = d.found("exclude") ? d.getNonNegative<double>("exclude") : s.model.cutoff;
}

}  // namespace

FitSlipLengthSetup readFitSlipLengthSetup(const Dictionary& dict, const Dictionary& dpdProperties) {
    FitSlipLengthSetup s;
    s.dict = dict;
    s.dpdProperties = dpdProperties;
    s.model = readDpdModel(dpdProperties);
    const Dictionary& d = s.dict;
    d.checkKeys({"mode", "profile", "component", "exclude", "fitRange", "slipPredictionNu", "wallPositions"});
    if (d.found("slipPredictionNu")) s.slipPredictionNu = d.getPositive<double>("slipPredictionNu");
    readWallPositions(s);

    const std::string mode = d.get<std::string>("mode");
    if (mode == "poiseuille") s.mode = FitSlipLengthMode::poiseuille;
    else if (mode == "reversePoiseuille") s.mode = FitSlipLengthMode::reversePoiseuille;
    else if (mode == "couette") s.mode = FitSlipLengthMode::couette;
    else d.fail("mode", "unknown mode '" + mode + "' (expected poiseuille, reversePoiseuille or couette)");

    s.profile = d.get<std::string>("profile");
    if (s.profile.empty() || s.profile.find('/') != std::string::npos)
        d.fail("profile", "expected the name of a table in postProcessing/profileBins/<time>/, without '.dat'");

    const BodyForce& f = s.model.bodyForce;
    const std::string dpdFile = dpdProperties.fileName();
    if (s.mode != FitSlipLengthMode::couette && d.found("fitRange"))
        d.fail("fitRange", "only mode couette takes a fitRange (use exclude)");
    if (s.mode == FitSlipLengthMode::poiseuille) {
        if (f.type == BodyForce::Type::reversePoiseuille)
            d.fail("mode", dpdFile + " has a reversePoiseuille body force: use mode reversePoiseuille");
        if (f.type != BodyForce::Type::uniform || !f.active())
            dpdProperties.fail("bodyForce", "mode poiseuille (" + d.fileName() + ") needs a uniform nonzero body force");
    } else if (s.mode == FitSlipLengthMode::reversePoiseuille) {
        if (f.type != BodyForce::Type::reversePoiseuille || !f.active())
            d.fail("mode", "mode reversePoiseuille needs a nonzero body force of type reversePoiseuille in " + dpdFile);
        if (s.hasWallPositions) d.fail("wallPositions", "mode reversePoiseuille has no walls");
    } else {
        readCouetteSetup(s);
        return s;
    }

    if (d.found("component")) {
        s.component = d.getAxis("component");
    } else {
        int nonzero = 0;
        for (int a = 0; a < 3; ++a)
            if (f.g[a] != 0.0) {
                s.component = a;
                ++nonzero;
            }
        if (nonzero != 1)
            d.fail("component", "not given, and the body force " + vectorText(f.g) + " of " + dpdFile +
                                    " does not point along one axis: say which velocity component to fit");
    }
    if (f.g[s.component] == 0.0)
        d.fail("component", std::string("the body force ") + vectorText(f.g) + " of " + dpdFile + " has no " +
                                axisLetter(s.component) + " component: nothing drives a flow along " +
                                axisLetter(s.component));

    const double defaultExclude = s.mode == FitSlipLengthMode::poiseuille ? 0.0 : 1.0;
    s.exclude = d.found("exclude") ? d.getNonNegative<double>("exclude") : defaultExclude;
    return s;
}

namespace {

// The predicted slip length of tunable-slip channel walls, from the central density and nu (the
// dictionary's slipPredictionNu, else the fit's own).
void predictSlip(const FitSlipLengthSetup& s, const ProfileTableData& t, FitSlipLengthResult& r) {
    if (s.hasWallPositions) return;  // walls of a geometry: no tunable slip
    const auto [lower, upper] = channelWalls(s, t, r.axis);
    if (!lower->hasTunableSlip && !upper->hasTunableSlip) return;
    const bool given = s.slipPredictionNu > 0.0;
    const bool fitted = r.mode == FitSlipLengthMode::poiseuille || r.hasStress;
    if (!given && !fitted)
        s.dict.fail("slipPredictionNu", "the walls have tunable slip but this fit measures no viscosity: give "
                                        "slipPredictionNu (or sample the stress) for the predicted slip length");
    const double nu = given ? s.slipPredictionNu : r.mode == FitSlipLengthMode::poiseuille ? r.poiseuille.nu : r.stress.nu;
    try {
        r.slipPrediction = predictTunableSlip(*lower, *upper, r.densityCentral, nu,
                                              given ? s.dict.fileName() + " slipPredictionNu" : "fit");
    } catch (const std::invalid_argument& e) {
        s.dict.fail(given ? "slipPredictionNu" : "", std::string("no predicted slip length: ") + e.what());
    }
}

}  // namespace

FitSlipLengthResult fitSlipLength(const FitSlipLengthSetup& s, const ProfileTableData& t, const std::string& time) {
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
    r.g = s.model.bodyForce.g[s.component];

    const Points pts = usablePoints(t, s.component);
    r.pointsUsed = static_cast<int>(pts.profile.y.size());
    r.binsWithoutVelocity = pts.withoutVelocity;
    r.binsWithoutError = pts.withoutError;

    if (s.mode == FitSlipLengthMode::poiseuille) {
        const ChannelBounds walls = channelBounds(s, t, r.axis);
        try {
            r.poiseuille = fitPoiseuille(pts.profile, r.g, walls.low, walls.high, s.exclude, walls.velocityLow,
                                         walls.velocityHigh);
        } catch (const std::invalid_argument& e) {
            fitFailed(s, t, e);
        }
    } else if (s.mode == FitSlipLengthMode::couette) {
        fitCouetteMode(s, t, pts.profile, r);
    } else {
        if (r.axis != s.model.bodyForce.gradientAxis)
            s.dpdProperties.fail("bodyForce", "the reversePoiseuille gradientAxis is " +
                                                  std::string(axisLetter(s.model.bodyForce.gradientAxis)) +
                                                  " but the profile " + t.file + " is binned along " + t.axisName());
        double lo, hi;
        binRange(t, lo, hi);
        r.boxLow = lo;
        r.boxLength = hi - lo;
        try {
            r.reverse = fitReversePoiseuille(pts.profile, r.g, r.boxLow, r.boxLength, s.exclude);
        } catch (const std::invalid_argument& e) {
            fitFailed(s, t, e);
        }
    }

    r.densityCentral = centralDensity(t);
    r.gamma = firstMobileGamma(s.model);
    r.nuKineticTheory = std::isfinite(r.gamma) && r.gamma > 0.0 && std::isfinite(r.densityCentral) && r.densityCentral > 0.0
                            ? kineticTheoryViscosity(s.model.kT, r.gamma, r.densityCentral, s.model.cutoff)
                            : std::numeric_limits<double>::quiet_NaN();
    if (s.mode != FitSlipLengthMode::reversePoiseuille) predictSlip(s, t, r);
    return r;
}

namespace {

// The per-wall entries fit.dat has in both channel modes: (lower upper) lists.
void setWallFits(Dictionary& d, const WallFitResult& lower, const WallFitResult& upper) {
    d.setValue("wallPosition", std::vector<double>{lower.position, upper.position});
    d.setValue("wallVelocity", std::vector<double>{lower.wallVelocity, upper.wallVelocity});
    d.setValue("slipLength", std::vector<double>{lower.slipLength, upper.slipLength});
    d.setValue("slipLengthError", std::vector<double>{lower.slipLengthErr, upper.slipLengthErr});
    d.setValue("slipVelocity", std::vector<double>{lower.slipVelocity, upper.slipVelocity});
    d.setValue("slipVelocityError", std::vector<double>{lower.slipVelocityErr, upper.slipVelocityErr});
}

}  // namespace

Dictionary fitSlipLengthDictionary(const FitSlipLengthResult& r) {
    Dictionary d;
    d.setValue("mode", std::string(modeName(r.mode)));
    if (!r.time.empty()) d.setValue("time", r.time);
    d.setValue("profile", r.profileFile);
    d.setValue("axis", std::string(axisLetter(r.axis)));
    d.setValue("component", std::string(axisLetter(r.component)));
    d.setValue("g", r.g);
    d.setValue("exclude", r.exclude);
    d.setValue("points", r.pointsUsed);
    if (r.mode == FitSlipLengthMode::poiseuille) {
        const PoiseuilleFitResult& p = r.poiseuille;
        d.setValue("nu", p.nu);
        d.setValue("nuError", p.nuErr);
        setWallFits(d, p.lower, p.upper);
        d.setValue("shearRate", std::vector<double>{p.lower.shearRate, p.upper.shearRate});
        d.setValue("centre", p.centre);
        d.setValue("maxVelocity", p.maxVelocity);
        d.setValue("coefficients", p.coefficients);
        d.setValue("chi2PerDof", p.chi2PerDof);
        d.setValue("dof", p.dof);
    } else if (r.mode == FitSlipLengthMode::couette) {
        const CouetteFitResult& c = r.couette;
        if (r.hasStress) {
            d.setValue("nu", r.stress.nu);
            d.setValue("nuError", r.stress.nuErr);
            d.setValue("eta", r.stress.eta);
            d.setValue("etaError", r.stress.etaErr);
            d.setValue("shearStress", r.stress.stress);
            d.setValue("shearStressError", r.stress.stressErr);
        } else {
            d.setValue("nu", "none");  // no stress column in the profile table
        }
        d.setValue("fitRange", std::vector<double>{c.fitLow, c.fitHigh});
        setWallFits(d, c.lower, c.upper);
        d.setValue("shearRate", c.shearRate);
        d.setValue("shearRateError", c.shearRateErr);
        d.setValue("coefficients", c.coefficients);
        d.setValue("chi2PerDof", c.chi2PerDof);
        d.setValue("dof", c.dof);
    } else {
        const ReversePoiseuilleResult& p = r.reverse;
        d.setValue("boxLow", r.boxLow);
        d.setValue("boxLength", r.boxLength);
        d.setValue("nu", p.nu);
        d.setValue("nuError", p.nuErr);
        d.setValue("nuFirstHalf", p.nuFirstHalf);
        d.setValue("nuFirstHalfError", p.nuFirstHalfErr);
        d.setValue("nuSecondHalf", p.nuSecondHalf);
        d.setValue("nuSecondHalfError", p.nuSecondHalfErr);
        d.setValue("chi2PerDof", p.chi2PerDof);
    }
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

void printFitSlipLength(std::ostream& out, const FitSlipLengthResult& r) {
    const auto num = [](double x) {
        std::ostringstream os;
        os << std::setprecision(6) << x;
        return os.str();
    };
    const auto withErr = [&](double v, double e) { return num(v) + " +- " + num(e); };
    const auto row = [&](const std::string& label, const std::string& a, const std::string& b = "") {
        out << "    " << std::left << std::setw(22) << label;
        if (b.empty()) out << a;
        else out << std::setw(28) << a << b;
        out << std::right << "\n";
    };
    const std::string ax = axisLetter(r.axis);

    out << "Time = " << (r.time.empty() ? "?" : r.time) << "\n";
    out << "    profile " << r.profileFile << ": u" << axisLetter(r.component) << " across " << ax << ", "
        << r.pointsUsed << " bins";
    if (r.binsWithoutVelocity) out << ", " << r.binsWithoutVelocity << " without particles left out";
    if (r.binsWithoutError) out << ", " << r.binsWithoutError << " without an error bar left out";
    out << "\n    mode " << modeName(r.mode) << ", g = " << num(r.g) << ", exclude " << num(r.exclude) << "\n";
    if (r.mode == FitSlipLengthMode::poiseuille) {
        const PoiseuilleFitResult& p = r.poiseuille;
        row("nu", withErr(p.nu, p.nuErr));
        row("chi2/dof", num(p.chi2PerDof) + " (dof " + std::to_string(p.dof) + ")");
        row("", "lower wall (" + ax + " = " + num(p.lower.position) + ")",
            "upper wall (" + ax + " = " + num(p.upper.position) + ")");
        row("slip length", withErr(p.lower.slipLength, p.lower.slipLengthErr),
            withErr(p.upper.slipLength, p.upper.slipLengthErr));
        row("slip velocity", withErr(p.lower.slipVelocity, p.lower.slipVelocityErr),
            withErr(p.upper.slipVelocity, p.upper.slipVelocityErr));
        row("shear rate", num(p.lower.shearRate), num(p.upper.shearRate));
    } else if (r.mode == FitSlipLengthMode::couette) {
        const CouetteFitResult& c = r.couette;
        row("fit range", "[" + num(c.fitLow) + ", " + num(c.fitHigh) + "]");
        row("shear rate", withErr(c.shearRate, c.shearRateErr));
        if (r.hasStress) {
            row("shear stress", withErr(r.stress.stress, r.stress.stressErr), "(" + r.stressColumn + ")");
            row("eta", withErr(r.stress.eta, r.stress.etaErr));
            row("nu", withErr(r.stress.nu, r.stress.nuErr));
        } else {
            row("nu", "none (no column " + r.stressColumn + " in the profile: sample with stress yes)");
        }
        row("chi2/dof", num(c.chi2PerDof) + " (dof " + std::to_string(c.dof) + ")");
        row("", "lower wall (" + ax + " = " + num(c.lower.position) + ")",
            "upper wall (" + ax + " = " + num(c.upper.position) + ")");
        row("wall velocity", num(c.lower.wallVelocity), num(c.upper.wallVelocity));
        row("slip length", withErr(c.lower.slipLength, c.lower.slipLengthErr),
            withErr(c.upper.slipLength, c.upper.slipLengthErr));
        row("slip velocity", withErr(c.lower.slipVelocity, c.lower.slipVelocityErr),
            withErr(c.upper.slipVelocity, c.upper.slipVelocityErr));
    } else {
        const ReversePoiseuilleResult& p = r.reverse;
        row("box along " + ax, "[" + num(r.boxLow) + ", " + num(r.boxLow + r.boxLength) + ")");
        row("nu", withErr(p.nu, p.nuErr));
        row("nu (+g half)", withErr(p.nuFirstHalf, p.nuFirstHalfErr));
        row("nu (-g half)", withErr(p.nuSecondHalf, p.nuSecondHalfErr));
        row("chi2/dof", num(p.chi2PerDof));
    }
    if (r.slipPrediction.any) {
        const TunableSlipPrediction& sp = r.slipPrediction;
        const auto predicted = [&](int k) {
            return sp.tunable[k] ? num(sp.slipLength[k]) + " (alpha " + num(sp.alpha[k]) + ")" : std::string("none");
        };
        row("slip length predicted", predicted(0), predicted(1));
        row("", "(tunable slip, rho = " + num(sp.density) + ", nu = " + num(sp.nu) + " from " + sp.nuSource + ")");
    }
    if (std::isfinite(r.nuKineticTheory))
        row("nu kinetic theory", num(r.nuKineticTheory),
            "(estimate: rho = " + num(r.densityCentral) + ", gamma = " + num(r.gamma) + ")");
    else
        row("nu kinetic theory", "none (no pair of mobile species or no density)");
}

std::vector<FitSlipLengthResult> runFitSlipLength(const FitSlipLengthOptions& o, std::ostream& out) {
    const fs::path caseDir(o.caseDir);
    const Dictionary dict = Dictionary::readFile((caseDir / "system" / "fitSlipLengthDict").string());
    const Dictionary props = Dictionary::readFile((caseDir / "constant" / "dpdProperties").string());
    const FitSlipLengthSetup setup = readFitSlipLengthSetup(dict, props);

    const auto tableOf = [&](const TimeDirectory& t) {
        return caseDir / "postProcessing" / "profileBins" / t.name / (setup.profile + ".dat");
    };
    const TimesWithInput selected = selectTimesWithInput(
        o.caseDir, o.time, o.latestTime, [&](const TimeDirectory& t) { return fs::exists(tableOf(t)); },
        [&](const TimeDirectory& t) {
            throw InputError(dict.fileName(), dict.lineOf("profile"), "profile",
                             "no profile table " + tableOf(t).string() + " (run profileBins first)");
        },
        [&](const std::vector<std::string>&) {
            throw InputError(dict.fileName(), dict.lineOf("profile"), "profile",
                             "no time of case '" + o.caseDir + "' has the profile table postProcessing/profileBins/<time>/" +
                                 setup.profile + ".dat (run profileBins first)");
        });
    std::vector<FitSlipLengthResult> results;
    for (const TimeDirectory& t : selected.times) {
        results.push_back(fitSlipLength(setup, readProfileTable(tableOf(t).string()), t.name));
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
