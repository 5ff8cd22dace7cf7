#include "io/TimeDirectories.hpp"

#include "core/Error.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <stdexcept>

namespace dpd {

namespace fs = std::filesystem;

std::string timeName(double t) {
    std::ostringstream os;
    os.precision(10);
    os << t;
    return os.str();
}

namespace {

bool parseNumber(const std::string& s, double& out) {
    if (s.empty()) return false;
    char* end = nullptr;
    out = std::strtod(s.c_str(), &end);
    return end == s.c_str() + s.size() && std::isfinite(out);
}

std::vector<std::string> splitCommas(const std::string& s) {
    std::vector<std::string> parts;
    std::stringstream ss(s);
    std::string item;
    while (std::getline(ss, item, ',')) parts.push_back(item);
    return parts;
}

}  // namespace

std::vector<TimeDirectory> listTimes(const std::string& caseDir) {
    std::vector<TimeDirectory> out;
    if (!fs::is_directory(caseDir)) throw IoError("case directory '" + caseDir + "' does not exist");
    for (const auto& entry : fs::directory_iterator(caseDir)) {
        if (!entry.is_directory()) continue;
        const std::string name = entry.path().filename().string();
        double value;
        if (parseNumber(name, value)) out.push_back({value, name});
    }
    std::sort(out.begin(), out.end(), [](const TimeDirectory& a, const TimeDirectory& b) { return a.value < b.value; });
    return out;
}

std::vector<TimeDirectory> selectTimes(const std::string& caseDir, const std::string& timeOption, bool latestTime,
                                       bool includeZero) {
    const std::vector<TimeDirectory> all = listTimes(caseDir);
    std::vector<TimeDirectory> chosen;
    if (latestTime) {
        if (!all.empty()) chosen.push_back(all.back());
    } else if (!timeOption.empty()) {
        for (const std::string& want : splitCommas(timeOption)) {
            double value;
            if (!parseNumber(want, value)) throw IoError("-time '" + want + "' is not a number");
            const auto it = std::find_if(all.begin(), all.end(), [&](const TimeDirectory& t) {
                return std::abs(t.value - value) <= 1e-9 * std::max(1.0, std::abs(value));
            });
            if (it == all.end()) throw IoError("case '" + caseDir + "' has no time directory " + want);
            chosen.push_back(*it);
        }
    } else {
        for (const auto& t : all)
            if (includeZero || t.value != 0.0) chosen.push_back(t);
    }
    if (chosen.empty()) throw IoError("case '" + caseDir + "' has no time directory to process");
    return chosen;
}

TimesWithInput selectTimesWithInput(const std::string& caseDir, const std::string& timeOption, bool latestTime,
                                    const std::function<bool(const TimeDirectory&)>& hasInput,
                                    const std::function<void(const TimeDirectory&)>& missing,
                                    const std::function<void(const std::vector<std::string>&)>& none) {
    const bool named = latestTime || !timeOption.empty();
    const char* const mustThrow = "selectTimesWithInput: missing() and none() must throw";
    TimesWithInput selected;
    for (const TimeDirectory& t : selectTimes(caseDir, timeOption, latestTime)) {
        if (hasInput(t)) {
            selected.times.push_back(t);
        } else if (named) {
            missing(t);
            throw std::logic_error(mustThrow);
        } else {
            selected.skipped.push_back(t.name);
        }
    }
    if (selected.times.empty()) {
        none(selected.skipped);
        throw std::logic_error(mustThrow);
    }
    return selected;
}

}  // namespace dpd
