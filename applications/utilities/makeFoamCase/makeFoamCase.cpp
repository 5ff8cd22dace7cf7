// makeFoamCase: writes the OpenFOAM simpleFoam twin of a DPD case (mesh, nu, body force, sampling
// lines, Allrun), as set in the optional system/makeFoamCaseDict; see libdpd/foam/FoamCaseSpec.hpp.
#include "app/ToolCommandLine.hpp"
#include "tools/MakeFoamCaseTool.hpp"

#include <iostream>

int main(int argc, char** argv) {
    return dpd::runTool("makeFoamCase", [&] {
        dpd::ToolCommandLine cl("makeFoamCase", "write the OpenFOAM simpleFoam case of a DPD case", false);
        double nu = 0.0;
        std::string output, dictFile;
        cl.addOptions()("nu", boost::program_options::value<double>(&nu),
                        "the DPD fluid's measured viscosity (overrides makeFoamCaseDict)")(
            "output", boost::program_options::value<std::string>(&output),
            "the OpenFOAM case directory to write (default: foamCase of makeFoamCaseDict, simpleFoam)")(
            "dict", boost::program_options::value<std::string>(&dictFile),
            "the settings file (default: <case>/system/makeFoamCaseDict)");
        if (!cl.parse(argc, argv)) return;
        dpd::MakeFoamCaseOptions options;
        options.caseDir = cl.caseDir();
        options.nuGiven = cl.has("nu");
        options.nu = nu;
        options.output = output;
        options.dictFile = dictFile;
        dpd::runMakeFoamCase(options, std::cout);
        std::cout << "End\n";
    });
}
