// blockFrozenWall: writes 0/ for a planar channel: fluid between the walls of constant/dpdProperties
// and frozen lattice walls behind them (system/blockFrozenWallDict).
#include "app/ToolCommandLine.hpp"
#include "io/Dictionary.hpp"
#include "case/DpdProperties.hpp"
#include "setup/BlockFrozenWall.hpp"

#include <filesystem>
#include <iostream>

int main(int argc, char** argv) {
    return dpd::runTool("blockFrozenWall", [&] {
        dpd::ToolCommandLine cl("blockFrozenWall", "build the initial particles of a channel with frozen lattice walls", false);
        if (!cl.parse(argc, argv)) return;
        const std::filesystem::path caseDir(cl.caseDir());
        const dpd::DpdModel model = dpd::readDpdProperties(cl.caseDir());
        const auto dict = dpd::Dictionary::readFile((caseDir / "system" / "blockFrozenWallDict").string());
        dpd::BlockFrozenWallReport report;
        const dpd::Snapshot snap = dpd::buildBlockFrozenWall(dict, model, report);
        dpd::writeSnapshot((caseDir / "0").string(), snap);
        std::cout << "Fluid particles  : " << report.fluid << " (volume " << report.fluidVolume << ")\n";
        const dpd::InitialFlow& flow = report.initialFlow;
        if (flow.type != dpd::InitialFlow::Type::none)
            std::cout << "Initial flow     : "
                      << (flow.type == dpd::InitialFlow::Type::poiseuille ? "Poiseuille" : "reverse Poiseuille")
                      << " for nu " << flow.nu << "\n";
        for (std::size_t k = 0; k < report.wallNames.size(); ++k)
        {
            std::cout << "Wall " << report.wallNames[k] << " : " << report.frozenPerWall[k] << " frozen particles";
            if (report.latticePerWall[k] != report.frozenPerWall[k])
                std::cout << " (" << report.latticePerWall[k]
                          << " in the lattice's thickness; those deeper than one cutoff never meet the fluid)";
            std::cout << "\n";
        }
        std::cout << "Written " << (caseDir / "0" / "particles.h5").string() << "\nEnd\n";
    });
}
