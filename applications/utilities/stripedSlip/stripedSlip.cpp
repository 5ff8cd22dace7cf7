// stripedSlip: the continuum reference for striped walls (docs/analysis.md 5.1) from the command line.
#include "app/ToolCommandLine.hpp"
#include "tools/StripedSlipTool.hpp"

#include <iostream>
#include <limits>
#include <sstream>
#include <string>

int main(int argc, char** argv) {
    return dpd::runTool("stripedSlip", [&] {
        dpd::ToolCommandLine cl("stripedSlip", "the effective slip of striped walls, from the continuum reference", false);
        dpd::StripedSlipQuery q;
        std::string angles, slip = "inf", height = "inf";
        namespace po = boost::program_options;
        cl.addOptions()("period", po::value<double>(&q.wall.period)->default_value(1.0), "the stripes' period L")(
            "gasFraction", po::value<double>(&q.wall.slipFraction)->default_value(0.5), "phi2, the gas sectors' share")(
            "slip", po::value<std::string>(&slip)->default_value("inf"), "the gas sectors' local slip length b (inf: shear-free)")(
            "height", po::value<std::string>(&height)->default_value("inf"), "the channel height H (inf: a single wall in shear)")(
            "walls", po::value<int>(&q.wall.stripedWalls)->default_value(1), "striped walls of the channel: 1 or 2 (in phase)")(
            "angles", po::value<std::string>(&angles), "angles to the stripes in degrees, comma-separated (b_eff, flux ratio)");
        if (!cl.parse(argc, argv)) return;
        const auto number = [](const std::string& text, const char* option) {
            if (text == "inf") return std::numeric_limits<double>::infinity();
            std::size_t used = 0;
            const double v = std::stod(text, &used);
            if (used != text.size()) throw std::invalid_argument(std::string("-") + option + ": '" + text + "' is not a number");
            return v;
        };
        q.wall.localSlip = number(slip, "slip");
        q.wall.height = number(height, "height");
        std::stringstream in(angles);
        for (std::string item; std::getline(in, item, ',');) q.anglesDegrees.push_back(number(item, "angles"));
        dpd::printStripedSlip(q, std::cout);
    });
}
