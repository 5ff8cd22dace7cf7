#include "BenchmarkScenes.hpp"

#include "io/Dictionary.hpp"
#include "case/DpdProperties.hpp"
#include "setup/ChainedFluid.hpp"
#include "setup/StandardFluid.hpp"
#include "setup/BlockFrozenWall.hpp"
#include "setup/InitialConditions.hpp"
#include "geometry/ImageMask.hpp"
#include "geometry/SignedDistanceField.hpp"
#include "walls/BounceLayerRule.hpp"
#include "walls/GeometryShape.hpp"

#include <cmath>
#include <sstream>

namespace dpd {

BenchmarkScene makeFluidScene(std::size_t particles, double a, int dimension, const Communicator& ranks) {
    StandardFluidSettings fluid;
    fluid.particles = particles * static_cast<std::size_t>(ranks.size());
    fluid.aspect.x() = ranks.size();
    fluid.ranks = &ranks;
    fluid.a = a;
    fluid.dimension = dimension;
    return {"fluid", makeStandardFluid(fluid), FunctionObjects(), -1};
}

BenchmarkScene makeChainsScene(std::size_t particles, double a, const Communicator& ranks) {
    ChainedFluidSettings s;
    s.fluid.particles = particles * static_cast<std::size_t>(ranks.size());
    s.fluid.aspect.x() = ranks.size();
    s.fluid.ranks = &ranks;
    s.fluid.a = a;
    s.length = 30;
    s.chains = std::max<long>(1, static_cast<long>(s.fluid.particles / 10 / 30));  // 10 % of the particles
    return {"chains", makeChainedFluid(s), FunctionObjects(), -1};
}

namespace {

// constant/dpdProperties of tutorials/channel/poiseuille with the walls at z = -10 and 10.
const char* const kChannelProperties = R"(
dimension 3; kT 1; cutoff 1; seed 2026;
species { fluid { frozen no; } wall { frozen yes; } }
pairCoeffs { fluid-fluid { a 18.75; gamma 4.5; } fluid-wall { a 18.75; gamma 4.5; } }
integrator { type GrootWarren; lambda 0.65; }
bodyForce { type uniform; value (0.02 0 0); }
walls
{
    lower { type plane; point (0 0 -10); normal (0 0 1); velocity (0 0 0); reflection bounceBack; }
    upper { type plane; point (0 0 10); normal (0 0 -1); velocity (0 0 0); reflection bounceBack; }
}
)";

}  // namespace

BenchmarkScene makeChannelScene(std::size_t particles) {
    const Dictionary properties = Dictionary::parse(kChannelProperties, "dpdBenchmark channel dpdProperties");
    const DpdModel model = readDpdModel(properties);
    // 22 cutoffs across z (20 of fluid, a wall cutoff each side) at density 4: N = 88 L^2.
    const double side = std::sqrt(static_cast<double>(particles) / 88.0);
    std::ostringstream wall;
    wall << "box { min (" << -side / 2 << " " << -side / 2 << " -11); max (" << side / 2 << " " << side / 2
         << " 11); }\nfluid { species fluid; density 4; }\nwall { species wall; lattice fcc; density 4; thickness 1; }\n";
    BlockFrozenWallReport report;
    Snapshot snapshot =
        buildBlockFrozenWall(Dictionary::parse(wall.str(), "dpdBenchmark channel blockFrozenWallDict"), model, report);
    BenchmarkScene scene{"channel", buildSystem(model, std::move(snapshot), 0.04, "dpdBenchmark channel"),
                         FunctionObjects(), 2};
    const Dictionary functions = Dictionary::parse(
        "profile { type binnedProfile; axis z; nBins 44; min -11; max 11; samplesPerBlock 100; }",
        "dpdBenchmark channel functions");
    scene.sampling = FunctionObjects::read(functions, scene.system);
    scene.system.sortByCell();
    scene.system.computeForces();
    return scene;
}

namespace {

// The fluid scene's fluid with a uniform push along x through the grains, a bounce layer 0.1 thick.
const char* const kGeometryProperties = R"(
dimension 3; kT 1; cutoff 1; seed 2026;
species { fluid { frozen no; } wall { frozen yes; } }
pairCoeffs { fluid-fluid { a 25; gamma 4.5; } fluid-wall { a 25; gamma 4.5; } }
integrator { type GrootWarren; lambda 0.65; }
bodyForce { type uniform; value (0.01 0 0); }
)";

