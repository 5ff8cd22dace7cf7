#include "setup/BlockFrozenWall.hpp"

#include "io/Dictionary.hpp"
#include "case/BoxDictionary.hpp"
#include "case/DpdProperties.hpp"
#include "setup/InitialConditions.hpp"
#include "setup/InitialFlow.hpp"
#include "setup/FrozenLattice.hpp"

#include <algorithm>
#include <cmath>

namespace dpd {

namespace {

int speciesIndex(const Dictionary& d, const DpdModel& model, bool wantFrozen) {
    const std::string name = d.get<std::string>("species");
    const int idx = model.species.indexOf(name);
    if (idx < 0) d.fail("species", "species '" + name + "' is not defined in constant/dpdProperties");
    if (model.species[idx].frozen != wantFrozen)
        d.fail("species", "species '" + name + (wantFrozen ? "' must be frozen" : "' must not be frozen"));
    return idx;
}

FrozenLatticeSettings readLattice(const Dictionary& wd, const DpdModel& model) {
    wd.checkKeys({"species", "lattice", "density", "thickness", "layers", "spacing", "staggered"});
    FrozenLatticeSettings s;
    s.lattice = wd.get<std::string>("lattice");
    if (s.lattice != "fcc" && s.lattice != "simpleCubic" && s.lattice != "layers")
        wd.fail("lattice", "expected fcc, simpleCubic or layers");
    if (s.lattice != "layers") s.density = wd.getPositive<double>("density");
    s.thickness = wd.found("thickness") ? wd.getPositive<double>("thickness") : model.cutoff;
    if (s.lattice == "layers") {
        s.layerDepths = wd.get<std::vector<double>>("layers");
        s.layerSpacing = wd.get<std::vector<double>>("spacing");
        s.staggered = wd.getOrDefault<bool>("staggered", false);
    } else if (wd.found("staggered")) {
        wd.fail("staggered", "only the layers lattice takes 'staggered' (fcc staggers its planes itself)");
    }
    return s;
}

// The lattice points a fluid particle can reach: a wall whose rule returns the fluid at its plane keeps
// it in front, so a point deeper than one cutoff behind the plane never meets it (docs/walls.md 3.1).
// With rule none the fluid may enter the solid, and every point is kept.
std::vector<Eigen::Vector3d> withinReachOfFluid(std::vector<Eigen::Vector3d> points, const PlanarWallSettings& w,
                                                double cutoff) {
    if (!w.rule->returnsFluid()) return points;
    points.erase(std::remove_if(points.begin(), points.end(),
                                [&](const Eigen::Vector3d& r) { return -w.signedDistance(r.x(), r.y(), r.z()) >= cutoff; }),
                 points.end());
    return points;
}

}  // namespace

Snapshot buildBlockFrozenWall(const Dictionary& d, const DpdModel& model, BlockFrozenWallReport& report) {
    d.checkKeys({"box", "fluid", "wall"});
    Snapshot snap;
    snap.box = readBoxDictionary(d, model.dimension, model.cutoff);
    for (int s = 0; s < model.species.size(); ++s) {
        snap.speciesNames.push_back(model.species[s].name);
        snap.speciesFrozen.push_back(model.species[s].frozen);
    }
    const std::vector<const PlanarWallSettings*> walls = model.planes();
    for (const PlanarWallSettings* w : walls)
        for (int a = 0; a < 3; ++a)
            if (snap.box.isActiveAxis(a) && (w->actingPoint()[a] < snap.box.lo[a] || w->actingPoint()[a] > snap.box.hi[a]))
                d.fail("box", "wall '" + w->name + "' of constant/dpdProperties lies outside the box");
    const std::string thin = model.walls.builtOn({snap.box, model.caseDir, model.cutoff}).thinWall(walls, snap.box, model.cutoff);
    if (!thin.empty())
        d.fail("box", "the solid behind wall '" + thin +
                          "' is thinner than one cutoff inside the box: enlarge the box along the wall normal");

    const Dictionary& fd = d.subDict("fluid");
    fd.checkKeys({"species", "density", "initialFlow"});
    const int fluidSpecies = speciesIndex(fd, model, false);
    const double density = fd.getPositive<double>("density");
    const PairRandom random(model.seed);
    // Fluid starts at least sigma in front of a tunable-slip wall: nearer, its WCA repulsion (more than
    // eps there, diverging at the plane) would throw the particle across the box on the first step.
    const auto clearOfWalls = [&](double x, double y, double z) {
        for (const PlanarWallSettings* w : walls)
            if (w->signedDistance(x, y, z) < (w->hasTunableSlip ? w->tunableSlip.sigma : 0.0)) return false;
        return true;
    };
    report.fluid = fillRandom(snap.particles, snap.box, snap.box.lo, snap.box.hi, density, fluidSpecies, clearOfWalls,
                              random, 0);
    report.fluidVolume = report.fluid / density;
    maxwellVelocities(snap.particles, 0, report.fluid, model.dimension, model.kT, random);
    report.initialFlow = readInitialFlow(fd, model, snap.box, fluidSpecies, density);
    addInitialFlow(snap.particles, 0, report.fluid, report.initialFlow);

    // Tunable-slip walls act on the fluid without frozen particles: when every wall is one, `wall` may
    // be left out.
    const bool everyWallSmooth =
        std::all_of(walls.begin(), walls.end(), [](const PlanarWallSettings* w) { return w->hasTunableSlip; });
    if (!walls.empty() && !(everyWallSmooth && !d.found("wall"))) {
        if (!d.found("wall")) d.fail("wall", "constant/dpdProperties has walls: say how to build them");
        const Dictionary& wd = d.subDict("wall");
        const int wallSpecies = speciesIndex(wd, model, true);
        const FrozenLatticeSettings lattice = readLattice(wd, model);
        for (const PlanarWallSettings* w : walls) {
            std::vector<Eigen::Vector3d> points;
            try {
                points = frozenLattice(snap.box, *w, lattice);
            } catch (const std::invalid_argument& e) {
                wd.fail("lattice", e.what());
            }
            report.latticePerWall.push_back(points.size());
            points = withinReachOfFluid(std::move(points), *w, model.cutoff);
            for (const auto& r : points)
                snap.particles.add(snap.particles.size(), wallSpecies, r.x(), r.y(), r.z(), w->velocity.x(),
                                   w->velocity.y(), w->velocity.z());
            report.frozenPerWall.push_back(points.size());
            report.wallNames.push_back(w->name);
        }
    }
    return snap;
}

}  // namespace dpd
