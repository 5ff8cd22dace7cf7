#include "case/ControlDict.hpp"

#include <cmath>
#include <filesystem>

namespace dpd {

namespace {

// Step counts are exact in a double and fit a 64-bit integer below 2^53.
constexpr double kMaxSteps = 9007199254740992.0;

std::int64_t stepsFor(const Dictionary& d, const std::string& key, double interval, double deltaT) {
    const double steps = interval / deltaT;
    if (!(steps <= kMaxSteps)) d.fail(key, "is more than 2^53 time steps of deltaT " + std::to_string(deltaT));
    const auto rounded = static_cast<std::int64_t>(std::llround(steps));
    if (rounded < 1 || std::abs(steps - rounded) > 1e-6 * steps)
        d.fail(key, "must be a whole number of time steps (deltaT " + std::to_string(deltaT) + ")");
    return rounded;
}

}  // namespace

RunControl readRunControl(const Dictionary& d) {
    d.checkKeys({"application", "startFrom", "startTime", "stopAt", "endTime", "deltaT", "writeControl",
                 "writeInterval", "reportInterval", "functions", "writeFormat", "writePrecision", "writeCompression",
                 "timeFormat", "timePrecision", "runTimeModifiable", "purgeWrite"});
    RunControl c;
    c.file = d.fileName();
    c.startFrom = d.getOrDefault<std::string>("startFrom", "startTime");
    if (c.startFrom != "startTime" && c.startFrom != "latestTime")
        d.fail("startFrom", "expected startTime or latestTime");
    c.startTime = d.getOrDefault<double>("startTime", 0.0);
    if (c.startTime < 0.0) d.fail("startTime", "must not be negative");
    const std::string stopAt = d.getOrDefault<std::string>("stopAt", "endTime");
    if (stopAt != "endTime") d.fail("stopAt", "only endTime is supported");
    c.deltaT = d.getPositive<double>("deltaT");
    c.endTime = d.get<double>("endTime");
    if (c.endTime < c.startTime) d.fail("endTime", "must not be before startTime");
    if (!((c.endTime - c.startTime) / c.deltaT <= kMaxSteps))
        d.fail("endTime", "is more than 2^53 time steps of deltaT after startTime: no run can count them");
    const std::string writeControl = d.getOrDefault<std::string>("writeControl", "timeStep");
    const double writeInterval = d.getPositive<double>("writeInterval");
    if (writeControl == "timeStep") {
        if (writeInterval != std::floor(writeInterval)) d.fail("writeInterval", "must be a whole number of steps");
        if (!(writeInterval <= kMaxSteps)) d.fail("writeInterval", "is more than 2^53 steps");
        c.writeIntervalSteps = static_cast<std::int64_t>(writeInterval);
    } else if (writeControl == "runTime") {
        c.writeIntervalSteps = stepsFor(d, "writeInterval", writeInterval, c.deltaT);
    } else {
        d.fail("writeControl", "expected timeStep or runTime");
    }
    c.reportIntervalSteps = d.found("reportInterval") ? d.getPositive<long>("reportInterval") : 100;
    if (d.found("functions")) {
        if (!d.isDict("functions")) d.fail("functions", "expected a sub-dictionary");
        c.functions = d.subDict("functions");
    }
    return c;
}

RunControl readControlDict(const std::string& caseDir) {
    return readRunControl(Dictionary::readFile((std::filesystem::path(caseDir) / "system" / "controlDict").string()));
}

}  // namespace dpd
