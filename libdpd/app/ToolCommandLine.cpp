#include "app/ToolCommandLine.hpp"

#include "core/Error.hpp"
#include "parallel/Communicator.hpp"

#include <iostream>
#include <stdexcept>

namespace dpd {

namespace po = boost::program_options;

ToolCommandLine::ToolCommandLine(std::string toolName, std::string description, bool readsTimes)
    : tool_(std::move(toolName)), options_(tool_ + ": " + description + "\n\nOptions") {
    options_.add_options()("help", "print this help and exit")(
        "case", po::value<std::string>(&caseDir_)->default_value("."), "the case directory");
    if (readsTimes)
        options_.add_options()("time", po::value<std::string>(&time_), "the time(s) to process, e.g. 100 or 50,100")(
            "latestTime", po::bool_switch(&latestTime_), "process the latest time only");
}

bool ToolCommandLine::parse(int argc, char** argv) {
    try {
        // OpenFOAM users write -case and -latestTime with one dash; both forms are accepted.
        const int style = po::command_line_style::default_style | po::command_line_style::allow_long_disguise;
        po::store(po::command_line_parser(argc, argv).options(options_).positional(positional_).style(style).run(), vm_);
        if (vm_.count("help")) {
            std::cout << options_ << "\n";
            return false;
        }
        po::notify(vm_);
    } catch (const po::error& e) {
        throw std::invalid_argument(std::string(e.what()) + " (see -help)");
    }
    return true;
}

int runTool(const std::string& tool, const std::function<void()>& body) {
    // Under mpirun every rank may meet the error; which one said it is part of the message.
    const Communicator& world = Communicator::world();
    const std::string toolName = world.rank() > 0 ? tool + " (rank " + std::to_string(world.rank()) + ")" : tool;
    try {
        body();
        return 0;
    } catch (const InputError& e) {
        std::cerr << "\n" << toolName << ": error in input: " << e.what() << "\n";
        return 1;
    } catch (const IoError& e) {
        std::cerr << "\n" << toolName << ": file error: " << e.what() << "\n";
        return 1;
    } catch (const InstabilityError& e) {
        std::cerr << "\n" << toolName << ": " << e.what() << "\n";
        return 2;
    } catch (const std::invalid_argument& e) {
        std::cerr << "\n" << toolName << ": error: " << e.what() << "\n";
        return 1;
    } catch (const std::exception& e) {
        std::cerr << "\n" << toolName << ": error: " << e.what() << "\n";
        return 3;
    }
}

}  // namespace dpd
