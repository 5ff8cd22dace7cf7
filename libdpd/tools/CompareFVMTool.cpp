#include "tools/CompareFVMTool.hpp"

#include "tools/CompareFVMOutput.hpp"

#include "core/Axis.hpp"
#include "core/Error.hpp"
#include "foam/FoamFieldFiles.hpp"
#include "io/AtomicFile.hpp"
#include "io/Dictionary.hpp"
#include "io/Snapshot.hpp"
#include "io/TimeDirectories.hpp"
#include "case/DpdProperties.hpp"
#include "sampling/UsableBin.hpp"
#include "sampling/ProfileTable.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <limits>
#include <numeric>
#include <ostream>
#include <sstream>

namespace dpd {

namespace fs = std::filesystem;

namespace {

bool sameVector(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double scale) {
    return (a - b).cwiseAbs().maxCoeff() <= 1e-9 * std::max(1.0, scale);
}

Dictionary optionalDictionary(const fs::path& p) {
    return fs::exists(p) ? Dictionary::readFile(p.string()) : Dictionary(p.string());
}

struct Setup {
    Dictionary dict;      // system/compareFVMDict (maybe empty)
    Dictionary record;    // <foamCase>/constant/dpdCase
    fs::path foamCase;
    std::string foamTime;
    std::string profile;
    int component = -1;
    double fluidDensity = 0.0;   // 0: not known (needed for 2-D profiles only)
};

// The DPD case must still be the one makeFoamCase read: same body force, walls and box.
void checkRecord(const Setup& s, const std::string& caseDir) {
    const Dictionary& r = s.record;
    const Dictionary props = Dictionary::readFile((fs::path(caseDir) / "constant" / "dpdProperties").string());
    const DpdModel model = readDpdModel(props, caseDir);
    const Eigen::Vector3d g = model.bodyForce->uniform() ? model.bodyForce->value() : Eigen::Vector3d::Zero();
    if (!sameVector(r.get<Eigen::Vector3d>("g"), g, g.norm()))
        r.fail("g", "differs from the body force of " + props.fileName() + ": rerun makeFoamCase");
    const std::string wallAxis = r.get<std::string>("wallAxis");
    for (const PlanarWallSettings* w : model.planes()) {
        const int a = axisFromLetter(wallAxis);
        const bool found = a >= 0 && (std::abs(r.subDict("lowerWall").get<double>("position") - w->point[a]) < 1e-9 ||
                                      std::abs(r.subDict("upperWall").get<double>("position") - w->point[a]) < 1e-9);
        if (!found || w->normalAxis() != a)
            r.fail("wallAxis", "wall '" + w->name + "' of " + props.fileName() + " is not where the continuum case has its walls: rerun makeFoamCase");
    }
    const std::vector<TimeDirectory> times = listTimes(caseDir);
    for (auto it = times.rbegin(); it != times.rend(); ++it) {
        const fs::path snap = fs::path(caseDir) / it->name / snapshotFileName;
        if (!fs::is_regular_file(snap)) continue;
        const Box box = readSnapshot(snap.string()).box;
        const double scale = (box.hi - box.lo).norm();
        if (!sameVector(r.get<Eigen::Vector3d>("dpdBoxMin"), box.lo, scale) ||
            !sameVector(r.get<Eigen::Vector3d>("dpdBoxMax"), box.hi, scale))
            r.fail("dpdBoxMin", "the box differs from that of " + snap.string() + ": rerun makeFoamCase");
        return;
    }
}

// The density the wall builder filled the box with (0 when there is no builder dictionary).
double builderDensity(const fs::path& caseDir) {
    for (const char* name : {"randomEquilWallDict", "blockFrozenWallDict"}) {
        const fs::path p = caseDir / "system" / name;
        if (!fs::is_regular_file(p)) continue;
        const Dictionary d = Dictionary::readFile(p.string());
        if (d.found("fluid") && d.subDict("fluid").found("density")) return d.subDict("fluid").getPositive<double>("density");
    }
    return 0.0;
}

Setup readSetup(const CompareFVMOptions& o) {
    const fs::path caseDir(o.caseDir);
    Setup s;
    s.dict = optionalDictionary(caseDir / "system" / "compareFVMDict");
    const Dictionary& d = s.dict;
    d.checkKeys({"foamCase", "profile", "component", "foamTime", "fluidDensity"});
    std::string foamCase = o.foamCase;
    if (foamCase.empty()) foamCase = d.getOrDefault<std::string>("foamCase", "");
    if (foamCase.empty())
        foamCase = optionalDictionary(caseDir / "system" / "makeFoamCaseDict").getOrDefault<std::string>("foamCase", "simpleFoam");
    s.foamCase = fs::path(foamCase).is_absolute() ? fs::path(foamCase) : caseDir / foamCase;
    if (!fs::is_directory(s.foamCase))
        throw IoError("no OpenFOAM case '" + s.foamCase.string() + "' (run makeFoamCase and the case's Allrun)");
    const fs::path recordFile = s.foamCase / "constant" / "dpdCase";
    if (!fs::is_regular_file(recordFile))
        throw IoError("no " + recordFile.string() + ": '" + s.foamCase.string() + "' was not written by makeFoamCase");
    s.record = Dictionary::readFile(recordFile.string());
    checkRecord(s, o.caseDir);

    s.foamTime = d.getOrDefault<std::string>("foamTime", "latestTime");
    if (s.foamTime == "latestTime") s.foamTime = latestFoamTime(s.foamCase.string());
    if (s.foamTime.empty())
        throw IoError("the OpenFOAM case '" + s.foamCase.string() + "' has no time after 0 (run its Allrun)");
    for (const char* field : {"U", "C"})
        if (!fs::is_regular_file(s.foamCase / s.foamTime / field))
            throw IoError("no " + (s.foamCase / s.foamTime / field).string() +
                          (field[0] == 'C' ? " (run postProcess -func writeCellCentres -latestTime in the OpenFOAM case)"
                                           : " (did simpleFoam run?)"));

    if (d.found("component")) {
        s.component = d.getAxis("component");
    } else {
        const Eigen::Vector3d g = s.record.get<Eigen::Vector3d>("g");
        int nonzero = 0;
        for (int a = 0; a < 3; ++a)
            if (g[a] != 0.0) s.component = a, ++nonzero;
        if (nonzero != 1) d.fail("component", "the body force does not point along one axis: say which component to compare");
    }
    s.profile = d.getOrDefault<std::string>("profile", "");
    s.fluidDensity = d.found("fluidDensity") ? d.getPositive<double>("fluidDensity") : builderDensity(caseDir);
    return s;
}

// The profile table of a DPD time: the one named, or the only one there.
fs::path profileTable(const Setup& s, const fs::path& caseDir, const std::string& time) {
    const fs::path dir = caseDir / "postProcessing" / "profileBins" / time;
    if (!s.profile.empty()) return dir / (s.profile + ".dat");
    std::vector<fs::path> tables;
    if (fs::is_directory(dir))
        for (const auto& e : fs::directory_iterator(dir))
            if (e.path().extension() == ".dat") tables.push_back(e.path());
    if (tables.size() != 1)
        s.dict.fail("profile", "found " + std::to_string(tables.size()) + " profile tables in " + dir.string() +
                                   ": name the one to compare");
    return tables.front();
}

// The bins the DPD profile has velocities in (sampling/UsableBin.hpp).
void dpdPoints(const ProfileTableData& t, int component, CompareFVMResult& r) {
    const std::string u = std::string("u") + axisLetter(component);
    const std::vector<double>& x = t.column(t.axisName());
    const std::vector<double>& v = t.column(u);
    const std::vector<double>& e = t.column(u + "Err");
    const std::vector<double>* count = t.has("count") ? &t.column("count") : nullptr;
    for (std::size_t i = 0; i < x.size(); ++i) {
        if (count && !usableBin((*count)[i])) continue;
        r.x.push_back(x[i]);
        r.uDPD.push_back(v[i]);
        r.uDPDErr.push_back(e[i]);
    }
}

// The fluid's extent along the axis: between the walls, or the whole mesh.
std::pair<double, double> fluidRange(const Dictionary& record, int axis) {
    if (record.get<std::string>("wallAxis") == axisLetter(axis))
        return {record.subDict("lowerWall").get<double>("position"), record.subDict("upperWall").get<double>("position")};
    return {record.get<Eigen::Vector3d>("meshMin")[axis], record.get<Eigen::Vector3d>("meshMax")[axis]};
}

std::vector<double> interpolateAt(const std::vector<double>& xs, const std::vector<double>& vs, const std::vector<double>& at,
                                  double lo, double hi) {
    std::vector<double> out;
    for (double x : at) out.push_back(x < lo || x > hi ? std::nan("") : interpolateLinear(xs, vs, x));
    return out;
}

// A sampled line parallel to the axis, as (coordinate, component) sorted along it; false otherwise.
bool lineProfile(const FoamSampledLine& l, int axis, int component, std::vector<double>& x, std::vector<double>& u) {
    const double scale = (l.points.back() - l.points.front()).norm();
    for (const Eigen::Vector3d& p : l.points)
        for (int a = 0; a < 3; ++a)
            if (a != axis && std::abs(p[a] - l.points.front()[a]) > 1e-9 * std::max(1.0, scale)) return false;
    std::vector<std::size_t> order(l.points.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return l.points[a][axis] < l.points[b][axis]; });
    for (std::size_t i : order) {
        x.push_back(l.points[i][axis]);
        u.push_back(l.values[i][component]);
    }
    return true;
}

ComparisonMetrics compareOrFail(const CompareFVMResult& r, const std::vector<double>& fvm, const std::string& what) {
    try {
        return compareValues(r.uDPD, r.uDPDErr, fvm);
    } catch (const std::invalid_argument& e) {
        throw IoError(r.profileFile + " against " + what + ": " + e.what());
    }
}

// What every comparison records about its inputs.
CompareFVMResult newResult(const Setup& s, const ProfileTableData& t, const std::string& time) {
    CompareFVMResult r;
    r.time = time;
    r.foamCase = s.foamCase.string();
    r.foamTime = s.foamTime;
    r.profileFile = t.file;
    r.component = s.component;
    return r;
}

CompareFVMResult compareTime(const Setup& s, const ProfileTableData& t, const std::vector<Eigen::Vector3d>& centres,
                             const std::vector<Eigen::Vector3d>& U, const std::string& time) {
    CompareFVMResult r = newResult(s, t, time);
    r.axis = axisFromLetter(t.axisName());
    if (r.axis < 0) throw IoError(t.file + ": the first column is '" + t.axisName() + "', not a bin axis x, y or z");
    if (r.axis == r.component) s.dict.fail("component", std::string("the component ") + axisLetter(r.component) + " is the profile's axis");
    dpdPoints(t, s.component, r);

    const auto [lo, hi] = fluidRange(s.record, r.axis);
    const std::vector<int> cells = s.record.get<std::vector<int>>("cells");
    const double h = (s.record.get<Eigen::Vector3d>("meshMax")[r.axis] - s.record.get<Eigen::Vector3d>("meshMin")[r.axis]) /
                     cells.at(static_cast<std::size_t>(r.axis));
    const LayerProfile layers = extendToBounds(layerAverage(centres, U, r.axis, s.component, 0.25 * h), lo, hi);
    r.uFVM = interpolateAt(layers.x, layers.u, r.x, lo, hi);
    r.field = compareOrFail(r, r.uFVM, (s.foamCase / s.foamTime / "U").string());

    const std::string setsName = s.record.get<std::string>("setsName");
    for (const std::string& name : s.record.get<std::vector<std::string>>("lines")) {
        const fs::path file = s.foamCase / "postProcessing" / setsName / s.foamTime / (name + "_U.xy");
        std::vector<double> x, u;
        if (!lineProfile(readFoamSampledLine(file.string()), r.axis, s.component, x, u)) {
            r.skippedLines.push_back(name);
            continue;
        }
        r.uLines[name] = interpolateAt(x, u, r.x, lo, hi);
        r.lines[name] = compareOrFail(r, r.uLines[name], file.string());
    }
    return r;
}

bool isGridTable(const ProfileTableData& t) { return t.names.size() > 1 && axisFromLetter(t.names[1]) >= 0; }

double meshCellSize(const Dictionary& record, int axis) {
    return (record.get<Eigen::Vector3d>("meshMax")[axis] - record.get<Eigen::Vector3d>("meshMin")[axis]) /
           record.get<std::vector<int>>("cells").at(static_cast<std::size_t>(axis));
}

// A sampled line along one of the grid's axes, against the row of bins it runs through: the line's
// values at the centres of the compared points in that row, NaN elsewhere. False when the line is not
// along a grid axis.
bool gridLine(const FoamSampledLine& l, const BinGrid& grid, const CompareFVMResult& r, std::vector<double>& out) {
    for (int along = 0; along < 2; ++along) {
        const int axis = along == 0 ? grid.axis0 : grid.axis1;
        std::vector<double> x, u;
        if (!lineProfile(l, axis, r.component, x, u)) continue;
        // Samples further apart than 1.5 spacings straddle solid, where OpenFOAM writes no point.
        double spacing = std::numeric_limits<double>::infinity();
        for (std::size_t i = 1; i < x.size(); ++i)
            if (x[i] > x[i - 1]) spacing = std::min(spacing, x[i] - x[i - 1]);
        const double across = l.points.front()[along == 0 ? grid.axis1 : grid.axis0];
        const long home = along == 0 ? grid.index(0.5 * (grid.lo0 + grid.hi0), across) : grid.index(across, 0.5 * (grid.lo1 + grid.hi1));
        const auto rowOf = [&](long k) { return along == 0 ? k / grid.n0 : k % grid.n0; };
        out.assign(r.x.size(), std::nan(""));
        for (std::size_t p = 0; p < r.x.size() && home >= 0; ++p) {
            if (rowOf(grid.index(r.x[p], r.x2[p])) != rowOf(home)) continue;
            out[p] = interpolateAcrossSamples(x, u, along == 0 ? r.x[p] : r.x2[p], 1.5 * spacing);
        }
        return true;
    }
    return false;
}

CompareFVMResult compareGrid(const Setup& s, const ProfileTableData& t, const std::vector<Eigen::Vector3d>& centres,
                             const std::vector<Eigen::Vector3d>& U, const std::string& time) {
    CompareFVMResult r = newResult(s, t, time);
    r.axis = axisFromLetter(t.names[0]);
    r.axis2 = axisFromLetter(t.names[1]);
    if (r.axis < 0 || r.axis2 == r.axis)
        throw IoError(t.file + ": the first two columns '" + t.names[0] + " " + t.names[1] + "' are not two bin axes");
    const std::string uName = std::string("u") + axisLetter(r.component);
    const std::vector<double>& c0 = t.column(t.names[0]);
    const std::vector<double>& c1 = t.column(t.names[1]);
    const std::vector<double>& u = t.column(uName);
    const std::vector<double>& e = t.column(uName + "Err");
    const std::vector<double>& count = t.column("count");
    const std::vector<double>& density = t.column("density");
    BinGrid grid;
    try {
        grid = gridOfCentres(r.axis, r.axis2, c0, c1);
    } catch (const std::invalid_argument& ex) {
        throw IoError(t.file + ": " + ex.what());
    }
    const BinnedCells cells = binCells(centres, U, r.component, grid);
    for (std::size_t k = 0; k < c0.size(); ++k) {
        if (!usableBin(count[k])) continue;
        r.x.push_back(c0[k]);
        r.x2.push_back(c1[k]);
        r.uDPD.push_back(u[k]);
        r.uDPDErr.push_back(e[k]);
        r.uFVM.push_back(cells.mean(k));
    }
    r.field = compareOrFail(r, r.uFVM, (s.foamCase / s.foamTime / "U").string());

    const std::string setsName = s.record.get<std::string>("setsName");
    for (const std::string& name : s.record.get<std::vector<std::string>>("lines")) {
        const fs::path file = s.foamCase / "postProcessing" / setsName / s.foamTime / (name + "_U.xy");
        std::vector<double> values;
        if (!gridLine(readFoamSampledLine(file.string()), grid, r, values)) {
            r.skippedLines.push_back(name);
            continue;
        }
        r.uLines[name] = values;
        r.lines[name] = compareOrFail(r, values, file.string());
    }

    if (!(s.fluidDensity > 0.0))
        s.dict.fail("fluidDensity", "a 2-D comparison needs the DPD fluid's number density (no system/randomEquilWallDict "
                                    "or blockFrozenWallDict gives it)");
    const double nu = s.record.get<double>("nu");
    const double g = s.record.get<Eigen::Vector3d>("g")[r.component];
    const double cellsPerBin = grid.width0() / meshCellSize(s.record, r.axis) * grid.width1() / meshCellSize(s.record, r.axis2);
    try {
        r.darcyDPD = darcyFromBins(density, u, e, s.fluidDensity, nu, g);
        r.darcyFVM = darcyFromCells(cells, cellsPerBin, nu, g);
    } catch (const std::invalid_argument& ex) {
        throw IoError(t.file + " against " + r.foamCase + ": " + ex.what());
    }
    r.hasDarcy = true;
    return r;
}

}  // namespace

