// dpdFoamLike: runs a DPD case (system/controlDict, constant/dpdProperties, a start time directory);
// under mpirun, on every rank together (docs/parallel.md).
#include "app/ToolCommandLine.hpp"
#include "parallel/Communicator.hpp"
#include "parallel/MpiSession.hpp"
#include "tools/Runner.hpp"

#include <iostream>

int main(int argc, char** argv) {
    const dpd::MpiSession mpi(argc, argv);
    const int status = dpd::runTool("dpdFoamLike", [&] {
        dpd::ToolCommandLine cl("dpdFoamLike", "run a dissipative particle dynamics case", false);
        if (!cl.parse(argc, argv)) return;
        dpd::runCase(cl.caseDir(), std::cout);
    });
    // An error met by some ranks only would leave the others waiting for them.
    if (status != 0 && dpd::Communicator::world().parallel()) dpd::Communicator::world().abort(status);
    return status;
}
