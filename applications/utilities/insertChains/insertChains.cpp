// insertChains: puts polymer chains (system/insertChainsDict) into the built case's 0/particles.h5.
#include "app/ToolCommandLine.hpp"
#include "tools/InsertChainsTool.hpp"

#include <iostream>

int main(int argc, char** argv) {
    return dpd::runTool("insertChains", [&] {
        dpd::ToolCommandLine cl("insertChains", "put polymer chains into the built case's time 0", false);
        if (!cl.parse(argc, argv)) return;
        dpd::runInsertChains(cl.caseDir(), std::cout);
        std::cout << "End\n";
    });
}
