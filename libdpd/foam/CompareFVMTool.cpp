#include "foam/CompareFVMTool.hpp"

#include "core/Error.hpp"
#include "foam/FoamFieldFiles.hpp"
#include "io/AtomicFile.hpp"
#include "io/Dictionary.hpp"
#include "io/Snapshot.hpp"
#include "io/TimeDirectories.hpp"
#include "run/DpdProperties.hpp"
#include "sampling/ProfileTable.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <numeric>
#include <ostream>
#include <sstream>

namespace dpd {

namespace fs = std::filesystem;

namespace {

const char* axisLetter(int a) { return a == 0 ? "x" : a == 1 ? "y" : "z"; }
int axisFromLetter(const std::string& s) { return s == "x" ? 0 : s == "y" ? 1 : s == "z" ? 2 : -1; }

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
};

// The DPD case must still be the one makeFoamCase read: same body force, walls and box.
void checkRecord(const Setup& s, const std::string& caseDir) {
    const Dictionary& r = s.record;
    const Dictionary props = Dictionary::readFile((fs::path(caseDir) / "constant" / "dpdProperties").string());
    const DpdModel model = readDpdModel(props);
    const Eigen::Vector3d g = model.bodyForce.type == BodyForce::Type::uniform ? model.bodyForce.g : Eigen::Vector3d::Zero();
    if (!sameVector(r.get<Eigen::Vector3d>("g"), g, g.norm()))
        r.fail("g", "differs from the body force of " + props.fileName() + ": rerun makeFoamCase");
    const std::string wallAxis = r.get<std::string>("wallAxis");
    for (const PlanarWall& w : model.walls.walls()) {
        const int a = axisFromLetter(wallAxis);
        const bool found = a >= 0 && (std::abs(r.subDict("lowerWall").get<double>("position") - w.point[a]) < 1e-9 ||
                                      std::abs(r.subDict("upperWall").get<double>("position") - w.point[a]) < 1e-9);
        if (!found || w.normalAxis() != a)
            r.fail("wallAxis", "wall '" + w.name + "' of " + props.fileName() + " is not where the continuum case has its walls: rerun makeFoamCase");
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

Setup readSetup(const CompareFVMOptions& o) {
    const fs::path caseDir(o.caseDir);
    Setup s;
    s.dict = optionalDictionary(caseDir / "system" / "compareFVMDict");
    const Dictionary& d = s.dict;
    d.checkKeys({"foamCase", "profile", "component", "foamTime"});
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
        s.component = axisFromLetter(d.get<std::string>("component"));
        if (s.component < 0) d.fail("component", "expected x, y or z");
    } else {
        const Eigen::Vector3d g = s.record.get<Eigen::Vector3d>("g");
        int nonzero = 0;
        for (int a = 0; a < 3; ++a)
            if (g[a] != 0.0) s.component = a, ++nonzero;
        if (nonzero != 1) d.fail("component", "the body force does not point along one axis: say which component to compare");
    }
    s.profile = d.getOrDefault<std::string>("profile", "");
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

// The bins the DPD profile has velocities in (at least 3 particle-samples).
void dpdPoints(const ProfileTableData& t, int component, CompareFVMResult& r) {
    const std::string u = std::string("u") + axisLetter(component);
    const std::vector<double>& x = t.column(t.axisName());
    const std::vector<double>& v = t.column(u);
    const std::vector<double>& e = t.column(u + "Err");
    const std::vector<double>* count = t.has("count") ? &t.column("count") : nullptr;
    for (std::size_t i = 0; i < x.size(); ++i) {
        if (count && (*count)[i] < 3.0) continue;
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

CompareFVMResult compareTime(const Setup& s, const ProfileTableData& t, const std::vector<Eigen::Vector3d>& centres,
                             const std::vector<Eigen::Vector3d>& U, const std::string& time) {
    CompareFVMResult r;
    r.time = time;
    r.foamCase = s.foamCase.string();
    r.foamTime = s.foamTime;
    r.profileFile = t.file;
    r.component = s.component;
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

void putMetrics(Dictionary& d, const ComparisonMetrics& m) {
    d.setValue("points", m.points);
    d.setValue("L2", m.L2);
    d.setValue("Linf", m.Linf);
    d.setValue("noiseL2", m.noiseL2);
    d.setValue("meanVelocityDPD", m.meanDPD);
    d.setValue("meanVelocityFVM", m.meanFVM);
    d.setValue("meanVelocityRatio", m.meanVelocityRatio);
}

std::string profilesText(const CompareFVMResult& r) {
    std::ostringstream os;
    os << std::setprecision(17) << "# " << axisLetter(r.axis) << " uDPD uDPDErr uFVM";
    for (const auto& [name, u] : r.uLines) os << " u_" << name;
    os << "\n";
    for (std::size_t i = 0; i < r.x.size(); ++i) {
        os << r.x[i] << " " << r.uDPD[i] << " " << r.uDPDErr[i] << " " << r.uFVM[i];
        for (const auto& [name, u] : r.uLines) os << " " << u[i];
        os << "\n";
    }
    return os.str();
}

void printResult(std::ostream& out, const CompareFVMResult& r) {
    const auto row = [&](const std::string& label, const ComparisonMetrics& m) {
        out << "    " << std::left << std::setw(18) << label << std::right << std::setprecision(5) << "L2 " << std::setw(11)
            << m.L2 << "  Linf " << std::setw(11) << m.Linf << "  mean ratio " << std::setw(9) << m.meanVelocityRatio
            << "  (noise L2 " << m.noiseL2 << ", " << m.points << " points)\n";
    };
    out << "Time = " << r.time << ": " << r.profileFile << " against " << r.foamCase << " at " << r.foamTime << ", u"
        << axisLetter(r.component) << " across " << axisLetter(r.axis) << "\n";
    row("field", r.field);
    for (const auto& [name, m] : r.lines) row("line " + name, m);
    for (const auto& name : r.skippedLines) out << "    line " << name << ": not along " << axisLetter(r.axis) << ", skipped\n";
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

    const std::vector<TimeDirectory> times = selectTimes(o.caseDir, o.time, o.latestTime);
    const bool explicitSelection = o.latestTime || !o.time.empty();
    std::vector<CompareFVMResult> results;
    for (const TimeDirectory& t : times) {
        const fs::path dir = fs::path(o.caseDir) / "postProcessing" / "profileBins" / t.name;
        if (!explicitSelection && !fs::is_directory(dir)) continue;
        const fs::path table = profileTable(s, o.caseDir, t.name);
        if (!fs::is_regular_file(table))
            throw IoError("no profile table " + table.string() + " (run profileBins first)");
        results.push_back(compareTime(s, readProfileTable(table.string()), centres, U, t.name));
    }
    if (results.empty())
        throw IoError("no time of case '" + o.caseDir + "' has postProcessing/profileBins/<time>/ (run profileBins first)");
    for (const CompareFVMResult& r : results) {
        const fs::path dir = fs::path(o.caseDir) / "postProcessing" / "compareFVM" / r.time;
        Dictionary d;
        d.setValue("time", r.time);
        d.setValue("profile", r.profileFile);
        d.setValue("foamCase", r.foamCase);
        d.setValue("foamTime", r.foamTime);
        d.setValue("axis", std::string(axisLetter(r.axis)));
        d.setValue("component", std::string(axisLetter(r.component)));
        putMetrics(d, r.field);
        Dictionary& lines = d.subDictOrCreate("lines");
        for (const auto& [name, m] : r.lines) putMetrics(lines.subDictOrCreate(name), m);
        writeTextFileAtomically((dir / "profiles.dat").string(), profilesText(r), true);
        writeDictionaryFile((dir / "compare.dat").string(), d);
    }
    for (const CompareFVMResult& r : results) printResult(out, r);
    return results;
}

}  // namespace dpd