std::vector<CompareFVMResult> runCompareFVM(const CompareFVMOptions& o, std::ostream& out) {
    const Setup s = readSetup(o);
    const fs::path cPath = s.foamCase / s.foamTime / "C";
    const std::vector<Eigen::Vector3d> centres = readFoamVectorField(cPath.string());
    const std::vector<Eigen::Vector3d> U = readFoamVectorField((s.foamCase / s.foamTime / "U").string(), static_cast<long>(centres.size()));
    if (U.size() != centres.size())
        throw IoError((s.foamCase / s.foamTime / "U").string() + ": " + std::to_string(U.size()) + " cell values but " +
                      cPath.string() + " has " + std::to_string(centres.size()) + " cells");

    const auto binsDir = [&](const TimeDirectory& t) { return fs::path(o.caseDir) / "postProcessing" / "profileBins" / t.name; };
    const TimesWithInput selected = selectTimesWithInput(
        o.caseDir, o.time, o.latestTime, [&](const TimeDirectory& t) { return fs::is_directory(binsDir(t)); },
        [&](const TimeDirectory& t) { throw IoError("no directory " + binsDir(t).string() + " (run profileBins first)"); },
        [&](const std::vector<std::string>&) {
            throw IoError("no time of case '" + o.caseDir + "' has postProcessing/profileBins/<time>/ (run profileBins first)");
        });
    std::vector<CompareFVMResult> results;
    for (const TimeDirectory& t : selected.times) {
        const fs::path table = profileTable(s, o.caseDir, t.name);
        if (!fs::is_regular_file(table)) throw IoError("no profile table " + table.string() + " (run profileBins first)");
        const ProfileTableData data = readProfileTable(table.string());
        results.push_back(isGridTable(data) ? compareGrid(s, data, centres, U, t.name) : compareTime(s, data, centres, U, t.name));
    }
    for (const CompareFVMResult& r : results) {
        const fs::path dir = fs::path(o.caseDir) / "postProcessing" / "compareFVM" / r.time;
        writeTextFileAtomically((dir / "profiles.dat").string(), compareFVMProfilesText(r), true);
        writeDictionaryFile((dir / "compare.dat").string(), compareFVMDictionary(r));
    }
    for (const CompareFVMResult& r : results) printCompareFVM(out, r);
    return results;
}

}  // namespace dpd
