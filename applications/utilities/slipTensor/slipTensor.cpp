// slipTensor: the effective slip tensor of a channel between striped walls (docs/analysis.md 5.4), from a
// run driven at an angle to the stripes; results in postProcessing/slipTensor/<time>/fit.dat.
#include "app/ToolCommandLine.hpp"
#include "tools/SlipTensorTool.hpp"

#include <iostream>

int main(int argc, char** argv) {
    return dpd::runTool("slipTensor", [&] {
        dpd::ToolCommandLine cl("slipTensor", "b_par, b_perp, b_eff(theta) and the transverse flux of striped walls", true);
        if (!cl.parse(argc, argv)) return;
        dpd::FitSlipLengthOptions options;
        options.caseDir = cl.caseDir();
        options.time = cl.time();
        options.latestTime = cl.latestTime();
        dpd::runSlipTensor(options, std::cout);
        std::cout << "End\n";
    });
}
