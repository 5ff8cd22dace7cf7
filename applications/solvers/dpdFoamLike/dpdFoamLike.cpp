// dpdFoamLike: runs a DPD case (system/controlDict, constant/dpdProperties, a start time directory).
#include "app/ToolCommandLine.hpp"
#include "tools/Runner.hpp"

#include <iostream>

int main(int argc, char** argv) {
    return dpd::runTool("dpdFoamLike", [&] {
        dpd::ToolCommandLine cl("dpdFoamLike", "run a dissipative particle dynamics case", false);
        if (!cl.parse(argc, argv)) return;
        dpd::runCase(cl.caseDir(), std::cout);
    });
}
