// Tests of the weighted polynomial fit and of the Poiseuille / reverse-Poiseuille viscosity and slip fits.
// Profiles are generated from the analytic solutions with known nu and slip lengths; without noise the fit
// must recover them to rounding, with noise the quoted errors must cover the truth about 68% of the time.
#include "analysis/PoiseuilleFit.hpp"
#include "analysis/WeightedPolyFit.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

namespace dpd {
namespace {

constexpr double kExact = 1e-10;  // relative tolerance for noise-free data

void expectRelNear(double actual, double expected, double rel = kExact) {
    EXPECT_NEAR(actual, expected, rel * std::abs(expected)) << "expected " << expected;
}

// ---------------------------------------------------------------------------------------------------------
// Coverage bound used by all statistical tests. With N = 400 independent repetitions and a true coverage
// p = 0.6827 (one Gaussian standard deviation), the observed fraction is binomial with standard deviation
// sqrt(p (1 - p) / N) = sqrt(0.2166 / 400) = 0.0233. The window [0.62, 0.74] is -2.7 / +2.5 of those
// standard deviations, so a correct error estimate fails it with probability below 2%, while an error bar
// wrong by 20% (coverage 0.58 or 0.77) lands outside it. The fitted covariance is scaled by the reduced
// chi^2, which turns the interval into a Student-t one; with ~37 degrees of freedom its coverage is 0.676,
// well inside the window. The generators are seeded, so the tests are deterministic.
constexpr int kRepetitions = 400;
constexpr double kCoverageLow = 0.62;
constexpr double kCoverageHigh = 0.74;

// ---------------------------------------------------------------------------------------------------------
// Plane Poiseuille channels with Navier slip.

struct Channel {
    double yLow, yHigh;
    double nu, g;
    double betaLow = 0.0, betaHigh = 0.0;  // slip lengths
    double uLow = 0.0, uHigh = 0.0;        // wall velocities
};

// Coefficients of the exact profile: c2 = -g/(2 nu), and c0, c1 from the two Navier conditions
//   u(yL) - UL =  betaL u'(yL)   ->  c0 + c1 (yL - betaL) = UL - c2 yL^2 + 2 betaL c2 yL
//   u(yH) - UH = -betaH u'(yH)   ->  c0 + c1 (yH + betaH) = UH - c2 yH^2 - 2 betaH c2 yH
struct Parabola {
    double c0, c1, c2;
    double operator()(double y) const { return c0 + c1 * y + c2 * y * y; }
    double slope(double y) const { return c1 + 2.0 * c2 * y; }
};

Parabola exactProfile(const Channel& ch) {
    Parabola p{};
    p.c2 = -ch.g / (2.0 * ch.nu);
    const double rhsLow = ch.uLow - p.c2 * ch.yLow * ch.yLow + 2.0 * ch.betaLow * p.c2 * ch.yLow;
    const double rhsHigh = ch.uHigh - p.c2 * ch.yHigh * ch.yHigh - 2.0 * ch.betaHigh * p.c2 * ch.yHigh;
    p.c1 = (rhsHigh - rhsLow) / ((ch.yHigh + ch.betaHigh) - (ch.yLow - ch.betaLow));
    p.c0 = rhsLow - p.c1 * (ch.yLow - ch.betaLow);
    return p;
}

// Bin centres across the channel, with per-bin errors that vary (so the weighting matters) and, when an
// rng is given, Gaussian noise of exactly that size.
Profile1D sampleProfile(const std::function<double(double)>& u, double yLow, double yHigh, int nBins,
                        double sigma, std::mt19937_64* rng = nullptr) {
    Profile1D p;
    const double dy = (yHigh - yLow) / nBins;
    std::normal_distribution<double> normal(0.0, 1.0);
    for (int i = 0; i < nBins; ++i) {
        const double y = yLow + (i + 0.5) * dy;
        const double err = sigma * (1.0 + 0.5 * std::sin(0.7 * i));
        p.y.push_back(y);
        p.u.push_back(u(y) + (rng ? err * normal(*rng) : 0.0));
        p.uErr.push_back(err);
    }
    return p;
}

Profile1D channelProfile(const Channel& ch, int nBins, double sigma = 0.01, std::mt19937_64* rng = nullptr) {
    return sampleProfile(exactProfile(ch), ch.yLow, ch.yHigh, nBins, sigma, rng);
}

PoiseuilleFitResult fitChannel(const Profile1D& p, const Channel& ch, double exclude = 0.0) {
    return fitPoiseuille(p, ch.g, ch.yLow, ch.yHigh, exclude, ch.uLow, ch.uHigh);
}

void expectExactRecovery(const Channel& ch, int nBins = 30) {
    const PoiseuilleFitResult r = fitChannel(channelProfile(ch, nBins), ch);
    const Parabola exact = exactProfile(ch);
    expectRelNear(r.nu, ch.nu);
    expectRelNear(r.lower.slipLength, ch.betaLow);
    expectRelNear(r.upper.slipLength, ch.betaHigh);
    expectRelNear(r.lower.slipVelocity, exact(ch.yLow) - ch.uLow);
    expectRelNear(r.upper.slipVelocity, exact(ch.yHigh) - ch.uHigh);
    expectRelNear(r.lower.shearRate, exact.slope(ch.yLow));
    expectRelNear(r.upper.shearRate, -exact.slope(ch.yHigh));
    // The centre may be 0 (symmetric slip in a centred channel): compare on the scale of the channel.
    EXPECT_NEAR(r.centre, -exact.c1 / (2.0 * exact.c2), kExact * (ch.yHigh - ch.yLow));
    expectRelNear(r.maxVelocity, exact(-exact.c1 / (2.0 * exact.c2)));
    EXPECT_EQ(r.dof, nBins - 3);
    EXPECT_EQ(r.lower.position, ch.yLow);
    EXPECT_EQ(r.upper.position, ch.yHigh);
}

// ---------------------------------------------------------------------------------------------------------
// Weighted polynomial fit

TEST(ProfileFitPolynomial, RecoversCubicExactlyInOriginalVariable) {
    std::vector<double> x, y, err;
    for (int i = 0; i < 12; ++i) {
        x.push_back(3.0 + 0.7 * i);
        y.push_back(1.5 - 2.0 * x.back() + 0.25 * std::pow(x.back(), 2) - 0.03 * std::pow(x.back(), 3));
        err.push_back(0.1 + 0.02 * i);
    }
    const PolyFitResult r = fitPolynomial(x, y, err, 3);
    ASSERT_EQ(r.coefficients.size(), 4);
    expectRelNear(r.coefficients(0), 1.5);
    expectRelNear(r.coefficients(1), -2.0);
    expectRelNear(r.coefficients(2), 0.25);
    expectRelNear(r.coefficients(3), -0.03);
    EXPECT_EQ(r.dof, 8);
    EXPECT_LT(r.chi2, 1e-20);
    expectRelNear(r.evaluate(5.0), 1.5 - 10.0 + 6.25 - 3.75);
}

// Far from x = 0 the monomial basis is badly conditioned; the internal centring must keep the fit accurate.
TEST(ProfileFitPolynomial, AccurateFarFromOrigin) {
    std::vector<double> x, y;
    const auto f = [](double v) { return 1.0 + 2.0 * (v - 1005.0) - 0.5 * (v - 1005.0) * (v - 1005.0); };
    for (int i = 0; i <= 20; ++i) {
        x.push_back(1000.0 + 0.5 * i);
        y.push_back(f(x.back()));
    }
    const PolyFitResult r = fitPolynomial(x, y, {}, 2);
    expectRelNear(r.coefficients(2), -0.5, 1e-9);
    for (double v : {1000.0, 1003.3, 1010.0}) EXPECT_NEAR(r.evaluate(v), f(v), 1e-6);
}

// Straight line, errors taken as absolute: compare with the textbook closed form
//   S = sum w, Sx = sum w x, Sxx = sum w x^2, D = S Sxx - Sx^2,
//   var(c0) = Sxx / D, var(c1) = S / D, cov(c0, c1) = -Sx / D.
TEST(ProfileFitPolynomial, LineCovarianceMatchesClosedForm) {
    const std::vector<double> x{1.0, 2.0, 4.0, 5.0, 7.5};
    const std::vector<double> y{2.1, 2.9, 5.2, 5.8, 8.9};
    const std::vector<double> err{0.1, 0.2, 0.15, 0.3, 0.25};
    double s = 0, sx = 0, sxx = 0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        const double w = 1.0 / (err[i] * err[i]);
        s += w;
        sx += w * x[i];
        sxx += w * x[i] * x[i];
    }
    const double d = s * sxx - sx * sx;

