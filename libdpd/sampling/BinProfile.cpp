#include "sampling/BinProfile.hpp"
#include "sampling/BlockStatistics.hpp"

#include <cmath>

namespace dpd {

namespace {

// What one bin says over a set of sums: density, velocity, temperature.
struct BinEstimate {
    double density = 0.0, ux = 0.0, uy = 0.0, uz = 0.0, kT = 0.0;
    bool valid = false;
};

BinEstimate estimate(const BinSums& b, long samples, double binMeasure, int dimension) {
    BinEstimate e;
    const double n = b.s[0];
    e.density = samples > 0 ? n / (samples * binMeasure) : 0.0;
    if (n < 3) return e;
    e.ux = b.s[1] / n; e.uy = b.s[2] / n; e.uz = b.s[3] / n;
    const double meanX = b.s[7] / n;
    const double varX = b.s[8] / n - meanX * meanX;
    // Per component: the variance of v about a line in x (the local shear removed).
    double sum = 0.0;
    for (int c = 0; c < 3; ++c) {
        if (dimension == 2 && c == 1) continue;
        const double meanV = b.s[1 + c] / n;
        const double varV = b.s[4 + c] / n - meanV * meanV;
        const double covVX = b.s[9 + c] / n - meanV * meanX;
        sum += varX > 0.0 ? varV - covVX * covVX / varX : varV;
    }
    e.kT = sum / dimension;
    e.valid = true;
    return e;
}

}  // namespace

BinProfile computeProfile(const BinAccumulator& acc, double crossSection, int dimension) {
    const BinLayout& L = acc.layout();
    const double binMeasure = L.width() * crossSection;
    BinProfile out;
    out.samples = acc.samples();
    // Error bars from complete blocks only: a partial block has a different variance.
    std::vector<std::size_t> complete;
    for (std::size_t k = 0; k < acc.blocks().size(); ++k)
        if (acc.samplesPerBlock()[k] == acc.blockSamples()) complete.push_back(k);
    out.blocksForErrors = complete.size() >= 2 ? static_cast<int>(complete.size()) : 0;
    for (int b = 0; b < L.nBins; ++b) {
        BinSums total;
        for (const auto& block : acc.blocks())
            for (int f = 0; f < BinSums::kFields; ++f) total.s[f] += block[b].s[f];
        const BinEstimate e = estimate(total, acc.samples(), binMeasure, dimension);
        std::vector<double> rho, ux, uy, uz, kT;
        if (out.blocksForErrors > 0)
            for (std::size_t k : complete) {
                const BinEstimate ek = estimate(acc.blocks()[k][b], acc.samplesPerBlock()[k], binMeasure, dimension);
                rho.push_back(ek.density);
                if (!ek.valid) continue;
                ux.push_back(ek.ux); uy.push_back(ek.uy); uz.push_back(ek.uz); kT.push_back(ek.kT);
            }
        out.centre.push_back(L.centre(b));
        out.count.push_back(total.s[0]);
        out.density.push_back(e.density);
        out.densityErr.push_back(standardErrorOfMean(rho));
        out.ux.push_back(e.ux); out.uy.push_back(e.uy); out.uz.push_back(e.uz);
        out.uxErr.push_back(standardErrorOfMean(ux)); out.uyErr.push_back(standardErrorOfMean(uy)); out.uzErr.push_back(standardErrorOfMean(uz));
        out.kT.push_back(e.kT);
        out.kTErr.push_back(standardErrorOfMean(kT));
    }
    return out;
}

}  // namespace dpd
