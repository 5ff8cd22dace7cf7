#include "core/Axis.hpp"
#include "sampling/BlockStatistics.hpp"
#include "sampling/ChainStatistics.hpp"

#include <cstdio>
#include <string>

namespace dpd {

namespace {

template <class... Values>
std::string line(const char* format, Values... values) {
    char buffer[256];
    std::snprintf(buffer, sizeof buffer, format, values...);
    return buffer;
}

// Mean of one column and its standard error from the complete blocks (0 with fewer than two).
std::pair<double, double> meanAndError(const std::vector<ChainSample>& samples, long perBlock, double ChainSample::*column) {
    double mean = 0.0;
    for (const ChainSample& s : samples) mean += s.*column;
    mean /= static_cast<double>(samples.size());
    std::vector<double> blocks;
    for (std::size_t start = 0; start + perBlock <= samples.size(); start += perBlock) {
        double m = 0.0;
        for (long k = 0; k < perBlock; ++k) m += samples[start + k].*column;
        blocks.push_back(m / static_cast<double>(perBlock));
    }
    return {mean, standardErrorOfMean(blocks)};
}

}  // namespace

std::string chainStatisticsTable(const std::vector<ChainSample>& samples, long samplesPerBlock, int flowAxis) {
    std::string t = "# chainStatistics: means over the chains at each sample; e = the flow axis " + std::string(axisLetter(flowAxis)) + "\n";
    t += line("# samples %zu, blocks of %ld samples for the errors (%zu complete)\n", samples.size(), samplesPerBlock,
              samples.size() / static_cast<std::size_t>(samplesPerBlock));
    const std::pair<const char*, double ChainSample::*> columns[] = {
        {"Rg2", &ChainSample::gyration2}, {"Ree2", &ChainSample::endToEnd2}, {"Ree_e", &ChainSample::endToEndFlow},
        {"Ree_e2", &ChainSample::endToEndFlow2}, {"span_e", &ChainSample::span}};
    for (const auto& [name, column] : columns) {
        const auto [mean, error] = meanAndError(samples, samplesPerBlock, column);
        t += line("# mean %-7s %.8g +- %.3g\n", name, mean, error);
    }
    t += "# time Rg2 Ree2 Ree_e Ree_e2 span_e\n";
    for (const ChainSample& s : samples)
        t += line("%.10g %.10g %.10g %.10g %.10g %.10g\n", s.time, s.gyration2, s.endToEnd2, s.endToEndFlow, s.endToEndFlow2, s.span);
    return t;
}

std::string chainBinsTable(const ChainBinSums& bins, int axis, double lo, double hi, int flowAxis) {
    const std::size_t n = bins.count.size();
    std::string t = "# chainBins: chains by where their centre lies along " + std::string(axisLetter(axis)) +
                    "; e = the flow axis " + std::string(axisLetter(flowAxis)) + "\n";
    t += "# centre chainSamples Rg2 span_e Ree_e2\n";
    for (std::size_t k = 0; k < n; ++k) {
        const double c = bins.count[k];
        const double centre = lo + (hi - lo) * (k + 0.5) / static_cast<double>(n);
        if (c > 0) t += line("%.8g %.0f %.8g %.8g %.8g\n", centre, c, bins.gyration2[k] / c, bins.span[k] / c, bins.endToEndFlow2[k] / c);
        else t += line("%.8g 0 nan nan nan\n", centre);
    }
    return t;
}

}  // namespace dpd
