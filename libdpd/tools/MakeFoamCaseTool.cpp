#include "tools/MakeFoamCaseTool.hpp"

#include "core/Axis.hpp"
#include "core/Error.hpp"
#include "foam/FoamCaseWriter.hpp"
#include "io/Dictionary.hpp"
#include "io/Snapshot.hpp"
#include "io/TimeDirectories.hpp"

#include <filesystem>
#include <ostream>

namespace dpd {

namespace fs = std::filesystem;

namespace {

// The latest time directory with a particle snapshot, 0/ included; "" when there is none.
std::string latestSnapshot(const std::string& caseDir) {
    const std::vector<TimeDirectory> times = listTimes(caseDir);
    for (auto it = times.rbegin(); it != times.rend(); ++it) {
        const fs::path f = fs::path(caseDir) / it->name / snapshotFileName;
        if (fs::is_regular_file(f)) return f.string();
    }
    return "";
}

}  // namespace

FoamCaseSpec runMakeFoamCase(const MakeFoamCaseOptions& o, std::ostream& out) {
    const fs::path caseDir(o.caseDir);
    if (!fs::is_directory(caseDir)) throw IoError("case directory '" + o.caseDir + "' does not exist");
    const fs::path dictFile = o.dictFile.empty() ? caseDir / "system" / "makeFoamCaseDict" : fs::path(o.dictFile);
    if (!o.dictFile.empty() && !fs::exists(dictFile)) throw IoError("-dict: no file '" + o.dictFile + "'");
    const Dictionary dict = fs::exists(dictFile) ? Dictionary::readFile(dictFile.string()) : Dictionary(dictFile.string());
    const Dictionary props = Dictionary::readFile((caseDir / "constant" / "dpdProperties").string());

    MakeFoamCaseInput in;
    in.caseDir = o.caseDir;
    in.nuGiven = o.nuGiven;
    in.nu = o.nu;
    if (o.nuGiven && !(o.nu > 0.0)) throw InputError("", 0, "-nu", "the viscosity must be positive");
    if (!dict.found("box")) {
        in.snapshotFile = latestSnapshot(o.caseDir);
        if (!in.snapshotFile.empty()) in.snapshotBox = readSnapshot(in.snapshotFile).box;
    }
    FoamCaseSpec spec = makeFoamCaseSpec(dict, props, in);
    if (!o.output.empty()) spec.foamCase = o.output;
    const fs::path target = fs::path(spec.foamCase).is_absolute() ? fs::path(spec.foamCase) : caseDir / spec.foamCase;
    writeFoamCase(spec, target.string());

    out << "OpenFOAM case " << target.string() << " (simpleFoam, laminar)\n"
        << "    box from     " << (in.snapshotFile.empty() ? dictFile.string() : in.snapshotFile) << "\n"
        << "    mesh         " << spec.cells[0] << " x " << spec.cells[1] << " x " << spec.cells[2] << " cells, "
        << spec.dimension << "-D, from (" << spec.lo.transpose() << ") to (" << spec.hi.transpose() << ")\n";
    if (spec.wallAxis >= 0)
        out << "    walls        " << spec.lower.name << " and " << spec.upper.name << " normal to " << axisLetter(spec.wallAxis)
            << ", slip lengths " << spec.lower.slipLength << " " << spec.upper.slipLength << "\n";
    if (!spec.solidCells.empty())
        out << "    solid cells  " << spec.solidCells.size() << " (from " << spec.geometrySource << ")\n";
    out << "    nu           " << spec.nu << " (" << spec.nuSource << ")\n"
        << "    body force   (" << spec.g.transpose() << ")\n"
        << "    lines        " << spec.lines.size() << "\n"
        << "Run it: " << (target / "Allrun").string() << "\n";
    return spec;
}

}  // namespace dpd
