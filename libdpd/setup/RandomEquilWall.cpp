#include "setup/RandomEquilWall.hpp"

#include "core/Axis.hpp"
#include "geometry/GeometryDictionary.hpp"
#include "geometry/Percolation.hpp"
#include "integrators/Integrator.hpp"
#include "parallel/Communicator.hpp"
#include "io/Dictionary.hpp"
#include "case/BoxDictionary.hpp"
#include "case/DpdProperties.hpp"
#include "case/RunCompatibility.hpp"
#include "setup/InitialConditions.hpp"
#include "setup/InitialFlow.hpp"
#include "system/Monitors.hpp"
#include "system/System.hpp"
#include "walls/GeometryShape.hpp"
#include "core/ThreadBudget.hpp"

#include <algorithm>
#include <cmath>

namespace dpd {

namespace {

int speciesOf(const Dictionary& parent, const std::string& key, const DpdModel& model, bool frozen) {
    const Dictionary& d = parent.subDict(key);
    d.checkKeys(frozen ? std::vector<std::string>{"species", "thickness"}
                       : std::vector<std::string>{"species", "density", "initialFlow"});
    const std::string name = d.get<std::string>("species");
    const int s = model.species.indexOf(name);
    if (s < 0) d.fail("species", "'" + name + "' is not a species of constant/dpdProperties");
    if (model.species[s].frozen != frozen)
        d.fail("species", "'" + name + "' must " + (frozen ? "" : "not ") + "be frozen (see species in constant/dpdProperties)");
    return s;
}

// Where the geometry's wall has the fluid begin: how far behind the geometry's surface the wall acts (a
// wall that asks for a slip length), and how far in front of that the fluid starts (its surface force's
// repulsion).
struct FluidStart {
    double offset = 0.0, beyond = 0.0;
};

FluidStart fluidStartOf(const DpdModel& model) {
    for (std::size_t k = 0; k < model.walls.size(); ++k)
        if (const auto* shape = dynamic_cast<const GeometryShape*>(&model.walls[k].shape())) {
            const SurfaceForce* force = model.walls[k].surfaceForce();
            return {shape->surfaceOffset(), force ? force->fluidStartsBeyond() : 0.0};
        }
    return {};
}

std::vector<int> drivingAxes(const Dictionary& d, const DpdModel& model) {
    if (d.found("drivingAxis")) {
        const std::string s = d.get<std::string>("drivingAxis");
        if (s == "none") return {};
        if (s != "x" && s != "y" && s != "z") d.fail("drivingAxis", "expected x, y, z or none, not '" + s + "'");
        const int axis = s[0] - 'x';
        if (model.dimension == 2 && axis == 1) d.fail("drivingAxis", "a 2-D scene lies in the x-z plane");
        return {axis};
    }
    std::vector<int> axes;
    for (int a = 0; a < 3; ++a)
        if (model.bodyForce->value()[a] != 0.0) axes.push_back(a);
    return axes;
}

void checkFlags(const SolidFlags& flags, const std::vector<int>& axes, const Dictionary& dict,
                const Dictionary& geometryDict) {
    if (flags.fluidCells() == 0)
        geometryDict.fail("file", "the geometry has no fluid: every cell of the box is solid (check solidValues/solidBelow/"
                                  "solidAbove, or the \"fluid\"/\"solid\" group)");
    if (flags.fluidCells() == flags.grid().size())
        geometryDict.fail("file", "the geometry has no solid: the whole box is fluid (nothing to freeze; use blockFrozenWall "
                                  "without walls for a plain fluid)");
    for (const int a : axes)
        if (!fluidPercolates(flags, a)) {
            const std::string message = std::string("the fluid does not percolate along ") + axisLetter(a) +
                                        ": no fluid path crosses the periodic box along the driving axis";
            if (dict.found("drivingAxis")) dict.fail("drivingAxis", message);
            geometryDict.fail("file", message + " (the direction of bodyForce in constant/dpdProperties)");
        }
}

// Runs the filled box as one fluid, without walls or body force, for the set time.
void equilibrate(Snapshot& snap, const Dictionary& dict, const DpdModel& model, RandomEquilWallReport& report) {
    const Dictionary& ed = dict.subDict("equilibration");
    ed.checkKeys({"time", "deltaT"});
    const double time = ed.getNonNegative<double>("time");
    const double dt = ed.getPositive<double>("deltaT");
    DpdModel fluidOnly = model;
    fluidOnly.bodyForce = noBodyForce();
    fluidOnly.walls = WallList{};  // the box is filled through the solids too
    // Under mpirun the ranks share the box (docs/parallel.md); every rank then goes on with all of it.
    System sys = buildSystem(fluidOnly, snap, dt, "the filled box of system/randomEquilWallDict", &Communicator::world());
    std::vector<RunPart> parts = caseParts(fluidOnly);
    parts.push_back(ranksPart(sys.domain() ? sys.domain()->communicator().size() : 1));
    checkCompatibility(parts);
    const auto integrator = makeIntegrator(model.integrator);
    useThreadsForParticles(sys.particles.size());
    sys.sortByCell();
    sys.computeForces();
    sys.dropGhosts();
    report.equilibrationSteps = static_cast<std::size_t>(std::llround(time / dt));
    for (std::size_t k = 0; k < report.equilibrationSteps; ++k) integrator->step(sys);
    const MonitorReport m = monitor(sys, -1);
    if (!m.finite) ed.fail("deltaT", "the equilibration went unstable (non-finite values): reduce deltaT");
    report.equilibratedKT = m.kT;
    snap.particles = sys.domain() ? sys.domain()->gatherToAll(sys.orderedParticles()) : std::move(sys.particles);
}

// Keeps the fluid (renumbered first) and the solid particles within one cutoff of the fluid. Fluid is
// what both the geometry and the run's distance field call fluid: a particle of the geometry's fluid
// that the field puts inside (a few at the surface, where the interpolated field and the exact shape
// differ by a fraction of a grid cell) is dropped, so the run starts with no fluid inside its wall
// and the wall is the geometry's solid, nothing more. With a wall thickness (a published wall's depth)
// the solid particles within it are counted too; those beyond one cutoff are dropped all the same.
// A wall acting `start.offset` behind the geometry's surface (one that asks for a slip length) keeps
// the fluid up to where it acts and freezes from there; a wall whose force repels the fluid keeps it
// `start.beyond` in front. Without a wall species (wallSpecies < 0: a smooth wall, whose force stands
// in for the solid) every solid particle is dropped.
Particles freezeWall(const Particles& p, const SolidRegion& solid, double cutoff, double thickness, FluidStart start,
                     int fluidSpecies, int wallSpecies, RandomEquilWallReport& report) {
    const SolidGeometry& geometry = solid.geometry;
    const double offset = start.offset;
    const double reach = std::max(cutoff, thickness) + offset;
    std::vector<std::size_t> fluid, frozen;
    report.withinThickness = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const Eigen::Vector3d r(p.rx[i], p.ry[i], p.rz[i]);
        const bool fluidHere = solid.distance.distance(r) + offset >= start.beyond;  // as the run's wall sees it
        if (!geometry.isSolid(r)) {
            if (fluidHere) fluid.push_back(i);
            continue;
        }
        const double depth = -geometry.signedDistance(r, 2.0 * reach).distance - offset;  // behind the acting surface
        if (offset > 0.0 && depth < 0.0) {
            if (fluidHere) fluid.push_back(i);
            continue;
        }
        if (wallSpecies >= 0 && depth <= cutoff) frozen.push_back(i);
        if (thickness > 0.0 && depth <= thickness) ++report.withinThickness;
    }
    Eigen::Vector3d mean(0, 0, 0);
    for (const std::size_t i : fluid) mean += Eigen::Vector3d(p.vx[i], p.vy[i], p.vz[i]);
    if (!fluid.empty()) mean /= static_cast<double>(fluid.size());
    Particles out;
    out.reserve(fluid.size() + frozen.size());
    for (const std::size_t i : fluid)
        out.add(out.size(), fluidSpecies, p.rx[i], p.ry[i], p.rz[i], p.vx[i] - mean.x(), p.vy[i] - mean.y(), p.vz[i] - mean.z());
    for (const std::size_t i : frozen) out.add(out.size(), wallSpecies, p.rx[i], p.ry[i], p.rz[i]);
    report.fluid = fluid.size();
    report.frozen = frozen.size();
    report.dropped = p.size() - fluid.size() - frozen.size();
    report.particlePorosity = static_cast<double>(fluid.size()) / static_cast<double>(p.size());
    return out;
}

}  // namespace

