#pragma once
// Time directories of a case, named as OpenFOAM names them ("0", "20", "0.5").
#include <functional>
#include <string>
#include <vector>

namespace dpd {

struct TimeDirectory {
    double value;
    std::string name;
};

// The name of a time: shortest decimal form at ten significant digits, so that 1000 x 0.02 is "20".
std::string timeName(double t);
// Every directory of the case whose name is a number, in increasing time.
std::vector<TimeDirectory> listTimes(const std::string& caseDir);
// Time selection of the post-processing tools: -time T (a name, a value, or a comma list),
// -latestTime, or (neither) every time but 0. Throws IoError naming the case when the
// selection finds nothing.
std::vector<TimeDirectory> selectTimes(const std::string& caseDir, const std::string& timeOption, bool latestTime,
                                       bool includeZero = false);

// The selected times that hold a post-processing tool's input (hasInput). A time named on the
// command line (-time, -latestTime) must hold it: missing(time) is called and must throw. In the
// default selection (every time but 0) the times without it are passed over and listed in
// `skipped`. When no time holds it, none(skipped) is called and must throw.
struct TimesWithInput {
    std::vector<TimeDirectory> times;
    std::vector<std::string> skipped;
};
TimesWithInput selectTimesWithInput(const std::string& caseDir, const std::string& timeOption, bool latestTime,
                                    const std::function<bool(const TimeDirectory&)>& hasInput,
                                    const std::function<void(const TimeDirectory&)>& missing,
                                    const std::function<void(const std::vector<std::string>&)>& none);

}  // namespace dpd