    const PolyFitResult absolute = fitPolynomial(x, y, err, 1, false);
    EXPECT_FALSE(absolute.covarianceScaled);
    expectRelNear(absolute.covariance(0, 0), sxx / d, 1e-12);
    expectRelNear(absolute.covariance(1, 1), s / d, 1e-12);
    expectRelNear(absolute.covariance(0, 1), -sx / d, 1e-12);
    expectRelNear(absolute.covariance(1, 0), -sx / d, 1e-12);

    // chi^2 from the residuals, and the default covariance is the absolute one times chi2/dof.
    double chi2 = 0;
    for (std::size_t i = 0; i < x.size(); ++i) chi2 += std::pow((y[i] - absolute.evaluate(x[i])) / err[i], 2);
    expectRelNear(absolute.chi2, chi2, 1e-12);
    const PolyFitResult scaled = fitPolynomial(x, y, err, 1);
    EXPECT_TRUE(scaled.covarianceScaled);
    EXPECT_EQ(scaled.dof, 3);
    expectRelNear(scaled.reducedChi2(), chi2 / 3.0, 1e-12);
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j)
            expectRelNear(scaled.covariance(i, j), absolute.covariance(i, j) * chi2 / 3.0, 1e-12);
}

TEST(ProfileFitPolynomial, ZeroOrMissingErrorsMeanUnitWeights) {
    const std::vector<double> x{0.0, 1.0, 2.0, 3.0, 4.0};
    const std::vector<double> y{1.0, 2.5, 2.9, 4.2, 5.1};
    const PolyFitResult none = fitPolynomial(x, y, {}, 1);
    const PolyFitResult zeros = fitPolynomial(x, y, std::vector<double>(5, 0.0), 1);
    const PolyFitResult equal = fitPolynomial(x, y, std::vector<double>(5, 0.3), 1);
    EXPECT_TRUE(none.unitWeights);
    EXPECT_TRUE(zeros.unitWeights);
    EXPECT_FALSE(equal.unitWeights);
    for (int k = 0; k < 2; ++k) {
        expectRelNear(zeros.coefficients(k), none.coefficients(k), 1e-12);
        expectRelNear(equal.coefficients(k), none.coefficients(k), 1e-12);
        // Scaled by the reduced chi^2 the covariance does not depend on a common error size.
        expectRelNear(equal.covariance(k, k), none.covariance(k, k), 1e-12);
    }
}

