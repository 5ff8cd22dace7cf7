// slipCalibration: a slip calibration's range and the wall it gives each asked slip length
// (docs/walls.md 3.7-3.8).
#include "app/ToolCommandLine.hpp"
#include "tools/SlipCalibrationTool.hpp"

#include <iostream>
#include <string>
#include <vector>

int main(int argc, char** argv) {
    return dpd::runTool("slipCalibration", [&] {
        dpd::ToolCommandLine cl("slipCalibration",
                                "a slip calibration's range and the friction and plane offset it gives each asked slip length", false);
        dpd::SlipCalibrationQuery q;
        namespace po = boost::program_options;
        cl.addOptions()("file", po::value<std::string>(&q.file)->required(), "the calibration (e.g. constant/slipCalibration)")(
            "slipLength", po::value<std::vector<double>>(&q.slipLengths)->multitoken(),
            "slip lengths to ask for, from 0 to the largest calibrated");
        if (!cl.parse(argc, argv)) return;
        dpd::printSlipCalibration(q, std::cout);
    });
}
