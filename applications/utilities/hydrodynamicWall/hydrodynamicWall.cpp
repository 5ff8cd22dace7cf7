// hydrodynamicWall: where a wall acts and its slip length, from Couette and Poiseuille fits of the same
// wall settings (docs/analysis.md 5.3).
#include "app/ToolCommandLine.hpp"
#include "tools/HydrodynamicWallTool.hpp"

#include <iostream>
#include <string>
#include <vector>

int main(int argc, char** argv) {
    return dpd::runTool("hydrodynamicWall", [&] {
        dpd::ToolCommandLine cl("hydrodynamicWall",
                                "the hydrodynamic wall position and slip lengths from Couette and Poiseuille fits", false);
        dpd::HydrodynamicWallInput in;
        namespace po = boost::program_options;
        cl.addOptions()("couette", po::value<std::vector<std::string>>(&in.couette)->multitoken()->required(),
                        "the Couette runs (cases or fit.dat files), one per wall setting")(
            "poiseuille", po::value<std::vector<std::string>>(&in.poiseuille)->multitoken()->required(),
            "the Poiseuille runs of the same settings, in the same order")(
            "calibration", po::value<std::string>(&in.calibration),
            "write the slip calibration of a tunable-slip wall's friction sweep (the runs' cases) to this file");
        if (!cl.parse(argc, argv)) return;
        dpd::printHydrodynamicWall(in, std::cout);
    });
}
