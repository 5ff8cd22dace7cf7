// fitSlipLength: viscosity, slip length and slip velocity from the profiles of profileBins, as set in
// system/fitSlipLengthDict; results in postProcessing/fitSlipLength/<time>/fit.dat.
#include "tools/FitSlipLengthTool.hpp"
#include "app/ToolCommandLine.hpp"

#include <iostream>

int main(int argc, char** argv) {
    return dpd::runTool("fitSlipLength", [&] {
        dpd::ToolCommandLine cl("fitSlipLength", "viscosity and wall slip from Poiseuille or reverse-Poiseuille profiles", true);
        if (!cl.parse(argc, argv)) return;
        dpd::FitSlipLengthOptions options;
        options.caseDir = cl.caseDir();
        options.time = cl.time();
        options.latestTime = cl.latestTime();
        dpd::runFitSlipLength(options, std::cout);
        std::cout << "End\n";
    });
}
