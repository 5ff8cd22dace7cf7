// compareFVM: the DPD profile against the OpenFOAM simpleFoam solution of the case's continuum twin
// (makeFoamCase); results in postProcessing/compareFVM/<time>/; see libdpd/tools/CompareFVMTool.hpp.
#include "app/ToolCommandLine.hpp"
#include "tools/CompareFVMTool.hpp"

#include <iostream>

int main(int argc, char** argv) {
    return dpd::runTool("compareFVM", [&] {
        dpd::ToolCommandLine cl("compareFVM", "DPD profiles against the OpenFOAM simpleFoam solution", true);
        std::string foamCase;
        cl.addOptions()("foamCase", boost::program_options::value<std::string>(&foamCase),
                        "the OpenFOAM case (default: foamCase of compareFVMDict or makeFoamCaseDict, simpleFoam)");
        if (!cl.parse(argc, argv)) return;
        dpd::CompareFVMOptions options;
        options.caseDir = cl.caseDir();
        options.time = cl.time();
        options.latestTime = cl.latestTime();
        options.foamCase = foamCase;
        dpd::runCompareFVM(options, std::cout);
        std::cout << "End\n";
    });
}
