#include "sampling/BinProfile.hpp"

#include "core/Axis.hpp"
#include "sampling/BlockStatistics.hpp"
#include "sampling/UsableBin.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace dpd {

namespace {

// What one bin says over a set of sums: density, velocity, temperature (and stress, when sampled).
struct BinEstimate {
    double density = 0.0, ux = 0.0, uy = 0.0, uz = 0.0, kT = 0.0;
    bool valid = false;
    StressPoint stress;
};

// The stress of the bin: the kinetic tensor rho cov(v_a, v_b) (cov about a mean velocity varying
// linearly across the bin, as for kT) plus the virial W_ab / (samples x volume); sigma = -P.
StressPoint stressEstimate(const BinSums& b, long samples, double binMeasure, int dimension, int flowAxis, int binAxis) {
    StressPoint s;
    if (samples <= 0) return s;
    const double volume = samples * binMeasure;
    const double n = b.s[0];
    const auto kinetic = [&](int a, int c) {
        if (!usableBin(n)) return 0.0;
        const double meanX = b.s[7] / n, varX = b.s[8] / n - meanX * meanX;
        const double va = b.s[1 + a] / n, vc = b.s[1 + c] / n;
        const double second = a == c ? b.s[4 + a] : b.s[BinSums::kCross + tensorIndex(a, c) - 3];
        const double cov = second / n - va * vc;
        const double covA = b.s[9 + a] / n - va * meanX, covC = b.s[9 + c] / n - vc * meanX;
        return (n / volume) * (varX > 0.0 ? cov - covA * covC / varX : cov);
    };
    const auto virial = [&](int a, int c) { return b.s[BinSums::kVirial + tensorIndex(a, c)] / volume; };
    s.shearKinetic = -kinetic(flowAxis, binAxis);
    s.shearVirial = -virial(flowAxis, binAxis);
    s.shear = s.shearKinetic + s.shearVirial;
    double trace = 0.0;
    for (int a = 0; a < 3; ++a)
        if (dimension == 3 || a != 1) trace += kinetic(a, a) + virial(a, a);
    s.pressure = trace / dimension;
    return s;
}

BinEstimate estimate(const BinSums& b, long samples, double binMeasure, int dimension) {
    BinEstimate e;
    const double n = b.s[0];
    e.density = samples > 0 ? n / (samples * binMeasure) : 0.0;
    if (!usableBin(n)) return e;
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

// The stress of bin b over all samples, with errors from the spread over the complete blocks.
StressPoint stressProfilePoint(const BinAccumulator& acc, int b, const std::vector<std::size_t>& complete, bool errors,
                               const BinSums& total, double binMeasure, int dimension, int flowAxis) {
    const int axis = acc.layout().axis;
    StressPoint s = stressEstimate(total, acc.samples(), binMeasure, dimension, flowAxis, axis);
    if (!errors) return s;
    std::vector<double> shear, kinetic, virial, pressure;
    for (std::size_t k : complete) {
        const StressPoint e =
            stressEstimate(acc.blocks()[k][b], acc.samplesPerBlock()[k], binMeasure, dimension, flowAxis, axis);
        shear.push_back(e.shear);
        kinetic.push_back(e.shearKinetic);
        virial.push_back(e.shearVirial);
        pressure.push_back(e.pressure);
    }
    s.shearErr = standardErrorOfMean(shear);
    s.shearKineticErr = standardErrorOfMean(kinetic);
    s.shearVirialErr = standardErrorOfMean(virial);
    s.pressureErr = standardErrorOfMean(pressure);
    return s;
}

// The blocks that ran their full length: a partial block has a different variance.
std::vector<std::size_t> completeBlocks(const BinAccumulator& acc) {
    std::vector<std::size_t> complete;
    for (std::size_t k = 0; k < acc.blocks().size(); ++k)
        if (acc.samplesPerBlock()[k] == acc.blockSamples()) complete.push_back(k);
    return complete;
}

}  // namespace

std::string shearStressName(int flowAxis, int binAxis) {
    return std::string("sigma") + axisLetter(std::min(flowAxis, binAxis)) + axisLetter(std::max(flowAxis, binAxis));
}

BinProfile computeProfile(const BinAccumulator& acc, double crossSection, int dimension) {
    const BinLayout& L = acc.layout();
    const double binMeasure = L.width() * L.width2() * crossSection;
    const int flowAxis = acc.stressFlowAxis();
    BinProfile out;
    out.samples = acc.samples();
    out.hasStress = flowAxis >= 0;
    if (out.hasStress) out.stressName = shearStressName(flowAxis, L.axis);
    const std::vector<std::size_t> complete = completeBlocks(acc);
    out.blocksForErrors = complete.size() >= 2 ? static_cast<int>(complete.size()) : 0;
    for (int b = 0; b < L.binCount(); ++b) {
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
        out.centre.push_back(L.centre(b % L.nBins));
        if (L.twoAxes()) out.centre2.push_back(L.centre2(b / L.nBins));
        out.count.push_back(total.s[0]);
        out.density.push_back(e.density);
        out.densityErr.push_back(standardErrorOfMean(rho));
        out.ux.push_back(e.ux); out.uy.push_back(e.uy); out.uz.push_back(e.uz);
        out.uxErr.push_back(standardErrorOfMean(ux)); out.uyErr.push_back(standardErrorOfMean(uy)); out.uzErr.push_back(standardErrorOfMean(uz));
        out.kT.push_back(e.kT);
        out.kTErr.push_back(standardErrorOfMean(kT));
        if (out.hasStress) out.stress.push_back(stressProfilePoint(acc, b, complete, out.blocksForErrors > 0, total,
                                                                   binMeasure, dimension, flowAxis));
    }
    return out;
}

std::vector<std::vector<double>> blockVelocities(const BinAccumulator& acc, int component) {
    std::vector<std::vector<double>> blocks;
    for (std::size_t k : completeBlocks(acc)) {
        std::vector<double> u;
        for (const BinSums& b : acc.blocks()[k])
            u.push_back(usableBin(b.s[0]) ? b.s[1 + component] / b.s[0] : std::numeric_limits<double>::quiet_NaN());
        blocks.push_back(std::move(u));
    }
    return blocks;
}

BlockVelocitySums blockVelocitySums(const BinAccumulator& acc, int component) {
    BlockVelocitySums b;
    for (std::size_t k : completeBlocks(acc)) {
        std::vector<double> count, sum;
        for (const BinSums& bin : acc.blocks()[k]) {
            count.push_back(bin.s[0]);
            sum.push_back(bin.s[1 + component]);
        }
        b.counts.push_back(std::move(count));
        b.velocitySums.push_back(std::move(sum));
    }
    return b;
}

std::vector<std::vector<double>> blockShearStress(const BinAccumulator& acc, double crossSection, int dimension) {
    const BinLayout& L = acc.layout();
    const double binMeasure = L.width() * L.width2() * crossSection;
    std::vector<std::vector<double>> blocks;
    for (std::size_t k : completeBlocks(acc)) {
        std::vector<double> sigma;
        for (const BinSums& b : acc.blocks()[k])
            sigma.push_back(
                stressEstimate(b, acc.samplesPerBlock()[k], binMeasure, dimension, acc.stressFlowAxis(), L.axis).shear);
        blocks.push_back(std::move(sigma));
    }
    return blocks;
}

}  // namespace dpd
