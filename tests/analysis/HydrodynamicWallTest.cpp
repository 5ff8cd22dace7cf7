// The hydrodynamic wall from Couette and Poiseuille together (analysis/HydrodynamicWall.*): apparent
// slip lengths made from a known wall position h and known slip lengths b (one of them negative, one
// zero), exactly and with Gaussian noise. Without noise the fit gives h and every b back to rounding;
// with noise the estimates scatter as the quoted errors say and the errors cover the truth.
#include "analysis/HydrodynamicWall.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

namespace dpd {
namespace {

constexpr double kWidth = 10.0;       // geometric width H
constexpr double kHalfWidth = 4.7;    // the wall acts 0.3 inside each geometric plane
const std::vector<double> kSlip = {2.0, 1.0, 0.4, 0.0, -0.1};

// What fits against the geometric planes give: Couette reaches the wall speed at h + b = H/2 + beta_c,
// the Poiseuille parabola's zero squared is h^2 + 2 b h = (H/2)^2 + H beta_p.
std::vector<ApparentSlip> apparent(double sigmaCouette, double sigmaPoiseuille, std::mt19937_64* rng = nullptr) {
    std::normal_distribution<double> normal(0.0, 1.0);
    std::vector<ApparentSlip> out;
    for (double b : kSlip) {
        ApparentSlip s;
        s.couette = kHalfWidth + b - 0.5 * kWidth + (rng ? sigmaCouette * normal(*rng) : 0.0);
        s.poiseuille = (kHalfWidth * kHalfWidth + 2.0 * b * kHalfWidth - 0.25 * kWidth * kWidth) / kWidth +
                       (rng ? sigmaPoiseuille * normal(*rng) : 0.0);
        s.couetteErr = sigmaCouette;
        s.poiseuilleErr = sigmaPoiseuille;
        out.push_back(s);
    }
    return out;
}

TEST(HydrodynamicWall, ExactDataGiveTheWallAndEverySlipLengthBack) {
    const HydrodynamicWallFit fit = fitHydrodynamicWall(kWidth, apparent(0.01, 0.01));
    EXPECT_NEAR(fit.halfWidth, kHalfWidth, 1e-9);
    EXPECT_NEAR(fit.offset, 0.3, 1e-9);
    EXPECT_LT(fit.chi2PerDof, 1e-12);
    EXPECT_EQ(fit.dof, 4);
    ASSERT_EQ(fit.slipLength.size(), kSlip.size());
    for (std::size_t i = 0; i < kSlip.size(); ++i) EXPECT_NEAR(fit.slipLength[i], kSlip[i], 1e-9) << "setting " << i;
    // The apparent (geometric-plane) Couette slip is b - 0.3: the fit moves every setting by the offset.
    EXPECT_GT(fit.halfWidthErr, 0.0);
}

TEST(HydrodynamicWall, EstimatesScatterAsTheirErrorsSayAndTheErrorsCoverTheTruth) {
    // 2000 noisy sweeps: the scatter of h and of the largest slip length against the mean quoted error
    // before its chi^2 scaling (the scatter's own relative error is 1/sqrt(2 x 2000) = 1.6 %, so a
    // bound of 8 % is five of those); with the scaling (up only) the errors cover the truth at least
    // as often as one standard error should (68.3 %, less 3 binomial errors: 65.2 %).
    std::mt19937_64 rng(20261125);
    const int n = 2000;
    double sumH = 0.0, sumH2 = 0.0, sumErrH = 0.0, sumB = 0.0, sumB2 = 0.0, sumErrB = 0.0;
    int coveredH = 0, coveredB = 0;
    for (int k = 0; k < n; ++k) {
        const HydrodynamicWallFit fit = fitHydrodynamicWall(kWidth, apparent(0.02, 0.03, &rng));
        const double unscale = 1.0 / std::sqrt(std::max(1.0, fit.chi2PerDof));
        sumH += fit.halfWidth;
        sumH2 += fit.halfWidth * fit.halfWidth;
        sumErrH += fit.halfWidthErr * unscale;
        sumB += fit.slipLength[0];
        sumB2 += fit.slipLength[0] * fit.slipLength[0];
        sumErrB += fit.slipLengthErr[0] * unscale;
        coveredH += std::abs(fit.halfWidth - kHalfWidth) <= fit.halfWidthErr;
        coveredB += std::abs(fit.slipLength[0] - kSlip[0]) <= fit.slipLengthErr[0];
    }
    const double meanH = sumH / n, sdH = std::sqrt(sumH2 / n - meanH * meanH);
    const double meanB = sumB / n, sdB = std::sqrt(sumB2 / n - meanB * meanB);
    EXPECT_NEAR(meanH, kHalfWidth, 4.0 * sdH / std::sqrt(n));
    EXPECT_NEAR(meanB, kSlip[0], 4.0 * sdB / std::sqrt(n));
    EXPECT_NEAR(sdH / (sumErrH / n), 1.0, 0.08) << "scatter of h " << sdH << ", quoted " << sumErrH / n;
    EXPECT_NEAR(sdB / (sumErrB / n), 1.0, 0.08) << "scatter of b " << sdB << ", quoted " << sumErrB / n;
    EXPECT_GE(coveredH, static_cast<int>(0.652 * n));
    EXPECT_GE(coveredB, static_cast<int>(0.652 * n));
}

TEST(HydrodynamicWall, RefusesWhatCannotPlaceTheWall) {
    std::vector<ApparentSlip> one = apparent(0.01, 0.01);
    one.resize(1);
    EXPECT_THROW(fitHydrodynamicWall(kWidth, one), std::invalid_argument);
    std::vector<ApparentSlip> same = apparent(0.01, 0.01);
    for (ApparentSlip& s : same) s = same[0];  // one slip length: B = 2hA - h^2 has no slope to give h
    EXPECT_THROW(fitHydrodynamicWall(kWidth, same), std::invalid_argument);
    std::vector<ApparentSlip> noError = apparent(0.01, 0.01);
    noError[2].poiseuilleErr = 0.0;
    EXPECT_THROW(fitHydrodynamicWall(kWidth, noError), std::invalid_argument);
    EXPECT_THROW(fitHydrodynamicWall(0.0, apparent(0.01, 0.01)), std::invalid_argument);
}

}  // namespace
}  // namespace dpd
