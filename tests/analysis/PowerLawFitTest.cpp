// The power-law fit against exact power laws and the weighted least-squares slope's textbook variance.
#include "analysis/PowerLawFit.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace dpd {
namespace {

TEST(PowerLawFit, AnExactPowerLawGivesItsExponentAndAmplitude) {
    const std::vector<double> x{5, 10, 20, 40};
    std::vector<double> y, e;
    for (double v : x) {
        y.push_back(0.3 * std::pow(v, 1.176));
        e.push_back(0.02 * y.back());
    }
    const PowerLawFitResult r = fitPowerLaw(x, y, e);
    EXPECT_NEAR(r.exponent, 1.176, 1e-12);
    EXPECT_NEAR(r.logAmplitude, std::log(0.3), 1e-12);
    EXPECT_EQ(r.dof, 2);
    EXPECT_LT(r.chi2PerDof, 1e-20);
}

// Without scatter beyond the errors (chi^2/dof <= 1) the error is the textbook one of a weighted line:
// var(slope) = 1 / sum_i w_i (u_i - u_w)^2 with u = ln x, w = (y / err)^2 and u_w the weighted mean.
TEST(PowerLawFit, TheExponentsErrorIsTheWeightedLinesWhenThePointsScatterNoMoreThanTheirErrors) {
    const std::vector<double> x{10, 15, 20, 30, 40, 60};
    const std::vector<double> rel{0.01, 0.015, 0.01, 0.02, 0.03, 0.05};
    std::vector<double> y, e;
    for (std::size_t i = 0; i < x.size(); ++i) {
        y.push_back(std::pow(x[i], 1.2) * (1.0 + 0.3 * rel[i] * (i % 2 ? 1.0 : -1.0)));  // chi^2/dof < 1
        e.push_back(rel[i] * y.back());
    }
    double sw = 0.0, swu = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        const double w = 1.0 / (rel[i] * rel[i]);
        sw += w;
        swu += w * std::log(x[i]);
    }
    double sxx = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) sxx += std::pow(std::log(x[i]) - swu / sw, 2) / (rel[i] * rel[i]);
    const PowerLawFitResult r = fitPowerLaw(x, y, e);
    ASSERT_LT(r.chi2PerDof, 1.0);
    EXPECT_NEAR(r.exponentError, 1.0 / std::sqrt(sxx), 1e-9 / std::sqrt(sxx));
}

TEST(PowerLawFit, ScatterBeyondTheErrorsWidensTheErrorByTheSquareRootOfChi2PerDof) {
    const std::vector<double> x{10, 20, 40, 80};
    std::vector<double> y{1.0, 2.6, 5.0, 11.0}, e;
    for (double v : y) e.push_back(0.001 * v);
    const PowerLawFitResult scattered = fitPowerLaw(x, y, e);
    ASSERT_GT(scattered.chi2PerDof, 1.0);
    std::vector<double> wide;
    for (double v : e) wide.push_back(v * std::sqrt(scattered.chi2PerDof));  // errors that explain the scatter
    const PowerLawFitResult explained = fitPowerLaw(x, y, wide);
    EXPECT_NEAR(explained.chi2PerDof, 1.0, 1e-9);
    EXPECT_NEAR(scattered.exponentError, explained.exponentError, 1e-9 * explained.exponentError);
    EXPECT_NEAR(scattered.exponent, explained.exponent, 1e-12);
}

TEST(PowerLawFit, RefusesTooFewPointsAndValuesThatAreNotPositive) {
    EXPECT_THROW(fitPowerLaw({1, 2}, {1, 2}, {0.1, 0.1}), std::invalid_argument);
    EXPECT_THROW(fitPowerLaw({1, 2, 3}, {1, 2}, {0.1, 0.1, 0.1}), std::invalid_argument);
    EXPECT_THROW(fitPowerLaw({1, 2, 3}, {1, -2, 3}, {0.1, 0.1, 0.1}), std::invalid_argument);
    EXPECT_THROW(fitPowerLaw({1, 2, 3}, {1, 2, 3}, {0.1, 0.0, 0.1}), std::invalid_argument);
    EXPECT_THROW(fitPowerLaw({1, 2, 3}, {1, NAN, 3}, {0.1, 0.1, 0.1}), std::invalid_argument);
}

}  // namespace
}  // namespace dpd