TEST(ProfileFitPolynomial, RejectsInvalidInput) {
    const std::vector<double> x{0.0, 1.0, 2.0, 3.0};
    const std::vector<double> y{1.0, 2.0, 2.5, 4.0};
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(fitPolynomial(x, y, {0.1, -0.1, 0.1, 0.1}, 1), std::invalid_argument);
    EXPECT_THROW(fitPolynomial(x, y, {0.1, nan, 0.1, 0.1}, 1), std::invalid_argument);
    EXPECT_THROW(fitPolynomial(x, y, {0.1, 0.0, 0.1, 0.1}, 1), std::invalid_argument);  // zero among positive
    EXPECT_THROW(fitPolynomial(x, y, {0.1, 0.1}, 1), std::invalid_argument);
    EXPECT_THROW(fitPolynomial(x, {1.0, 2.0}, {}, 1), std::invalid_argument);
    EXPECT_THROW(fitPolynomial(x, {1.0, nan, 2.0, 3.0}, {}, 1), std::invalid_argument);
    EXPECT_THROW(fitPolynomial(x, y, {}, 4), std::invalid_argument);                    // too few points
    EXPECT_THROW(fitPolynomial(x, y, {}, -1), std::invalid_argument);
    EXPECT_THROW(fitPolynomial({1.0, 1.0, 1.0}, {1.0, 2.0, 3.0}, {}, 1), std::invalid_argument);  // one x
}

