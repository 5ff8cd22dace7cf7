// randomEquilWall: writes 0/ for walls of any shape (docs/walls.md 3.2): the box filled and
// equilibrated as one fluid, then the particles inside the solid of the geometry block of
// constant/dpdProperties frozen within one cutoff of the fluid and dropped deeper in
// (system/randomEquilWallDict). Under mpirun the equilibration runs on every rank together
// (docs/parallel.md); the first rank writes.
#include "app/ToolCommandLine.hpp"
#include "core/Axis.hpp"
#include "setup/RandomEquilWall.hpp"
#include "io/Dictionary.hpp"
#include "case/DpdProperties.hpp"
#include "parallel/Communicator.hpp"
#include "parallel/MpiSession.hpp"

#include <filesystem>
#include <iostream>

int main(int argc, char** argv) {
    const dpd::MpiSession mpi(argc, argv);
    const dpd::Communicator& world = dpd::Communicator::world();
    const int status = dpd::runTool("randomEquilWall", [&] {
        dpd::ToolCommandLine cl("randomEquilWall", "build the initial particles of walls of any shape (image mask or gmsh)", false);
        if (!cl.parse(argc, argv)) return;
        const std::filesystem::path caseDir(cl.caseDir());
        const auto properties = dpd::Dictionary::readFile((caseDir / "constant" / "dpdProperties").string());
        const dpd::DpdModel model = dpd::readDpdModel(properties, cl.caseDir());
        const auto dict = dpd::Dictionary::readFile((caseDir / "system" / "randomEquilWallDict").string());
        dpd::RandomEquilWallReport r;
        const dpd::Snapshot snap = dpd::buildRandomEquilWall(dict, properties, model, cl.caseDir(), r);
        if (!world.isRoot()) return;
        dpd::writeSnapshot((caseDir / "0").string(), snap);
        std::cout << "Background grid  : " << r.gridCells[0] << " x " << r.gridCells[1] << " x " << r.gridCells[2]
                  << " cells, porosity " << r.gridPorosity << "\n"
                  << "Percolation      : ";
        for (const int a : r.drivingAxes) std::cout << dpd::axisLetter(a) << " ";
        std::cout << (r.drivingAxes.empty() ? "not checked (no driving axis)\n" : "ok\n")
                  << "Filled           : " << r.filled << " particles, equilibrated for " << r.equilibrationSteps
                  << " steps (kT " << r.equilibratedKT << ")\n"
                  << "Fluid particles  : " << r.fluid << " (porosity " << r.particlePorosity << ")\n"
                  << "Frozen particles : " << r.frozen;
        if (r.thickness > 0.0)
            std::cout << " (" << r.withinThickness << " in the wall's thickness " << r.thickness << ": within one cutoff of the "
                      << "fluid frozen, the rest dropped)";
        if (!dict.found("wall")) std::cout << " (no wall entry: a smooth wall, every solid particle dropped)";
        if (r.surfaceOffset > 0.0 || r.fluidStartsBeyond > 0.0)
            std::cout << "\nFluid starts     : " << r.fluidStartsBeyond << " in front of where the wall acts (its repulsion), "
                      << r.surfaceOffset << " behind the geometry's surface (its slipLength)";
        std::cout << "\n"
                  << "Dropped          : " << r.dropped << "\n"
                  << "Written " << (caseDir / "0" / "particles.h5").string() << "\nEnd\n";
    });
    if (status != 0 && world.parallel()) world.abort(status);
    return status;
}
