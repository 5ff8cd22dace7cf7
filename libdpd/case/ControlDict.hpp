#pragma once
// system/controlDict: when a run starts and stops, its step, what it writes and when.
//
//   application   dpdFoamLike;
//   startFrom     startTime;     // startTime | latestTime
//   startTime     0;
//   stopAt        endTime;
//   endTime       100;
//   deltaT        0.02;
//   writeControl  timeStep;      // timeStep | runTime
//   writeInterval 1000;
//   reportInterval 100;          // steps between log reports (default 100)
//   functions { ... }            // run-time sampling (see sampling/FunctionObjects.hpp)
//
// OpenFOAM keywords that mean nothing here (writeFormat, writePrecision, timeFormat, timePrecision,
// runTimeModifiable, writeCompression, purgeWrite) are accepted and ignored so an OpenFOAM user's
// habits do not break a case; any other unknown keyword is an error.
#include "io/Dictionary.hpp"

#include <cstdint>
#include <string>

namespace dpd {

struct RunControl {
    std::string startFrom = "startTime";
    double startTime = 0.0;
    double endTime = 0.0;
    double deltaT = 0.0;
    std::int64_t writeIntervalSteps = 0;  // steps between writes
    std::int64_t reportIntervalSteps = 100;
    Dictionary functions;  // empty when there are none
    std::string file;
};

RunControl readRunControl(const Dictionary& dict);
RunControl readControlDict(const std::string& caseDir);

}  // namespace dpd