// ---------------------------------------------------------------------------------------------------------
// Plane Poiseuille

TEST(ProfileFitPoiseuille, NoSlipCentredChannel) {
    const Channel ch{-20.0, 20.0, 0.3, 0.02};
    const PoiseuilleFitResult r = fitChannel(channelProfile(ch, 40), ch);
    const double d = 40.0;
    const double uMax = ch.g * d * d / (8.0 * ch.nu);
    expectRelNear(r.nu, ch.nu);
    EXPECT_NEAR(r.lower.slipVelocity, 0.0, kExact * uMax);
    EXPECT_NEAR(r.upper.slipVelocity, 0.0, kExact * uMax);
    EXPECT_NEAR(r.lower.slipLength, 0.0, kExact * d);
    EXPECT_NEAR(r.upper.slipLength, 0.0, kExact * d);
    EXPECT_NEAR(r.centre, 0.0, kExact * d);
    expectRelNear(r.maxVelocity, uMax);
    ASSERT_EQ(r.coefficients.size(), 3u);
    expectRelNear(r.coefficients[2], -ch.g / (2.0 * ch.nu));
}

// The symmetric closed form of the brief, u = g d^2/(8 nu) (1 - (2 y'/d)^2 + 4 beta/d), in a shifted
// channel: slip velocity g d beta/(2 nu), wall shear rate g d/(2 nu).
TEST(ProfileFitPoiseuille, SymmetricSlipMatchesClosedForm) {
    const double yLow = 3.0, yHigh = 11.0, d = yHigh - yLow, nu = 0.85, g = 0.05, beta = 0.7;
    const auto u = [&](double y) {
        const double yc = y - 0.5 * (yLow + yHigh);
        return g * d * d / (8.0 * nu) * (1.0 - std::pow(2.0 * yc / d, 2) + 4.0 * beta / d);
    };
    const PoiseuilleFitResult r = fitPoiseuille(sampleProfile(u, yLow, yHigh, 16, 0.01), g, yLow, yHigh);
    expectRelNear(r.nu, nu);
    for (const WallFitResult* w : {&r.lower, &r.upper}) {
        expectRelNear(w->slipLength, beta);
        expectRelNear(w->slipVelocity, g * d * beta / (2.0 * nu));
        expectRelNear(w->shearRate, g * d / (2.0 * nu));
    }
    expectRelNear(r.centre, 7.0);
    expectRelNear(r.maxVelocity, g * d * d / (8.0 * nu) * (1.0 + 4.0 * beta / d));
}

TEST(ProfileFitPoiseuille, AsymmetricSlipInShiftedChannels) {
    expectExactRecovery({3.0, 11.0, 0.4, 0.05, 0.4, 1.3});
    expectExactRecovery({-20.0, 20.0, 0.3, 0.02, 2.0, 0.25});
}

// Walls moving together (a Galilean shift) and walls moving apart (Poiseuille plus Couette).
TEST(ProfileFitPoiseuille, MovingWalls) {
    expectExactRecovery({-20.0, 20.0, 0.3, 0.02, 0.8, 0.8, 0.5, 0.5});
    expectExactRecovery({3.0, 11.0, 0.4, 0.05, 0.3, 1.1, -0.2, 0.6});
}

