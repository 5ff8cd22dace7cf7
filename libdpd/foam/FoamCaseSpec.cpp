#include "foam/FoamCaseSpec.hpp"

#include "core/Axis.hpp"
#include "core/Error.hpp"
#include "geometry/GeometryDictionary.hpp"
#include "io/Dictionary.hpp"
#include "io/TimeDirectories.hpp"
#include "case/DpdProperties.hpp"
#include "walls/GeometryShape.hpp"

#include <cmath>
#include <cstdint>
#include <filesystem>

namespace dpd {

namespace fs = std::filesystem;

namespace {

Box readMeshBox(const Dictionary& dict, const MakeFoamCaseInput& in, int dpdDimension) {
    Box box = in.snapshotBox;
    box.dimension = dpdDimension;
    if (dict.found("box")) {
        const Dictionary& b = dict.subDict("box");
        b.checkKeys({"min", "max"});
        box.lo = b.get<Eigen::Vector3d>("min");
        box.hi = b.get<Eigen::Vector3d>("max");
        for (int a = 0; a < 3; ++a)
            if (!(box.hi[a] > box.lo[a]) && (dpdDimension == 3 || a != 1))
                b.fail("max", std::string("must exceed min along ") + axisLetter(a));
    } else if (in.snapshotFile.empty()) {
        dict.fail("box", "no particle snapshot (<time>/particles.h5 or 0/particles.h5) in case '" + in.caseDir +
                             "' to take the box from: run the wall builder first, or give box { min (..); max (..); }");
    }
    return box;
}

// The slip length the geometry wall asks for (docs/walls.md 3.9), for the solidWalls patch.
double geometryWallSlip(const DpdModel& model) {
    for (std::size_t w = 0; w < model.walls.size(); ++w) {
        const Wall& wall = model.walls[w];
        if (dynamic_cast<const GeometryShape*>(&wall.shape()) && wall.askedSlipLength()) return *wall.askedSlipLength();
    }
    return 0.0;
}

// The two planar walls facing each other along one axis (none is fine: a periodic box).
void readWalls(const Dictionary& dpdProperties, const DpdModel& model, FoamCaseSpec& s) {
    const std::vector<const PlanarWallSettings*> walls = model.planes();
    if (walls.empty()) return;  // a geometry's walls are the geometry block's (readGeometry)
    if (walls.size() != 2)
        dpdProperties.fail("walls", "the continuum case takes no walls or two planar walls facing each other, found " +
                                        std::to_string(walls.size()));
    const int axis = walls[0]->normalAxis();
    if (axis < 0 || walls[1]->normalAxis() != axis)
        dpdProperties.fail("walls", "the walls '" + walls[0]->name + "' and '" + walls[1]->name +
                                        "' are not both normal to the same axis x, y or z");
    const PlanarWallSettings* lo = walls[0];
    const PlanarWallSettings* hi = walls[1];
    if (lo->point[axis] > hi->point[axis]) std::swap(lo, hi);
    if (!(lo->normal[axis] > 0.0 && hi->normal[axis] < 0.0 && hi->point[axis] > lo->point[axis]))
        dpdProperties.fail("walls", "walls '" + lo->name + "' and '" + hi->name + "' do not face each other across a channel");
    for (const PlanarWallSettings* w : {lo, hi})
        if (std::abs(w->velocity[axis]) > 0.0)
            dpdProperties.fail("walls", "wall '" + w->name + "' moves along its normal: no steady continuum case");
    s.wallAxis = axis;
    // A wall that asks for a slip length (docs/walls.md 3.8) gives its twin the same b, from its point.
    const auto slipOf = [](const PlanarWallSettings* w) { return w->asksSlipLength ? w->slipLength : 0.0; };
    s.lower = {lo->name, lo->point[axis], lo->velocity, slipOf(lo)};
    s.upper = {hi->name, hi->point[axis], hi->velocity, slipOf(hi)};
}

// A dictionary file with 'nu' (and 'slipLength'): fit.dat of fitSlipLength.
Dictionary readFitFile(const Dictionary& dict, const std::string& caseDir) {
    const std::string from = dict.found("nuFrom") ? dict.get<std::string>("nuFrom") : std::string(".");
    const fs::path p = fs::path(from).is_absolute() ? fs::path(from) : fs::path(caseDir) / from;
    try {
        return Dictionary::readFile(findFitFile(p.string()));
    } catch (const IoError& e) {
        dict.fail(dict.found("nuFrom") ? "nuFrom" : "nu",
                  std::string(e.what()) + " (give nu as a number, -nu on the command line, or run fitSlipLength)");
    }
}

void readViscosityAndSlip(const Dictionary& dict, const MakeFoamCaseInput& in, FoamCaseSpec& s) {
    if (dict.found("nu") && dict.found("nuFrom")) dict.fail("nuFrom", "give either nu or nuFrom, not both");
    const bool slipFitted = dict.found("slipLength") && dict.rawValue("slipLength") == "fitted";
    Dictionary fit;
    const bool needFit = slipFitted || (!in.nuGiven && !dict.found("nu"));
    if (needFit) fit = readFitFile(dict, in.caseDir);

    if (in.nuGiven) {
        s.nu = in.nu;
        s.nuSource = "command line";
    } else if (dict.found("nu")) {
        s.nu = dict.getPositive<double>("nu");
        s.nuSource = dict.fileName();
    } else {
        s.nu = fit.getPositive<double>("nu");
        s.nuSource = fit.fileName();
    }
    if (!(s.nu > 0.0) || !std::isfinite(s.nu)) dict.fail("nu", "the viscosity must be positive");

    if (!dict.found("slipLength")) return;
    if (s.wallAxis < 0) dict.fail("slipLength", "the case has no planar walls to slip on");
    std::vector<double> beta;
    if (slipFitted) {
        beta = fit.get<std::vector<double>>("slipLength");
        if (beta.size() != 2) fit.fail("slipLength", "expected (lower upper)");
    } else if (dict.rawValue("slipLength").front() == '(') {
        beta = dict.get<std::vector<double>>("slipLength");
        if (beta.size() != 2) dict.fail("slipLength", "expected a number, (lower upper) or fitted");
    } else {
        beta.assign(2, dict.get<double>("slipLength"));
    }
    for (double b : beta)
        if (!(b >= 0.0) || !std::isfinite(b))
            dict.fail("slipLength", "a Navier slip length must be zero or positive (partialSlip walls), got " +
                                        std::to_string(b) + (slipFitted ? " from " + fit.fileName() : ""));
    s.lower.slipLength = beta[0];
    s.upper.slipLength = beta[1];
}

// 2 when nothing varies along y: no wall normal to y, no force along y, a geometry extruded along y.
int readMeshDimension(const Dictionary& dict, const Dictionary& dpdProperties, const DpdModel& model,
                      const FoamCaseSpec& s) {
    std::string yVaries;
    if (s.wallAxis == 1) yVaries = "the walls are normal to y";
    else if (model.bodyForce->value().y() != 0.0) yVaries = "the body force has a y component";
    else if (dpdProperties.found("geometry") && model.dimension == 3 &&
             dpdProperties.subDict("geometry").getOrDefault<std::string>("extrudeAxis", "y") != "y")
        yVaries = "the geometry is not extruded along y";
    const int dflt = yVaries.empty() ? 2 : 3;
    const int dim = dict.getOrDefault<int>("dimension", dflt);
    if (dim != 2 && dim != 3) dict.fail("dimension", "expected 2 or 3");
    if (dim == 2 && !yVaries.empty()) dict.fail("dimension", "a 2-D mesh cannot hold this case: " + yVaries);
    if (dim == 3 && model.dimension == 2) dict.fail("dimension", "the DPD case is 2-D (x-z plane): the mesh must be 2-D");
    return dim;
}

void readMesh(const Dictionary& dict, const Box& box, double cutoff, bool hasGeometry, FoamCaseSpec& s) {
    for (int a = 0; a < 3; ++a) {
        s.lo[a] = box.lo[a];
        s.hi[a] = box.hi[a];
    }
    if (s.wallAxis >= 0) {
        s.lo[s.wallAxis] = s.lower.position;
        s.hi[s.wallAxis] = s.upper.position;
    }
    if (s.dimension == 2 && box.dimension == 2) {  // a 2-D DPD box has no y extent: one unit thick
        s.lo.y() = -0.5;
        s.hi.y() = 0.5;
    }
    if (dict.found("cells")) {
        if (dict.found("cellSize")) dict.fail("cellSize", "give either cells or cellSize, not both");
        const std::vector<int> n = dict.get<std::vector<int>>("cells");
        if (n.size() != 3) dict.fail("cells", "expected three cell counts (nx ny nz)");
        for (int a = 0; a < 3; ++a) {
            if (n[a] < 1) dict.fail("cells", "cell counts must be positive");
            s.cells[a] = n[a];
        }
        if (s.dimension == 2 && s.cells[1] != 1) dict.fail("cells", "a 2-D mesh has one cell along y");
        return;
    }
    const double h = dict.found("cellSize") ? dict.getPositive<double>("cellSize") : cutoff / 4.0;
    for (int a = 0; a < 3; ++a) {
        const bool varies = a == s.wallAxis || (hasGeometry && !(s.dimension == 2 && a == 1));
        s.cells[a] = varies ? std::max(1, static_cast<int>(std::ceil((s.hi[a] - s.lo[a]) / h - 1e-9))) : 1;
    }
}

void readLines(const Dictionary& dict, FoamCaseSpec& s) {
    if (!dict.found("lines")) {
        if (s.wallAxis < 0) return;
        // One line across the channel through the middle of the box, hitting every cell centre and face.
        FoamLine l;
        l.name = "channel";
        l.start = 0.5 * (s.lo + s.hi);
        l.end = l.start;
        l.start[s.wallAxis] = s.lo[s.wallAxis];
        l.end[s.wallAxis] = s.hi[s.wallAxis];
        l.nPoints = 4 * s.cells[s.wallAxis] + 1;
        s.lines.push_back(l);
        return;
    }
    const Dictionary& lines = dict.subDict("lines");
    for (const std::string& name : lines.keys()) {
        const Dictionary& d = lines.subDict(name);
        d.checkKeys({"start", "end", "nPoints"});
        FoamLine l;
        l.name = name;
        l.start = d.get<Eigen::Vector3d>("start");
        l.end = d.get<Eigen::Vector3d>("end");
        l.nPoints = d.getOrDefault<int>("nPoints", 101);
        if (l.nPoints < 2) d.fail("nPoints", "a line needs at least 2 points");
        if ((l.end - l.start).norm() == 0.0) d.fail("end", "the line has no length");
        for (int a = 0; a < 3; ++a) {
            const double tol = 1e-9 * (1.0 + std::abs(s.hi[a] - s.lo[a]));
            for (double v : {l.start[a], l.end[a]})
                if (v < s.lo[a] - tol || v > s.hi[a] + tol)
                    d.fail(v == l.start[a] ? "start" : "end", std::string("lies outside the mesh along ") + axisLetter(a));
        }
        s.lines.push_back(l);
    }
}

// A point of the mesh as the geometry reads it (a 2-D box's geometry lies in y = 0).
Eigen::Vector3d geometryPoint(Eigen::Vector3d r, const Box& box) {
    if (box.dimension == 2) r.y() = 0.0;
    return r;
}

// Every face between a fluid and a solid cell inside the block (faces across a periodic side stay the
// cyclic patch's), slipping by b times the staircase's length per unit of wall, |n|_1 with n the
// geometry's normal at the face: flow along the faces then meets the smooth wall's friction.
void findStaircaseFaces(const SolidGeometry& geometry, const Box& box, const std::vector<std::uint8_t>& solid,
                        FoamCaseSpec& s) {
    const auto label = [&](const std::array<int, 3>& c) {
        return (static_cast<std::size_t>(c[2]) * s.cells[1] + c[1]) * s.cells[0] + c[0];
    };
    const double reach = 2.0 * s.cellSize(0) + 2.0 * s.cellSize(1) + 2.0 * s.cellSize(2);
    for (int k = 0; k < s.cells[2]; ++k)
        for (int j = 0; j < s.cells[1]; ++j)
            for (int i = 0; i < s.cells[0]; ++i) {
                const std::array<int, 3> cell{i, j, k};
                if (solid[label(cell)]) continue;
                for (int a = 0; a < 3; ++a)
                    for (int side : {-1, 1}) {
                        std::array<int, 3> next = cell;
                        next[a] += side;
                        if (next[a] < 0 || next[a] >= s.cells[a] || !solid[label(next)]) continue;
                        Eigen::Vector3d centre = s.cellCentre(i, j, k);
                        centre[a] += 0.5 * side * s.cellSize(a);
                        const Eigen::Vector3d n = geometry.signedDistance(geometryPoint(centre, box), reach).normal;
                        StaircaseFace face;
                        for (int c = 0; c < 3; ++c) face.halfCells[c] = 2L * cell[c] + 1;
                        face.halfCells[a] += side;
                        face.axis = a;
                        face.slipLength = s.solidWallSlip * (n.isZero() ? 1.0 : n.lpNorm<1>() / n.norm());
                        s.staircaseFaces.push_back(face);
                    }
            }
}

void markSolidCells(const Dictionary& dpdProperties, const std::string& caseDir, const Box& box, double cutoff,
                    FoamCaseSpec& s) {
    const SolidGeometry geometry = readGeometry(dpdProperties.subDict("geometry"), caseDir, box, cutoff);
    s.geometrySource = geometry.source();
    std::vector<std::uint8_t> solid(static_cast<std::size_t>(s.cells[0]) * s.cells[1] * s.cells[2], 0);
    for (int k = 0; k < s.cells[2]; ++k)
        for (int j = 0; j < s.cells[1]; ++j)
            for (int i = 0; i < s.cells[0]; ++i) {
                if (!geometry.isSolid(geometryPoint(s.cellCentre(i, j, k), box))) continue;
                const std::size_t cell = (static_cast<std::size_t>(k) * s.cells[1] + j) * s.cells[0] + i;
                s.solidCells.push_back(cell);
                solid[cell] = 1;
            }
    if (s.solidCells.size() == solid.size())
        dpdProperties.fail("geometry", "every cell of the continuum mesh is solid: refine cellSize");
    if (s.solidWallSlip > 0.0) findStaircaseFaces(geometry, box, solid, s);
}

}  // namespace

std::string findFitFile(const std::string& fileOrCase) {
    if (fs::is_regular_file(fileOrCase)) return fileOrCase;
    if (!fs::is_directory(fileOrCase)) throw IoError("'" + fileOrCase + "' is neither a fit.dat file nor a case directory");
    const fs::path dir = fs::path(fileOrCase) / "postProcessing" / "fitSlipLength";
    if (!fs::is_directory(dir)) throw IoError("no " + dir.string() + " (run fitSlipLength on that case)");
    std::vector<TimeDirectory> times = listTimes(dir.string());
    for (auto it = times.rbegin(); it != times.rend(); ++it) {
        const fs::path f = dir / it->name / "fit.dat";
        if (fs::is_regular_file(f)) return f.string();
    }
    throw IoError("no " + (dir / "<time>" / "fit.dat").string() + " (run fitSlipLength on that case)");
}

FoamCaseSpec makeFoamCaseSpec(const Dictionary& dict, const Dictionary& dpdProperties, const MakeFoamCaseInput& in) {
    dict.checkKeys({"foamCase", "nu", "nuFrom", "slipLength", "cellSize", "cells", "dimension", "box", "lines",
                    "maxIterations", "residual"});
    const DpdModel model = readDpdModel(dpdProperties, in.caseDir);
    FoamCaseSpec s;
    s.dpdCase = in.caseDir;
    s.foamCase = dict.getOrDefault<std::string>("foamCase", "simpleFoam");
    if (s.foamCase.empty()) dict.fail("foamCase", "must name a directory");

    const BodyForce& f = *model.bodyForce;
    if (!f.uniform())
        dpdProperties.fail("bodyForce", "a " + f.typeName() + " force has no continuum twin here (use a uniform force)");
    s.g = f.value();

    readWalls(dpdProperties, model, s);
    s.dpdBox = readMeshBox(dict, in, model.dimension);
    if (s.wallAxis >= 0 && (s.lower.position < s.dpdBox.lo[s.wallAxis] || s.upper.position > s.dpdBox.hi[s.wallAxis]))
        dpdProperties.fail("walls", std::string("the walls lie outside the box along ") + axisLetter(s.wallAxis));
    s.dimension = readMeshDimension(dict, dpdProperties, model, s);
    const bool hasGeometry = dpdProperties.found("geometry");
    readMesh(dict, s.dpdBox, model.cutoff, hasGeometry, s);
    readViscosityAndSlip(dict, in, s);
    readLines(dict, s);
    s.maxIterations = dict.getOrDefault<int>("maxIterations", 20000);
    if (s.maxIterations < 1) dict.fail("maxIterations", "must be positive");
    s.residual = dict.found("residual") ? dict.getPositive<double>("residual") : 1e-12;
    if (hasGeometry) {
        s.solidWallSlip = geometryWallSlip(model);
        markSolidCells(dpdProperties, in.caseDir, s.dpdBox, model.cutoff, s);
    }
    return s;
}

}  // namespace dpd
