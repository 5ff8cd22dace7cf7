#pragma once
// What every tool shares: OpenFOAM-style options (-case DIR, -help, and -time/-latestTime for tools
// that read times), and one place that turns errors into a single clear message and an exit status.
//
// Exit status: 0 success, 1 bad input (dictionary, file, option), 2 the run went unstable,
// 3 anything unexpected.
#include <boost/program_options.hpp>

#include <functional>
#include <string>

namespace dpd {

class ToolCommandLine {
public:
    ToolCommandLine(std::string toolName, std::string description, bool readsTimes);
    // Add tool-specific options here before parse().
    boost::program_options::options_description_easy_init addOptions() { return options_.add_options(); }
    // A bare argument (like foamDictionary's file name) fills this option.
    void setPositional(const std::string& option) { positional_.add(option.c_str(), 1); }
    // Returns false when -help was asked for (the help is printed); throws std::invalid_argument for
    // bad options.
    bool parse(int argc, char** argv);
    const std::string& caseDir() const { return caseDir_; }
    const std::string& time() const { return time_; }
    bool latestTime() const { return latestTime_; }
    bool has(const std::string& option) const { return vm_.count(option) > 0; }
    const std::string& toolName() const { return tool_; }

private:
    std::string tool_;
    boost::program_options::options_description options_;
    boost::program_options::positional_options_description positional_;
    boost::program_options::variables_map vm_;
    std::string caseDir_ = ".";
    std::string time_;
    bool latestTime_ = false;
};

// Runs a tool's body and maps exceptions to a message on stderr and an exit status.
int runTool(const std::string& toolName, const std::function<void()>& body);

}  // namespace dpd