// A force along -x drives the flow along -x; the fluid still slides in the flow direction, so the slip
// lengths stay positive while slip velocities and shear rates flip sign.
TEST(ProfileFitPoiseuille, NegativeForceKeepsSlipLengthPositive) {
    const Channel ch{3.0, 11.0, 0.4, -0.05, 0.4, 1.3};
    expectExactRecovery(ch);
    const PoiseuilleFitResult r = fitChannel(channelProfile(ch, 30), ch);
    EXPECT_GT(r.nu, 0.0);
    EXPECT_GT(r.lower.slipLength, 0.0);
    EXPECT_LT(r.lower.slipVelocity, 0.0);
    EXPECT_LT(r.lower.shearRate, 0.0);
}

TEST(ProfileFitPoiseuille, ExcludedWallLayersDoNotMatter) {
    const Channel ch{-20.0, 20.0, 0.3, 0.02, 1.0, 0.5};
    Profile1D p = channelProfile(ch, 80);
    const double exclude = 1.5;
    int spoiled = 0;
    for (std::size_t i = 0; i < p.y.size(); ++i) {
        if (p.y[i] >= ch.yLow + exclude && p.y[i] <= ch.yHigh - exclude) continue;
        p.u[i] = (spoiled % 2 == 0) ? 1e6 : std::numeric_limits<double>::quiet_NaN();
        p.uErr[i] = (spoiled % 3 == 0) ? 0.0 : -1.0;  // invalid errors are also never looked at
        ++spoiled;
    }
    ASSERT_EQ(spoiled, 6);  // bins of width 0.5: centres 0.25, 0.75, 1.25 from each wall
    const PoiseuilleFitResult r = fitChannel(p, ch, exclude);
    expectRelNear(r.nu, ch.nu);
    expectRelNear(r.lower.slipLength, ch.betaLow);
    expectRelNear(r.upper.slipLength, ch.betaHigh);
    EXPECT_EQ(r.dof, 80 - 6 - 3);
    // Without the exclusion the garbage is fitted and the errors are rejected.
    EXPECT_THROW(fitChannel(p, ch), std::invalid_argument);
}

TEST(ProfileFitPoiseuille, RejectsTooFewPointsAndBadArguments) {
    const Channel ch{3.0, 11.0, 0.4, 0.05};
    const Profile1D p = channelProfile(ch, 8);  // bin width 1: centres 3.5 ... 10.5
    EXPECT_NO_THROW(fitChannel(p, ch, 2.0));  // 4 points: 5.5 ... 8.5
    EXPECT_THROW(fitChannel(p, ch, 2.6), std::invalid_argument);  // 3 points
    try {
        fitChannel(p, ch, 3.0);
        FAIL() << "expected std::invalid_argument";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("at least 4"), std::string::npos) << e.what();
    }
    EXPECT_THROW(fitPoiseuille(p, 0.0, ch.yLow, ch.yHigh), std::invalid_argument);
    EXPECT_THROW(fitPoiseuille(p, ch.g, ch.yHigh, ch.yLow), std::invalid_argument);
    EXPECT_THROW(fitPoiseuille(p, ch.g, ch.yLow, ch.yHigh, -1.0), std::invalid_argument);
    Profile1D bad = p;
    bad.uErr.pop_back();
    EXPECT_THROW(fitChannel(bad, ch), std::invalid_argument);
}

