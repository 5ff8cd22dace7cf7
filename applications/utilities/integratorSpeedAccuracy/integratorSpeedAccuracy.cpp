// integratorSpeedAccuracy: kT, pressure and viscosity errors, stability and cost of each integrator
// against the time step on the standard fluid, from system/integratorSpeedAccuracyDict, into
// postProcessing/integratorSpeedAccuracy/speedAccuracy.dat.
#include "app/ToolCommandLine.hpp"
#include "studies/SpeedAccuracyStudy.hpp"
#include "io/AtomicFile.hpp"
#include "io/Dictionary.hpp"

#include <filesystem>
#include <iostream>

int main(int argc, char** argv) {
    return dpd::runTool("integratorSpeedAccuracy", [&] {
        dpd::ToolCommandLine cl("integratorSpeedAccuracy", "kT, pressure and viscosity errors, stability and cost of the integrators against deltaT", false);
        if (!cl.parse(argc, argv)) return;
        const std::filesystem::path dir(cl.caseDir());
        const dpd::SpeedAccuracySettings s = dpd::readSpeedAccuracySettings(
            dpd::Dictionary::readFile((dir / "system" / "integratorSpeedAccuracyDict").string()));
        const auto rows = dpd::runSpeedAccuracyStudy(s, std::cout);
        const auto out = dir / "postProcessing" / "integratorSpeedAccuracy" / "speedAccuracy.dat";
        dpd::writeTextFileAtomically(out.string(), dpd::speedAccuracyTable(rows, s), true);
        std::cout << "Written " << out.string() << "\n";
    });
}
