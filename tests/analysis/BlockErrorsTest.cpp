// Errors of fits to profiles whose bins fluctuate together and whose blocks are correlated in time, as
// in a DPD channel: the whole profile moves with the flow's slowest mode (a shift common to every bin)
// that outlives a block. Synthetic blocks with such noise are fitted many times; the quoted errors must
// cover the truth about 68 % of the time, and the errors computed as if bins and blocks were
// independent must be seen to fail (so that the test can tell the two apart).
#include "analysis/CorrelatedMean.hpp"
#include "analysis/CouetteFit.hpp"
#include "analysis/PoiseuilleFit.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>
#include <vector>

namespace dpd {
namespace {

// Coverage window, as in ProfileFitsTest.cpp: 400 repetitions, binomial standard deviation 0.0233 about
// 0.6827. The error estimate from m = 256 correlated blocks summed over a window of W ~ 10 lags has
// about m / (2W + 1) ~ 12 degrees of freedom, so the interval is Student-t like with coverage ~ 0.66;
// [0.60, 0.74] is -2.6 / +3.5 binomial standard deviations about that. An error bar wrong by 25 %
// (coverage 0.55 or 0.79) falls outside.
constexpr int kRepetitions = 400;
constexpr double kCoverageLow = 0.60, kCoverageHigh = 0.74;
constexpr int kBlocks = 256;
constexpr double kRho = 0.6;  // block-to-block correlation of the common shift: tau_int = (1 + rho) / (2 (1 - rho)) = 2

// One step of the AR(1) process that correlates a block with the one before (stationary deviation sd).
double nextAutoregressive(double a, double sd, std::normal_distribution<double>& normal, std::mt19937_64& rng) {
    return kRho * a + std::sqrt(1.0 - kRho * kRho) * sd * normal(rng);
}

// Per-bin mean of the blocks and the standard error of that mean with blocks taken as independent (as
// profileBins writes them).
struct BinMeans {
    std::vector<double> mean, err;
};
BinMeans binMeans(const std::vector<std::vector<double>>& blocks) {
    const std::size_t nBins = blocks.front().size();
    BinMeans r{std::vector<double>(nBins, 0.0), std::vector<double>(nBins, 0.0)};
    for (std::size_t i = 0; i < nBins; ++i) {
        double sum = 0.0, var = 0.0;
        for (const auto& b : blocks) sum += b[i];
        r.mean[i] = sum / kBlocks;
        for (const auto& b : blocks) var += (b[i] - r.mean[i]) * (b[i] - r.mean[i]);
        r.err[i] = std::sqrt(var / (kBlocks - 1) / kBlocks);
    }
    return r;
}

void expectCoverage(int hits) {
    const double f = static_cast<double>(hits) / kRepetitions;
    EXPECT_GT(f, kCoverageLow);
    EXPECT_LT(f, kCoverageHigh);
}

// Blocks of a profile u(y) on nBins bins over [yLow, yHigh]: each block is u plus a shift common to all
// bins (AR(1) from block to block, standard deviation `shift`) plus independent noise `sigma` per bin.
// Returns the mean profile with the per-bin standard errors of the block means (as profileBins writes
// them, blocks taken as independent) and the blocks.
Profile1D correlatedBlocks(const std::function<double(double)>& u, double yLow, double yHigh, int nBins, double shift,
                           double sigma, std::mt19937_64& rng) {
    std::normal_distribution<double> normal(0.0, 1.0);
    Profile1D p;
    const double dy = (yHigh - yLow) / nBins;
    for (int i = 0; i < nBins; ++i) p.y.push_back(yLow + (i + 0.5) * dy);
    double a = shift * normal(rng);
    for (int k = 0; k < kBlocks; ++k) {
        a = nextAutoregressive(a, shift, normal, rng);
        std::vector<double> block;
        for (double y : p.y) block.push_back(u(y) + a + sigma * normal(rng));
        p.blocks.push_back(block);
    }
    const BinMeans m = binMeans(p.blocks);
    p.u = m.mean;
    p.uErr = m.err;
    return p;
}

Profile1D withoutBlocks(Profile1D p) {
    p.blocks.clear();
    return p;
}

double fraction(int hits) { return static_cast<double>(hits) / kRepetitions; }

// Poiseuille channel between -5 and 5, nu 0.3, g 0.02, slip length 0.5 at both walls.
constexpr double kNu = 0.3, kG = 0.02, kH = 5.0, kBeta = 0.5;
double poiseuille(double y) { return kG / (2.0 * kNu) * (kH * kH - y * y) + kBeta * kG * kH / kNu; }

TEST(BlockErrors, CorrelatedMeanOfAnAutoregressiveSeriesCoversTheTruth) {
    // A scalar AR(1) series with mean 0: tau_int = 2 blocks; the quoted error must cover 0 ~ 68 %.
    std::mt19937_64 rng(31);
    std::normal_distribution<double> normal(0.0, 1.0);
    int hits = 0, found = 0;
    double tauSum = 0.0;
    for (int rep = 0; rep < kRepetitions; ++rep) {
        std::vector<Eigen::VectorXd> series;
        double a = normal(rng);
        for (int k = 0; k < kBlocks; ++k) {
            a = nextAutoregressive(a, 1.0, normal, rng);
            series.push_back(Eigen::VectorXd::Constant(1, a));
        }
        const CorrelatedMean c = correlatedMean(series);
        hits += std::abs(c.mean(0)) < std::sqrt(c.covariance(0, 0));
        found += c.windowFound;
        tauSum += c.maxTau;
    }
    expectCoverage(hits);
    EXPECT_EQ(found, kRepetitions);
    // tau_int from 256 values with a window ~10 scatters by ~ tau sqrt(2 (2W + 1) / m) ~ 0.8 per run,
    // 0.04 for the mean of 400; its bias (the window's tail and the mean's fluctuation) is ~ -0.1.
    EXPECT_NEAR(tauSum / kRepetitions, 2.0, 0.25);
}

TEST(BlockErrors, IndependentValuesGiveHalfABlock) {
    std::mt19937_64 rng(7);
    std::normal_distribution<double> normal(0.0, 1.0);
    std::vector<Eigen::VectorXd> series;
    for (int k = 0; k < 4096; ++k) series.push_back(Eigen::VectorXd::Constant(2, normal(rng)));
    const CorrelatedMean c = correlatedMean(series);
    // tau_int of white noise is 1/2; from 4096 values with a window of ~3 lags it scatters by
    // 0.5 sqrt(2 x 7 / 4096) = 0.03.
    EXPECT_NEAR(c.maxTau, 0.5, 0.12);
    EXPECT_TRUE(c.windowFound);
    // The variance of the mean of unit white noise is 1/m; its estimate scatters by ~ sqrt(2 x 7 / m) = 6 %.
    EXPECT_NEAR(c.covariance(0, 0) * 4096.0, 1.0, 0.25);
    EXPECT_THROW(correlatedMean(std::vector<Eigen::VectorXd>(3, Eigen::VectorXd::Zero(1))), std::invalid_argument);
}

TEST(BlockErrors, BlocksDoNotChangeTheFittedValues) {
    std::mt19937_64 rng(3);
    const Profile1D p = correlatedBlocks(poiseuille, -kH, kH, 40, 0.05, 0.05, rng);
    const PoiseuilleFitResult a = fitPoiseuille(p, kG, -kH, kH), b = fitPoiseuille(withoutBlocks(p), kG, -kH, kH);
    EXPECT_EQ(a.nu, b.nu);
    EXPECT_EQ(a.lower.slipLength, b.lower.slipLength);
    EXPECT_EQ(a.chi2PerDof, b.chi2PerDof);
    EXPECT_EQ(a.blockErrors.blocks, kBlocks);
    EXPECT_EQ(b.blockErrors.blocks, 0);
}

TEST(BlockErrors, PoiseuilleErrorsCoverTheTruthWhenTheProfileMovesAsAWhole) {
    std::mt19937_64 rng(20261124);
    int nu = 0, slipLength = 0, slipVelocity = 0, naiveSlipVelocity = 0, naiveSlipLength = 0;
    const double slipTrue = poiseuille(-kH);
    for (int rep = 0; rep < kRepetitions; ++rep) {
        // A common shift of 0.05 per block against 0.05 per bin: the shift dominates the slip velocity.
        const Profile1D p = correlatedBlocks(poiseuille, -kH, kH, 40, 0.05, 0.05, rng);
        const PoiseuilleFitResult r = fitPoiseuille(p, kG, -kH, kH);
        nu += std::abs(r.nu - kNu) < r.nuErr;
        slipLength += std::abs(r.lower.slipLength - kBeta) < r.lower.slipLengthErr;
        slipVelocity += std::abs(r.lower.slipVelocity - slipTrue) < r.lower.slipVelocityErr;
        const PoiseuilleFitResult n = fitPoiseuille(withoutBlocks(p), kG, -kH, kH);
        naiveSlipVelocity += std::abs(n.lower.slipVelocity - slipTrue) < n.lower.slipVelocityErr;
        naiveSlipLength += std::abs(n.lower.slipLength - kBeta) < n.lower.slipLengthErr;
    }
    for (int hits : {nu, slipLength, slipVelocity}) expectCoverage(hits);
    // Bins and blocks taken as independent: the common shift averages as if it were 40 x 2 tau_int
    // independent values, errors several times too small (coverage ~ 0.2).
    EXPECT_LT(fraction(naiveSlipVelocity), 0.45);
    EXPECT_LT(fraction(naiveSlipLength), 0.45);
}

TEST(BlockErrors, CouetteErrorsCoverTheTruthWhenTheProfileMovesAsAWhole) {
    // Walls at -5 and 5 sliding at -1 and +1, slip length 0.7: u = y / 5.7.
    const auto couette = [](double y) { return y / 5.7; };
    std::mt19937_64 rng(11);
    int slip = 0, shear = 0, naive = 0;
    for (int rep = 0; rep < kRepetitions; ++rep) {
        const Profile1D p = correlatedBlocks(couette, -5.0, 5.0, 40, 0.02, 0.02, rng);
        const CouetteFitResult r = fitCouette(p, -5.0, 5.0, -4.0, 4.0, -1.0, 1.0);
        slip += std::abs(r.lower.slipVelocity - (couette(-5.0) + 1.0)) < r.lower.slipVelocityErr;
        shear += std::abs(r.shearRate - 1.0 / 5.7) < r.shearRateErr;
        const CouetteFitResult n = fitCouette(withoutBlocks(p), -5.0, 5.0, -4.0, 4.0, -1.0, 1.0);
        naive += std::abs(n.lower.slipVelocity - (couette(-5.0) + 1.0)) < n.lower.slipVelocityErr;
    }
    for (int hits : {slip, shear}) expectCoverage(hits);
    EXPECT_LT(fraction(naive), 0.45);
}

TEST(BlockErrors, AnticorrelatedBlocksKeepThePlainError) {
    std::vector<Eigen::VectorXd> series;
    for (int k = 0; k < 64; ++k) series.push_back(Eigen::VectorXd::Constant(1, k % 2 == 0 ? 1.0 : -1.0));
    const CorrelatedMean c = correlatedMean(series);
    EXPECT_EQ(c.window, 0);
    // Gamma_0 = 1, times the bias factor 1 + 1/64, over 64 values.
    EXPECT_NEAR(c.covariance(0, 0), (1.0 + 1.0 / 64.0) / 64.0, 1e-12);
}

TEST(BlockErrors, ReversePoiseuilleErrorsCoverTheTruthWhenTheProfileMovesAsAWhole) {
    // Box [0, 20), nu 0.3, g 0.05, +g on the first half. The common shift moves both halves; a mode
    // shaped like the profile itself (its amplitude AR(1) from block to block) moves the curvature.
    const double L = 20.0, nu = 0.3, g = 0.05;
    const auto shape = [&](double y) {
        const double h = 0.5 * L;
        return y < h ? g / (2 * nu) * y * (h - y) : -g / (2 * nu) * (y - h) * (L - y);
    };
    std::mt19937_64 rng(5);
    std::normal_distribution<double> normal(0.0, 1.0);
    int hits = 0, naive = 0;
    for (int rep = 0; rep < kRepetitions; ++rep) {
        Profile1D p = correlatedBlocks(shape, 0.0, L, 40, 0.05, 0.05, rng);
        double a = 0.0;
        for (auto& block : p.blocks) {  // the curvature mode: 2 % of the profile per block, correlated
            a = nextAutoregressive(a, 0.02, normal, rng);
            for (std::size_t i = 0; i < block.size(); ++i) block[i] += a * shape(p.y[i]);
        }
        const BinMeans m = binMeans(p.blocks);
        p.u = m.mean;
        p.uErr = m.err;
        const ReversePoiseuilleResult r = fitReversePoiseuille(p, g, 0.0, L, 1.0);
        hits += std::abs(r.nu - nu) < r.nuErr;
        const ReversePoiseuilleResult n = fitReversePoiseuille(withoutBlocks(p), g, 0.0, L, 1.0);
        naive += std::abs(n.nu - nu) < n.nuErr;
    }
    expectCoverage(hits);
    EXPECT_LT(fraction(naive), 0.45);
}

TEST(BlockErrors, CouetteStressViscosityCoversTheTruthWhenTheStressMovesAsAWhole) {
    // Walls at -5 and 5 sliding at -+1, slip 0.7, eta 1.1: the stress of each block is eta times the
    // shear rate plus a shift common to every bin (AR(1) from block to block) and noise per bin.
    const double eta = 1.1, shear = 1.0 / 5.7;
    const auto couette = [&](double y) { return shear * y; };
    std::mt19937_64 rng(18);
    std::normal_distribution<double> normal(0.0, 1.0);
    int hits = 0, naive = 0;
    for (int rep = 0; rep < kRepetitions; ++rep) {
        const Profile1D p = correlatedBlocks(couette, -5.0, 5.0, 40, 0.02, 0.02, rng);
        std::vector<std::vector<double>> sigmaBlocks;
        double a = 0.0;
        for (int k = 0; k < kBlocks; ++k) {
            a = nextAutoregressive(a, 0.01, normal, rng);
            std::vector<double> s;
            for (std::size_t i = 0; i < p.y.size(); ++i) s.push_back(eta * shear + a + 0.01 * normal(rng));
            sigmaBlocks.push_back(s);
        }
        const BinMeans sigma = binMeans(sigmaBlocks);
        const CouetteFitResult fit = fitCouette(p, -5.0, 5.0, -4.0, 4.0, -1.0, 1.0);
        const StressViscosity v = viscosityFromStress(p.y, sigma.mean, sigma.err, fit, 1.0, sigmaBlocks);
        hits += std::abs(v.eta - eta) < v.etaErr;
        const CouetteFitResult fitNaive = fitCouette(withoutBlocks(p), -5.0, 5.0, -4.0, 4.0, -1.0, 1.0);
        const StressViscosity n = viscosityFromStress(p.y, sigma.mean, sigma.err, fitNaive, 1.0);
        naive += std::abs(n.eta - eta) < n.etaErr;
    }
    expectCoverage(hits);
    EXPECT_LT(fraction(naive), 0.45);
}

}  // namespace
}  // namespace dpd