// Gaussian noise of the quoted size: the delta-method errors must cover the truth ~68% of the time (bound
// explained at kRepetitions), and the reduced chi^2 must average to about 1.
TEST(ProfileFitPoiseuille, ErrorEstimatesAreStatisticallyRight) {
    const Channel ch{-20.0, 20.0, 0.3, 0.01, 1.0, 0.5};  // u_max ~ 6.7, slip velocities 0.67 and 0.33
    std::mt19937_64 rng(20240611);
    int nuHits = 0, betaLowHits = 0, betaHighHits = 0, slipHits = 0;
    double chi2Sum = 0.0;
    for (int rep = 0; rep < kRepetitions; ++rep) {
        const PoiseuilleFitResult r = fitChannel(channelProfile(ch, 40, 0.05, &rng), ch);
        const Parabola exact = exactProfile(ch);
        nuHits += std::abs(r.nu - ch.nu) < r.nuErr;
        betaLowHits += std::abs(r.lower.slipLength - ch.betaLow) < r.lower.slipLengthErr;
        betaHighHits += std::abs(r.upper.slipLength - ch.betaHigh) < r.upper.slipLengthErr;
        slipHits += std::abs(r.lower.slipVelocity - exact(ch.yLow)) < r.lower.slipVelocityErr;
        chi2Sum += r.chi2PerDof;
    }
    for (int hits : {nuHits, betaLowHits, betaHighHits, slipHits}) {
        const double fraction = double(hits) / kRepetitions;
        EXPECT_GT(fraction, kCoverageLow);
        EXPECT_LT(fraction, kCoverageHigh);
    }
    // Mean of 400 reduced chi^2 with 37 dof: standard deviation sqrt(2/37/400) = 0.012.
    EXPECT_NEAR(chi2Sum / kRepetitions, 1.0, 0.05);
}

// ---------------------------------------------------------------------------------------------------------
// Reverse Poiseuille: periodic box [yLo, yLo + L), force +g on the first half, -g on the second. With
// s = y - yLo the steady solution (continuous, with continuous slope, periodic) is
//   u = U0 + g/(2 nu) s (L/2 - s)             for s in [0, L/2)
//   u = U0 - g/(2 nu) (s - L/2) (L - s)       for s in [L/2, L)
struct ReverseBox {
    double yLo, length, nu, g, offset = 0.3;
    double operator()(double y) const {
        const double s = y - yLo, half = 0.5 * length;
        return offset + (s < half ? g / (2 * nu) * s * (half - s) : -g / (2 * nu) * (s - half) * (length - s));
    }
};

Profile1D reverseProfile(const ReverseBox& box, int nBins, double sigma = 0.01, std::mt19937_64* rng = nullptr) {
    return sampleProfile(box, box.yLo, box.yLo + box.length, nBins, sigma, rng);
}

TEST(ProfileFitReversePoiseuille, RecoversViscosityExactly) {
    const ReverseBox box{-5.0, 20.0, 0.32, 0.05};
    const ReversePoiseuilleResult r = fitReversePoiseuille(reverseProfile(box, 40), box.g, box.yLo, box.length, 0.0);
    expectRelNear(r.nu, box.nu);
    expectRelNear(r.nuFirstHalf, box.nu);
    expectRelNear(r.nuSecondHalf, box.nu);
}

// Bins next to the planes where the force jumps carry garbage (as DPD smooths the cusp there); with the
// exclusion they must not matter, including those at the periodic boundary.
TEST(ProfileFitReversePoiseuille, ExcludeBandIsHonoured) {
    const ReverseBox box{2.0, 24.0, 0.5, -0.04};
    const double exclude = 1.0;
    Profile1D p = reverseProfile(box, 48);  // bin width 0.5
    int spoiled = 0;
    for (std::size_t i = 0; i < p.y.size(); ++i) {
        const double s = p.y[i] - box.yLo;
        const double distance = std::min({s, std::abs(s - 12.0), 24.0 - s});
        if (distance >= exclude) continue;
        p.u[i] = (i % 2 == 0) ? -1e4 : std::numeric_limits<double>::quiet_NaN();
        ++spoiled;
    }
    ASSERT_EQ(spoiled, 8);  // two bins on each side of each of the two planes
    const ReversePoiseuilleResult r = fitReversePoiseuille(p, box.g, box.yLo, box.length, exclude);
    expectRelNear(r.nu, box.nu);
    expectRelNear(r.nuFirstHalf, box.nu);
    expectRelNear(r.nuSecondHalf, box.nu);
    EXPECT_THROW(fitReversePoiseuille(p, box.g, box.yLo, box.length, 0.0), std::invalid_argument);
}

