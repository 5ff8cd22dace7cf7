#include "tools/FitSuperBlocks.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace dpd {

SuperBlockSetup readSuperBlockSetup(const Dictionary& fitDict) {
    SuperBlockSetup s;
    if (!fitDict.found("superBlocks")) return s;
    const Dictionary& d = fitDict.subDict("superBlocks");
    d.checkKeys({"length", "decayTimes", "minimum"});
    const bool length = d.found("length"), decay = d.found("decayTimes");
    if (length == decay) d.fail(length ? "decayTimes" : "", "give one of length (time units) and decayTimes");
    if (length) s.length = d.getPositive<double>("length");
    if (decay) s.decayTimes = d.getPositive<double>("decayTimes");
    if (d.found("minimum")) {
        s.minimum = d.getPositive<int>("minimum");
        if (s.minimum < 2) d.fail("minimum", "a jackknife needs at least 2 super-blocks");
    }
    return s;
}

double samplingBlockTime(const Dictionary& controlDict, const std::string& profile, long blockSamples,
                         const Dictionary& fitDict) {
    if (!controlDict.isDict("functions") || !controlDict.subDict("functions").isDict(profile))
        fitDict.fail("superBlocks", controlDict.fileName() + " has no function object '" + profile +
                                        "': the time a sampling block spans is unknown");
    const Dictionary& fo = controlDict.subDict("functions").subDict(profile);
    const long interval = fo.found("sampleInterval") ? fo.getPositive<long>("sampleInterval") : 1;
    return static_cast<double>(blockSamples) * static_cast<double>(interval) * controlDict.getPositive<double>("deltaT");
}

int blocksPerSuperBlock(double length, double blockTime) {
    return std::max(1, static_cast<int>(std::nearbyint(length / blockTime)));
}

double jackknifeError(const std::vector<double>& leaveOneOut) {
    const double m = static_cast<double>(leaveOneOut.size());
    double mean = 0.0;
    for (double x : leaveOneOut) mean += x;
    mean /= m;
    double squares = 0.0;
    for (double x : leaveOneOut) squares += (x - mean) * (x - mean);
    return std::sqrt((m - 1.0) / m * squares);
}

std::vector<double> leaveOneOutVelocities(const BlockSums& b, int per, int m, int left) {
    const std::size_t rows = b.counts.empty() ? 0 : b.counts.front().size();
    const std::size_t first = b.counts.size() - static_cast<std::size_t>(per) * m;
    std::vector<double> count(rows, 0.0), sum(rows, 0.0);
    for (std::size_t k = first; k < b.counts.size(); ++k) {
        if (static_cast<int>((k - first) / per) == left) continue;
        for (std::size_t i = 0; i < rows; ++i) {
            count[i] += b.counts[k][i];
            sum[i] += b.velocitySums[k][i];
        }
    }
    std::vector<double> u(rows);
    for (std::size_t i = 0; i < rows; ++i)
        u[i] = count[i] > 0.0 ? sum[i] / count[i] : std::numeric_limits<double>::quiet_NaN();
    return u;
}

}  // namespace dpd
