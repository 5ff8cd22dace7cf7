// profileBins: profiles (density, velocity, kT with standard errors) from the bins the solver
// accumulated, written as tables under postProcessing/profileBins/<time>/; -snapshot bins the
// particles of <time>/particles.h5 instead, as system/profileBinsDict says.
#include "app/ToolCommandLine.hpp"
#include "tools/ProfileBinsTool.hpp"

#include <iostream>

int main(int argc, char** argv) {
    return dpd::runTool("profileBins", [&] {
        dpd::ToolCommandLine cl("profileBins", "profile tables from the accumulated bins of each time", true);
        bool snapshot = false;
        cl.addOptions()("snapshot", boost::program_options::bool_switch(&snapshot),
                        "bin the instantaneous particles of <time>/particles.h5 (system/profileBinsDict)");
        if (!cl.parse(argc, argv)) return;
        dpd::ProfileBinsOptions options;
        options.caseDir = cl.caseDir();
        options.time = cl.time();
        options.latestTime = cl.latestTime();
        options.snapshot = snapshot;
        dpd::runProfileBins(options, std::cout);
        std::cout << "End\n";
    });
}