// The same profile written with coordinates shifted by whole periods is the same flow.
TEST(ProfileFitReversePoiseuille, PeriodicImagesAreWrapped) {
    const ReverseBox box{0.0, 16.0, 0.4, 0.03};
    Profile1D p = reverseProfile(box, 32);
    for (std::size_t i = 0; i < p.y.size(); ++i) p.y[i] += (i % 3 == 0) ? 16.0 : (i % 3 == 1 ? -32.0 : 0.0);
    const ReversePoiseuilleResult r = fitReversePoiseuille(p, box.g, box.yLo, box.length, 0.5);
    expectRelNear(r.nu, box.nu);
}

TEST(ProfileFitReversePoiseuille, ErrorEstimatesAreStatisticallyRight) {
    const ReverseBox box{0.0, 30.0, 0.3, 0.02};
    std::mt19937_64 rng(77);
    int hits = 0, firstHits = 0;
    double chi2Sum = 0.0;
    for (int rep = 0; rep < kRepetitions; ++rep) {
        const ReversePoiseuilleResult r =
            fitReversePoiseuille(reverseProfile(box, 60, 0.03, &rng), box.g, box.yLo, box.length, 1.0);
        hits += std::abs(r.nu - box.nu) < r.nuErr;
        firstHits += std::abs(r.nuFirstHalf - box.nu) < r.nuFirstHalfErr;
        chi2Sum += r.chi2PerDof;
    }
    for (int h : {hits, firstHits}) {
        EXPECT_GT(double(h) / kRepetitions, kCoverageLow);
        EXPECT_LT(double(h) / kRepetitions, kCoverageHigh);
    }
    EXPECT_NEAR(chi2Sum / kRepetitions, 1.0, 0.05);
}

TEST(ProfileFitReversePoiseuille, RejectsBadArguments) {
    const ReverseBox box{0.0, 16.0, 0.4, 0.03};
    const Profile1D p = reverseProfile(box, 16);  // 8 bins per half, width 1
    EXPECT_NO_THROW(fitReversePoiseuille(p, box.g, box.yLo, box.length, 2.5));  // 4 bins per half left
    EXPECT_THROW(fitReversePoiseuille(p, box.g, box.yLo, box.length, 3.0), std::invalid_argument);  // 2 left
    EXPECT_THROW(fitReversePoiseuille(p, box.g, box.yLo, box.length, 4.0), std::invalid_argument);  // >= L/4
    EXPECT_THROW(fitReversePoiseuille(p, 0.0, box.yLo, box.length), std::invalid_argument);
    EXPECT_THROW(fitReversePoiseuille(p, box.g, box.yLo, 0.0), std::invalid_argument);
}

// ---------------------------------------------------------------------------------------------------------
// Kinetic theory, kT = 1, gamma = 4.5, rho = 3, rc = 1:
//   kinetic     45 / (4 pi * 4.5 * 3) = 45 / (54 pi) = 45 / 169.6460033 = 0.2652582385
//   dissipative 2 pi * 4.5 * 3 / 1575 = 27 pi / 1575 = 84.8230016 / 1575 = 0.0538558741
//   total                                                                 = 0.3191141126
TEST(ProfileFitKineticTheory, HandComputedValue) {
    EXPECT_NEAR(kineticTheoryViscosity(1.0, 4.5, 3.0), 0.3191141126, 1e-9);
    EXPECT_NEAR(kineticTheoryViscosity(1.0, 4.5, 3.0, 1.0), 0.2652582385 + 0.0538558741, 1e-9);
    // Only the kinetic part scales with kT; it scales as rc^-3 and the dissipative part as rc^5.
    EXPECT_NEAR(kineticTheoryViscosity(2.0, 4.5, 3.0), 2 * 0.2652582385 + 0.0538558741, 1e-9);
    EXPECT_NEAR(kineticTheoryViscosity(1.0, 4.5, 3.0, 2.0), 0.2652582385 / 8 + 0.0538558741 * 32, 1e-8);
}

}  // namespace
}  // namespace dpd
