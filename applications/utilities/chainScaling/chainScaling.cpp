// chainScaling: the Flory exponent nu of R_g ~ N^nu from a sweep of single-chain cases, one chain length
// each (tools/ChainScalingTool.hpp); the result to -output (a dictionary) and the terminal.
#include "app/ToolCommandLine.hpp"
#include "io/Dictionary.hpp"
#include "tools/ChainScalingTool.hpp"

#include <iostream>
#include <string>
#include <vector>

int main(int argc, char** argv) {
    return dpd::runTool("chainScaling", [&] {
        dpd::ToolCommandLine cl("chainScaling", "the Flory exponent from single-chain cases of several lengths", false);
        std::vector<std::string> cases;
        std::string function = "chains", output = "scaling.dat";
        namespace po = boost::program_options;
        cl.addOptions()("cases", po::value<std::vector<std::string>>(&cases)->multitoken()->required(),
                        "the cases, one chain length each")(
            "function", po::value<std::string>(&function), "their chainStatistics function object (default chains)")(
            "output", po::value<std::string>(&output), "the dictionary written (default scaling.dat)");
        if (!cl.parse(argc, argv)) return;
        const dpd::ChainScalingResult r = dpd::chainScaling(cases, function);
        dpd::writeDictionaryFile(output, dpd::chainScalingDictionary(r));
        dpd::printChainScaling(std::cout, r);
        std::cout << "    written " << output << "\nEnd\n";
    });
}