constexpr int kPixelsPerGrain = 16;
constexpr double kGridSpacing = 0.125;  // the distance field's cells, as tutorials/porous/porousMedium
constexpr double kFieldBand = 2.0;      // cutoffs of distance tabulated, as a geometry block's

// A square of grains a side, each a disc on its own square of kPixelsPerGrain pixels, half the area
// solid (grey 0), the rest fluid (255).
GreyImage grainImage(int grains) {
    const int side = grains * kPixelsPerGrain;
    const double radius = kPixelsPerGrain * std::sqrt(0.5 / M_PI);
    GreyImage image{side, side, std::vector<double>(static_cast<std::size_t>(side) * side, 255.0)};
    for (int row = 0; row < side; ++row)
        for (int column = 0; column < side; ++column) {
            const double u = (column % kPixelsPerGrain) + 0.5 - 0.5 * kPixelsPerGrain;
            const double v = (row % kPixelsPerGrain) + 0.5 - 0.5 * kPixelsPerGrain;
            if (u * u + v * v < radius * radius) image.grey[static_cast<std::size_t>(row) * side + column] = 0.0;
        }
    return image;
}

}  // namespace

BenchmarkScene makeGeometryScene(std::size_t particles) {
    DpdModel model = readDpdModel(Dictionary::parse(kGeometryProperties, "dpdBenchmark geometry dpdProperties"));
    // A cube, half of it fluid at rho 3: particles = 1.5 L^3; grains about 8 cutoffs apart.
    const double side = std::cbrt(particles / 1.5);
    const int grains = std::max(2, static_cast<int>(std::lround(side / 8.0)));
    Snapshot snapshot;
    snapshot.box.hi = Eigen::Vector3d(side, side, side);
    ImageMaskSettings mask;
    mask.solidValues = {0.0};
    mask.pixelSize = side / (grains * kPixelsPerGrain);
    mask.extrudeAxis = 1;
    const SolidGeometry geometry =
        imageMaskGeometry(grainImage(grains), mask, snapshot.box, "dpdBenchmark grains", kFieldBand * model.cutoff);
    const BackgroundGrid grid = BackgroundGrid::covering(snapshot.box, kGridSpacing, geometry.uniformAxis());
    auto shape = std::make_shared<GeometryShape>(SignedDistanceField(geometry, grid, kFieldBand * model.cutoff));
    model.walls.add(std::make_shared<Wall>("grains", shape, std::make_shared<BounceLayerRule>(0.1 * model.cutoff)));

    // The fluid at rho 3 in the pores; the grains' frozen particles at the same density, one cutoff deep
    // (by the distance the wall reflects on, so that no fluid particle starts inside).
    const PairRandom random(model.seed);
    const Box& box = snapshot.box;
    const std::size_t fluid = fillRandom(snapshot.particles, box, box.lo, box.hi, 3.0, 0,
                                         [&](double x, double y, double z) { return shape->signedDistance({x, y, z}) > 0.0; },
                                         random, 0);
    maxwellVelocities(snapshot.particles, 0, fluid, 3, model.kT, random);
    fillRandom(snapshot.particles, box, box.lo, box.hi, 3.0, 1,
               [&](double x, double y, double z) {
                   const double d = shape->signedDistance({x, y, z});
                   return d <= 0.0 && d > -model.cutoff;
               },
               random, fluid);
    snapshot.speciesNames = {"fluid", "wall"};
    snapshot.speciesFrozen = {false, true};
    BenchmarkScene scene{"geometry", buildSystem(model, std::move(snapshot), 0.04, "dpdBenchmark geometry"),
                         FunctionObjects(), -1};
    // The pores' flow on a grid of one cutoff, sampled every fifth step, as the porous tutorial samples.
    std::ostringstream functions;
    const int bins = static_cast<int>(std::lround(side));
    functions << "flowField { type binnedProfile; axes (x z); nBins (" << bins << " " << bins << "); min (0 0); max ("
              << side << " " << side << "); species (fluid); sampleInterval 5; samplesPerBlock 200; }";
    scene.sampling = FunctionObjects::read(Dictionary::parse(functions.str(), "dpdBenchmark geometry functions"),
                                           scene.system);
    scene.system.sortByCell();
    scene.system.computeForces();
    return scene;
}

}  // namespace dpd
