#include "foam/FoamCaseWriter.hpp"

#include "core/Axis.hpp"
#include "core/Error.hpp"
#include "foam/StaircaseSlipScript.hpp"
#include "io/AtomicFile.hpp"
#include "io/Dictionary.hpp"

#include <filesystem>
#include <iomanip>
#include <limits>
#include <sstream>

#include <sys/stat.h>

namespace dpd {

namespace fs = std::filesystem;

namespace {

const char* axisUpper(int a) { return a == 0 ? "X" : a == 1 ? "Y" : "Z"; }

// Shortest form that reads back the same double.
std::string num(double x) {
    std::string text;
    for (int digits = 1; digits <= std::numeric_limits<double>::max_digits10; ++digits) {
        std::ostringstream os;
        os << std::setprecision(digits) << x;
        text = os.str();
        if (std::stod(text) == x) break;
    }
    return text;
}

std::string vec(const Eigen::Vector3d& v) { return "(" + num(v.x()) + " " + num(v.y()) + " " + num(v.z()) + ")"; }

std::string header(const std::string& cls, const std::string& object, const std::string& location = "") {
    std::string s = "/*--------------------------------*- C++ -*----------------------------------*\\\n"
                    "  OpenFOAM case written by makeFoamCase (dpdFoamLike): the continuum twin of a DPD case\n"
                    "\\*---------------------------------------------------------------------------*/\n"
                    "FoamFile\n{\n    version     2.0;\n    format      ascii;\n    class       " +
                    cls + ";\n";
    if (!location.empty()) s += "    location    \"" + location + "\";\n";
    return s + "    object      " + object + ";\n}\n\n";
}

std::string periodicPatch(int axis, bool high) {
    return std::string("periodic") + axisUpper(axis) + (high ? "High" : "Low");
}

double staircaseValueFraction(const FoamCaseSpec& s, const StaircaseFace& f) {
    return partialSlipValueFraction(f.slipLength, s.cellSize(f.axis));
}

// What the staircase's faces take until the Allrun gives each its own: a flat wall's, on the first.
double flatWallValueFraction(const FoamCaseSpec& s) {
    if (s.staircaseFaces.empty()) return 1.0;
    return partialSlipValueFraction(s.solidWallSlip, s.cellSize(s.staircaseFaces.front().axis));
}

// The boundary conditions of U or p on every patch, one line each.
std::string boundaryField(const FoamCaseSpec& s, bool velocity) {
    std::ostringstream os;
    os << "boundaryField\n{\n";
    if (s.wallAxis >= 0) {
        const double h = s.cellSize(s.wallAxis);
        for (const FoamWall* w : {&s.lower, &s.upper}) {
            os << "    " << w->name << "\n    {\n";
            const double f = partialSlipValueFraction(w->slipLength, h);
            if (!velocity) os << "        type            zeroGradient;\n";
            else if (w->slipLength > 0.0 && w->velocity.squaredNorm() > 0.0)
                // The moving wall's Navier slip u_w - U = b du/dn over the half cell: u_w = f U + (1 - f) U_P.
                os << "        type            mixed;          // Navier slip length " << num(w->slipLength)
                   << " on a wall moving at U: u = f U + (1 - f) u_P, f = (h/2) / (beta + h/2)\n"
                   << "        refValue        uniform " << vec(w->velocity) << ";\n        refGradient     uniform (0 0 0);\n"
                   << "        valueFraction   uniform " << num(f) << ";\n        value           uniform " << vec(w->velocity) << ";\n";
            else if (w->slipLength > 0.0)
                os << "        type            partialSlip;    // Navier slip length " << num(w->slipLength)
                   << ": f = (h/2) / (beta + h/2)\n        valueFraction   uniform "
                   << num(f) << ";\n        value           uniform (0 0 0);\n";
            else if (w->velocity.squaredNorm() > 0.0)
                os << "        type            fixedValue;\n        value           uniform " << vec(w->velocity) << ";\n";
            else os << "        type            noSlip;\n";
            os << "    }\n";
        }
    }
    for (int a = 0; a < 3; ++a)
        if (s.isPeriodic(a)) os << "    \"periodic" << axisUpper(a) << ".*\"\n    {\n        type            cyclic;\n    }\n";
    if (s.dimension == 2) os << "    frontAndBack\n    {\n        type            empty;\n    }\n";
    if (!s.solidCells.empty()) {
        os << "    solidWalls\n    {\n";
        if (velocity && s.solidWallSlip > 0.0) {
            os << "        type            partialSlip;    // Navier slip length " << num(s.solidWallSlip)
               << " along the wall: each face its own f after subsetMesh (Allrun, staircaseSlip.awk)\n"
                  "        valueFraction   uniform "
               << num(flatWallValueFraction(s)) << ";\n        value           uniform (0 0 0);\n";
        } else {
            os << "        type            " << (velocity ? "noSlip" : "zeroGradient") << ";\n";
        }
        os << "    }\n";
    }
    os << "}\n";
    return os.str();
}

std::string fvSchemes() {
    return header("dictionary", "fvSchemes", "system") +
           "ddtSchemes      { default steadyState; }\n"
           "gradSchemes     { default Gauss linear; }\n"
           "divSchemes\n{\n    default         none;\n    div(phi,U)      bounded Gauss linear;\n"
           "    div((nuEff*dev2(T(grad(U))))) Gauss linear;\n}\n"
           "laplacianSchemes { default Gauss linear corrected; }\n"
           "interpolationSchemes { default linear; }\n"
           "snGradSchemes   { default corrected; }\n";
}

// SIMPLEC (consistent) with U relaxed by 0.95 and p not at all: the slowest (viscous) mode of an N-cell
// channel then decays by about 1 / (1 + 19 (pi/N)^2 / 2) per iteration: to 1e-12 in ~500 iterations for
// N = 40, ~6000 for N = 160 (measured: 424-487 and 6016; seconds on a small mesh). Linear solvers run
// to relTol 0.01 each iteration; the outer loop stops at `residual` (normalised initial residuals of p
// and U), or at maxIterations.
std::string fvSolution(const FoamCaseSpec& s) {
    return header("dictionary", "fvSolution", "system") +
           "solvers\n{\n"
           "    p\n    {\n        solver          GAMG;\n        smoother        GaussSeidel;\n"
           "        tolerance       1e-14;\n        relTol          0.01;\n    }\n"
           "    U\n    {\n        solver          smoothSolver;\n        smoother        symGaussSeidel;\n"
           "        tolerance       1e-14;\n        relTol          0.01;\n    }\n}\n\n"
           "SIMPLE\n{\n    nNonOrthogonalCorrectors 0;\n    consistent      yes;\n"
           "    pRefCell        0;      // periodic p: fix its level (no mean pressure gradient)\n"
           "    pRefValue       0;\n"
           "    residualControl\n    {\n        p               " + num(s.residual) + ";\n        U               " +
           num(s.residual) + ";\n    }\n}\n\n"
           "relaxationFactors\n{\n    equations\n    {\n        U               0.95;\n    }\n"
           "    fields\n    {\n        p               1;\n    }\n}\n";
}

std::string transportProperties(const FoamCaseSpec& s) {
    return header("dictionary", "transportProperties", "constant") + "transportModel  Newtonian;\n\n// " + s.nuSource +
           "\nnu              " + num(s.nu) + ";\n";
}

std::string turbulenceProperties() {
    return header("dictionary", "turbulenceProperties", "constant") + "simulationType  laminar;\n";
}

std::string allrun(const FoamCaseSpec& s) {
    std::string text =
        "#!/bin/bash\n"
        "# simpleFoam twin of a DPD case, written by makeFoamCase. Run: ./Allrun  (logs in log.<tool>)\n"
        "cd \"${0%/*}\" || exit 1\n"
        "if [ -z \"${WM_PROJECT_DIR:-}\" ] || ! command -v simpleFoam >/dev/null 2>&1; then\n"
        "    # The Debian package's environment; it reports helper scripts the package leaves out: harmless.\n"
        "    . \"${FOAM_BASHRC:-/usr/share/openfoam/etc/bashrc}\" >/dev/null 2>&1\n"
        "fi\n"
        "command -v simpleFoam >/dev/null 2>&1 || {\n"
        "    echo \"Allrun: OpenFOAM not found (install the Debian package openfoam, or set FOAM_BASHRC)\" >&2; exit 1; }\n"
        "run() { echo \"Running $1\"; \"$@\" > \"log.$1\" 2>&1 || { tail -n 20 \"log.$1\" >&2; "
        "echo \"Allrun: $1 failed (see log.$1)\" >&2; exit 1; }; }\n"
        "run blockMesh\n";
    if (!s.solidCells.empty())
        text += "run topoSet\n"
                "# subsetMesh maps the fields and leaves the faces it exposes without values of their own (a\n"
                "# partialSlip's valueFraction among them): the fields as written, all uniform, are read afresh.\n"
                "rm -rf 0.orig 0/C 0/Cx 0/Cy 0/Cz && cp -r 0 0.orig\n"
                "run subsetMesh fluid -patch solidWalls -overwrite\n"
                "rm -rf 0 && mv 0.orig 0\n";
    if (!s.staircaseFaces.empty())
        text += "# Each face of the slipping staircase its own valueFraction (constant/staircaseSlip), found by its\n"
                "# centre: subsetMesh orders the patch's faces itself.\n"
                "run postProcess -func writeCellCentres -time 0\n"
                "awk -f staircaseSlip.awk constant/staircaseSlip 0/C 0/U > 0/U.staircase || exit 1\n"
                "mv 0/U.staircase 0/U && rm -f 0/C 0/Cx 0/Cy 0/Cz\n";
    text += "run simpleFoam\n"
            "grep -q 'SIMPLE solution converged' log.simpleFoam || "
            "echo \"Allrun: warning: simpleFoam stopped at endTime before reaching residualControl\" >&2\n"
            "run postProcess -func writeCellCentres -latestTime\n";
    return text;
}

std::string allclean() {
    return "#!/bin/bash\n"
           "# Removes what Allrun made: time directories but 0/, the mesh, postProcessing, logs.\n"
           "cd \"${0%/*}\" || exit 1\n"
           "for d in [0-9]*; do [ -d \"$d\" ] && [ \"$d\" != 0 ] && rm -rf -- \"$d\"; done\n"
           "rm -rf -- constant/polyMesh postProcessing log.*\n";
}

void writeFile(const fs::path& path, const std::string& text, bool executable = false) {
    writeTextFileAtomically(path.string(), text, true);
    if (executable) ::chmod(path.c_str(), 0755);
}

}  // namespace

double partialSlipValueFraction(double beta, double h) { return 0.5 * h / (beta + 0.5 * h); }

std::string foamBlockMeshDict(const FoamCaseSpec& s) {
    const Eigen::Vector3d& a = s.lo;
    const Eigen::Vector3d& b = s.hi;
    std::ostringstream os;
    os << header("dictionary", "blockMeshDict", "system") << "convertToMeters 1;\n\nvertices\n(\n";
    const Eigen::Vector3d v[8] = {{a.x(), a.y(), a.z()}, {b.x(), a.y(), a.z()}, {b.x(), b.y(), a.z()},
                                  {a.x(), b.y(), a.z()}, {a.x(), a.y(), b.z()}, {b.x(), a.y(), b.z()},
                                  {b.x(), b.y(), b.z()}, {a.x(), b.y(), b.z()}};
    for (const auto& p : v) os << "    " << vec(p) << "\n";
    os << ");\n\nblocks\n(\n    hex (0 1 2 3 4 5 6 7) (" << s.cells[0] << " " << s.cells[1] << " " << s.cells[2]
       << ") simpleGrading (1 1 1)\n);\n\n";
    // Faces of the block per axis and side, numbered so that their normals point out of the block.
    const char* faces[3][2] = {{"(0 4 7 3)", "(1 2 6 5)"}, {"(0 1 5 4)", "(3 7 6 2)"}, {"(0 3 2 1)", "(4 5 6 7)"}};
    os << "boundary\n(\n";
    for (int ax = 0; ax < 3; ++ax) {
        if (ax == s.wallAxis) {
            os << "    " << s.lower.name << "\n    {\n        type wall;\n        faces (" << faces[ax][0] << ");\n    }\n";
            os << "    " << s.upper.name << "\n    {\n        type wall;\n        faces (" << faces[ax][1] << ");\n    }\n";
        } else if (s.isPeriodic(ax)) {
            for (int side = 0; side < 2; ++side)
                os << "    " << periodicPatch(ax, side == 1) << "\n    {\n        type cyclic;\n        neighbourPatch "
                   << periodicPatch(ax, side == 0) << ";\n        faces (" << faces[ax][side] << ");\n    }\n";
        }
    }
    if (s.dimension == 2)
        os << "    frontAndBack\n    {\n        type empty;\n        faces (" << faces[1][0] << " " << faces[1][1]
           << ");\n    }\n";
    if (!s.solidCells.empty())
        os << "    solidWalls      // filled by subsetMesh with the faces exposed by the solid cut\n"
              "    {\n        type wall;\n        faces ();\n    }\n";
    os << ");\n";
    return os.str();
}

std::string foamVelocityField(const FoamCaseSpec& s) {
    return header("volVectorField", "U", "0") + "dimensions      [0 1 -1 0 0 0 0];\n\ninternalField   uniform (0 0 0);\n\n" +
           boundaryField(s, true);
}

std::string foamPressureField(const FoamCaseSpec& s) {
    return header("volScalarField", "p", "0") +
           "// Kinematic pressure; periodic with no mean gradient: the body force (system/fvOptions) drives the flow.\n"
           "dimensions      [0 2 -2 0 0 0 0];\n\ninternalField   uniform 0;\n\n" +
           boundaryField(s, false);
}

std::string foamControlDict(const FoamCaseSpec& s) {
    std::ostringstream os;
    os << header("dictionary", "controlDict", "system") << "application     simpleFoam;\n\n"
       << "startFrom       startTime;\nstartTime       0;\nstopAt          endTime;\n"
       << "endTime         " << s.maxIterations << ";     // SIMPLE iterations at most; residualControl stops earlier\n"
       << "deltaT          1;\n\nwriteControl    timeStep;\nwriteInterval   " << s.maxIterations
       << ";\npurgeWrite      0;\nwriteFormat     ascii;\nwritePrecision  17;\nwriteCompression off;\n"
       << "timeFormat      general;\ntimePrecision   6;\nrunTimeModifiable true;\n";
    if (s.lines.empty()) return os.str();
    os << "\nfunctions\n{\n    sampledLines\n    {\n        type            sets;\n        libs            (\"libsampling.so\");\n"
       << "        writeControl    writeTime;\n        interpolationScheme cellPoint;\n        setFormat       raw;\n"
       << "        fields          (U);\n        sets\n        (\n";
    for (const FoamLine& l : s.lines)
        os << "            " << l.name << "\n            {\n                type    uniform;\n                axis    xyz;\n"
           << "                start   " << vec(l.start) << ";\n                end     " << vec(l.end) << ";\n"
           << "                nPoints " << l.nPoints << ";\n            }\n";
    os << "        );\n    }\n}\n";
    return os.str();
}

std::string foamFvOptions(const FoamCaseSpec& s) {
    return header("dictionary", "fvOptions", "system") +
           "// The DPD body force per unit mass, on every cell.\n"
           "bodyForce\n{\n    type            vectorSemiImplicitSource;\n    active          yes;\n\n"
           "    vectorSemiImplicitSourceCoeffs\n    {\n        selectionMode   all;\n        volumeMode      specific;\n"
           "        injectionRateSuSp\n        {\n            U           (" + vec(s.g) + " 0);\n        }\n    }\n}\n";
}

std::string foamTopoSetDict(const FoamCaseSpec& s) {
    std::ostringstream os;
    os << header("dictionary", "topoSetDict", "system")
       << "// The fluid cells: every cell but the solid ones, whose centres lie in the solid of\n// " << s.geometrySource
       << " (blockMesh cell labels i + nx (j + ny k)).\nactions\n(\n    {\n        name    fluid;\n        type    cellSet;\n"
       << "        action  new;\n        source  labelToCell;\n        value\n        (";
    for (std::size_t n = 0; n < s.solidCells.size(); ++n) os << (n % 12 == 0 ? "\n            " : " ") << s.solidCells[n];
    os << "\n        );\n    }\n    {\n        name    fluid;\n        type    cellSet;\n        action  invert;\n    }\n);\n";
    return os.str();
}

std::string foamStaircaseSlip(const FoamCaseSpec& s) {
    std::ostringstream os;
    os << "// The faces of the staircase the geometry wall leaves (" << s.geometrySource << "), slipping by " << num(s.solidWallSlip)
       << "\n// times |n|_1 of the wall's normal n there (docs/walls.md 3.9), for staircaseSlip.awk: each face's\n"
          "// centre in half cells from the mesh's corner (origin, halfCell), its valueFraction and slip length.\n"
       << "origin " << num(s.lo.x()) << " " << num(s.lo.y()) << " " << num(s.lo.z()) << "\n"
       << "halfCell " << num(0.5 * s.cellSize(0)) << " " << num(0.5 * s.cellSize(1)) << " " << num(0.5 * s.cellSize(2)) << "\n";
    for (const StaircaseFace& f : s.staircaseFaces)
        os << f.halfCells[0] << " " << f.halfCells[1] << " " << f.halfCells[2] << " " << num(staircaseValueFraction(s, f))
           << " " << num(f.slipLength) << "\n";
    return os.str();
}

std::string foamCaseRecord(const FoamCaseSpec& s) {
    Dictionary d;
    d.setValue("dpdCase", fs::absolute(s.dpdCase).lexically_normal().string());
    d.setValue("dpdDimension", s.dpdBox.dimension);
    d.setValue("dpdBoxMin", Eigen::Vector3d(s.dpdBox.lo));
    d.setValue("dpdBoxMax", Eigen::Vector3d(s.dpdBox.hi));
    d.setValue("meshMin", Eigen::Vector3d(s.lo));
    d.setValue("meshMax", Eigen::Vector3d(s.hi));
    d.setValue("cells", std::vector<int>{s.cells[0], s.cells[1], s.cells[2]});
    d.setValue("dimension", s.dimension);
    d.setValue("wallAxis", std::string(s.wallAxis >= 0 ? axisLetter(s.wallAxis) : "none"));
    if (s.wallAxis >= 0)
        for (const auto& [key, w] : {std::pair<const char*, const FoamWall*>{"lowerWall", &s.lower}, {"upperWall", &s.upper}}) {
            Dictionary& wd = d.subDictOrCreate(key);
            wd.setValue("patch", w->name);
            wd.setValue("position", w->position);
            wd.setValue("velocity", Eigen::Vector3d(w->velocity));
            wd.setValue("slipLength", w->slipLength);
        }
    d.setValue("g", Eigen::Vector3d(s.g));
    d.setValue("nu", s.nu);
    d.setValue("nuSource", s.nuSource);
    d.setValue("setsName", std::string("sampledLines"));
    std::vector<std::string> names;
    for (const FoamLine& l : s.lines) names.push_back(l.name);
    d.setValue("lines", names);
    d.setValue("solidCells", static_cast<long>(s.solidCells.size()));
    if (!s.geometrySource.empty()) d.setValue("geometry", s.geometrySource);
    return d.toString();
}

void writeFoamCase(const FoamCaseSpec& s, const std::string& dir) {
    const fs::path c(dir);
    writeFile(c / "0" / "U", foamVelocityField(s));
    writeFile(c / "0" / "p", foamPressureField(s));
    writeFile(c / "constant" / "transportProperties", transportProperties(s));
    writeFile(c / "constant" / "turbulenceProperties", turbulenceProperties());
    writeFile(c / "constant" / "dpdCase", header("dictionary", "dpdCase", "constant") + foamCaseRecord(s));
    writeFile(c / "system" / "blockMeshDict", foamBlockMeshDict(s));
    writeFile(c / "system" / "controlDict", foamControlDict(s));
    writeFile(c / "system" / "fvSchemes", fvSchemes());
    writeFile(c / "system" / "fvSolution", fvSolution(s));
    writeFile(c / "system" / "fvOptions", foamFvOptions(s));
    std::error_code ec;
    if (!s.solidCells.empty()) writeFile(c / "system" / "topoSetDict", foamTopoSetDict(s));
    else fs::remove(c / "system" / "topoSetDict", ec);
    if (!s.staircaseFaces.empty()) {
        writeFile(c / "constant" / "staircaseSlip", foamStaircaseSlip(s));
        writeFile(c / "staircaseSlip.awk", staircaseSlipScript());
    } else {
        fs::remove(c / "constant" / "staircaseSlip", ec);
        fs::remove(c / "staircaseSlip.awk", ec);
    }
    writeFile(c / "Allrun", allrun(s), true);
    writeFile(c / "Allclean", allclean(), true);
}

}  // namespace dpd