Snapshot buildRandomEquilWall(const Dictionary& dict, const Dictionary& dpdProperties, const DpdModel& model,
                              const std::string& caseDir, RandomEquilWallReport& report) {
    dict.checkKeys({"box", "fluid", "wall", "equilibration", "drivingAxis"});
    if (!model.planes().empty())
        dpdProperties.fail("walls", "randomEquilWall builds the walls from the geometry block: remove the planar walls");
    if (!dpdProperties.found("geometry"))
        dpdProperties.fail("geometry", "randomEquilWall needs the shape of the solid: add a geometry { type imageMask; ... } "
                                       "or geometry { type gmsh; ... } block");
    const Dictionary& geometryDict = dpdProperties.subDict("geometry");
    Snapshot snap;
    snap.box = readBoxDictionary(dict, model.dimension, model.cutoff);
    snap.speciesNames = model.species.names();
    for (int s = 0; s < model.species.size(); ++s) snap.speciesFrozen.push_back(model.species[s].frozen);
    const int fluidSpecies = speciesOf(dict, "fluid", model, false);
    const int wallSpecies = dict.found("wall") ? speciesOf(dict, "wall", model, true) : -1;
    const double density = dict.subDict("fluid").getPositive<double>("density");
    report.drivingAxes = drivingAxes(dict, model);
    const InitialFlow flow = readInitialFlow(dict.subDict("fluid"), model, snap.box, fluidSpecies, density);

    // 1. The geometry and its flags, checked before any particle moves.
    // The distance field is the one the run's geometry wall uses (case/DpdProperties buildSystem).
    const SolidRegion solid = readSolidRegion(geometryDict, caseDir, snap.box, model.cutoff);
    const SolidFlags& flags = solid.flags;
    report.gridPorosity = flags.porosity();
    report.gridCells = flags.grid().n;
    checkFlags(flags, report.drivingAxes, dict, geometryDict);

    // 2. The whole box at the density, equilibrated as one fluid.
    const PairRandom random(model.seed);
    report.filled = fillRandom(snap.particles, snap.box, snap.box.lo, snap.box.hi, density, fluidSpecies,
                               [](double, double, double) { return true; }, random, 0);
    maxwellVelocities(snap.particles, 0, report.filled, model.dimension, model.kT, random);
    equilibrate(snap, dict, model, report);

    // 3. Freeze the wall, drop the rest of the solid.
    report.thickness = dict.found("wall") && dict.subDict("wall").found("thickness")
                           ? dict.subDict("wall").getPositive<double>("thickness") : 0.0;
    const FluidStart start = fluidStartOf(model);
    report.surfaceOffset = start.offset;
    report.fluidStartsBeyond = start.beyond;
    snap.particles = freezeWall(snap.particles, solid, model.cutoff, report.thickness, start, fluidSpecies, wallSpecies,
                                report);
    addInitialFlow(snap.particles, 0, report.fluid, flow);  // the fluid comes first
    snap.time = 0.0;
    snap.step = 0;
    return snap;
}

}  // namespace dpd
