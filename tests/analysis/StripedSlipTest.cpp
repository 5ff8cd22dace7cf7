// The continuum reference for striped walls (analysis/StripedSlip.hpp, docs/analysis.md 5.1). Each test
// holds the solution to a value found another way: Philip's exact result, a plain Fourier collocation
// written here, the biharmonic modes solved here, the single wall against the deep channel, lubrication
// for thin channels, the slip tensor rotated here.
#include "analysis/StripedSlip.hpp"
#include "analysis/StripedSlipModes.hpp"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>

namespace dpd {
namespace {

const double kInf = std::numeric_limits<double>::infinity();
const double kPi = 3.14159265358979323846;

StripedWall wall(double phi2, double b, double height = kInf, int stripedWalls = 1) {
    StripedWall w;
    w.period = 1.0;
    w.slipFraction = phi2;
    w.localSlip = b;
    w.height = height;
    w.stripedWalls = stripedWalls;
    return w;
}

double relative(double actual, double expected) { return std::abs(actual / expected - 1.0); }

// The mean slip velocity a0 from a plain truncated cosine series collocated at `points` midpoints of the
// half period (no edge functions): s = a0 + sum a_n cos(k n x), tau = T0 - sigma a0 - sum g_n a_n cos, with
// s = 0 on the no-slip part and s = b tau on the gas. It converges like 1/points, so points and 2 points
// with one Richardson step; phi2 * points is kept whole so that the edge sits midway between two points
// at both sizes.
double collocatedMeanSlip(double phi2, double b, const std::function<double(double)>& g, double t0, double sigma,
                          int points) {
    const double k = 2.0 * kPi;
    Eigen::MatrixXd a(points, points);
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(points);
    for (int i = 0; i < points; ++i) {
        const double x = (i + 0.5) * 0.5 / points;
        const bool gas = x < 0.5 * phi2;
        a(i, 0) = !gas ? 1.0 : std::isinf(b) ? sigma : 1.0 + b * sigma;
        for (int n = 1; n < points; ++n) {
            const double c = std::cos(k * n * x);
            a(i, n) = !gas ? c : std::isinf(b) ? g(k * n) * c : (1.0 + b * g(k * n)) * c;
        }
        if (gas) rhs(i) = std::isinf(b) ? t0 : b * t0;
    }
    return a.partialPivLu().solve(rhs)(0);
}

double richardsonMeanSlip(double phi2, double b, const std::function<double(double)>& g, double t0, double sigma) {
    return 2.0 * collocatedMeanSlip(phi2, b, g, t0, sigma, 800) - collocatedMeanSlip(phi2, b, g, t0, sigma, 400);
}

// The biharmonic mode psi = f(y) cos(kx), written here from its four exponentials, with psi = 0 and
// psi_y = 1 on the striped wall; g = -psi_yy there. Far side: psi = psi_y = 0 at y = H (no-slip wall), or
// psi odd about H/2 (two striped walls, f = P(y) - P(H - y)).
double biharmonicResponse(double k, double height, int stripedWalls) {
    const double h = k * height;
    // f(eta) = A eta e^-eta + B e^-eta + C e^-(h-eta) + D (h-eta) e^-(h-eta), eta = k y; rows: f, f', f''.
    auto row = [h](double eta, int derivative) {
        const double ea = std::exp(-eta), eb = std::exp(-(h - eta)), r = h - eta;
        Eigen::RowVector4d v;
        if (derivative == 0) v << eta * ea, ea, eb, r * eb;
        if (derivative == 1) v << (1.0 - eta) * ea, -ea, eb, (r - 1.0) * eb;
        if (derivative == 2) v << (eta - 2.0) * ea, ea, eb, (r - 2.0) * eb;
        return v;
    };
    Eigen::Matrix4d m;
    Eigen::Vector4d rhs(0.0, 1.0, 0.0, 0.0);
    if (stripedWalls == 1) {
        m << row(0.0, 0), row(0.0, 1), row(h, 0), row(h, 1);
    } else {
        // Odd about the middle: C = -B, D = -A turn f into P(eta) - P(h - eta).
        m << row(0.0, 0), row(0.0, 1), 0.0, 1.0, 1.0, 0.0, 1.0, 0.0, 0.0, 1.0;
    }
    const Eigen::Vector4d c = m.partialPivLu().solve(rhs);
    return -k * row(0.0, 2).dot(c);  // g = -f_yy / f_y = -k f''(eta) / f'(eta), f'(0) = 1
}

}  // namespace

// Philip (1972): b_par = 2 b_perp = (L / pi) ln sec(pi phi2 / 2) for shear-free stripes under shear.
// The automatic resolution claims 1e-4, ten times inside the 1e-3 the reference must meet.
TEST(StripedSlip, ReproducesPhilipForShearFreeStripes) {
    for (double phi2 : {0.05, 0.2, 0.5, 0.8, 0.95}) {
        const double exact = std::log(1.0 / std::cos(0.5 * kPi * phi2)) / kPi;
        EXPECT_NEAR(philipLongitudinalSlip(1.0, phi2), exact, 1e-15);
        EXPECT_LT(relative(longitudinalSlip(wall(phi2, kInf)), exact), 1e-4) << "phi2 " << phi2;
        EXPECT_LT(relative(transverseSlip(wall(phi2, kInf)), 0.5 * exact), 1e-4) << "phi2 " << phi2;
    }
    // Lengths scale with the period.
    StripedWall w = wall(0.5, kInf);
    w.period = 3.0;
    EXPECT_LT(relative(longitudinalSlip(w), 3.0 * philipLongitudinalSlip(1.0, 0.5)), 1e-4);
}

// Doubling the sector functions (with the modes they need) and, separately, the modes changes the slip
// by less than the 1e-4 the automatic resolution claims, for single walls and channels.
TEST(StripedSlip, ConvergesUnderDoubling) {
    const StripedWall cases[] = {wall(0.5, 0.01), wall(0.8, 0.3), wall(0.2, 1.0, 0.5), wall(0.8, kInf, 0.02, 2),
                                 wall(0.95, 0.1, 0.1, 2)};
    for (const StripedWall& w : cases) {
        const StripedSlipResolution r = stripedSlipResolution(w);
        const StripedSlipResolution moreBasis{2 * r.basis, 0}, moreModes{r.basis, 2 * r.modes};
        for (auto slip : {&longitudinalSlip, &transverseSlip}) {
            const double b = slip(w, r);
            EXPECT_LT(relative(slip(w, moreBasis), b), 1e-4) << "phi2 " << w.slipFraction << " H " << w.height;
            EXPECT_LT(relative(slip(w, moreModes), b), 1e-4) << "phi2 " << w.slipFraction << " H " << w.height;
        }
    }
}

// A uniform wall (phi2 = 1) is its own reference: b exactly, in every geometry. Towards phi2 = 1 a
// weakly slipping wall's b_eff approaches b, with the no-slip strips' share shrinking.
TEST(StripedSlip, UniformSlipIsExact) {
    for (const StripedWall& w : {wall(1.0, 0.3), wall(1.0, 0.3, 0.2), wall(1.0, 0.3, 0.2, 2), wall(1.0, kInf)}) {
        EXPECT_EQ(longitudinalSlip(w), w.localSlip);
        EXPECT_EQ(transverseSlip(w), w.localSlip);
    }
    EXPECT_EQ(belyaevVinogradovaLongitudinalSlip(1.0, 1.0, 0.3), 0.3);
    EXPECT_EQ(philipTransverseSlip(1.0, 1.0), kInf);
    double previous = 0.0;
    for (double phi2 : {0.9, 0.95, 0.99}) {
        const SlipTensor t = stripedSlipTensor(wall(phi2, 0.01));
        EXPECT_GT(t.perpendicular, previous);
        EXPECT_LT(t.parallel, 0.01);
        EXPECT_GT(t.parallel, 0.01 * (1.0 - 3.0 * (1.0 - phi2)));
        previous = t.perpendicular;
    }
}

// phi2 -> 0: the slip vanishes, quadratically in phi2 for shear-free stripes (Philip: b_par ~ pi phi2^2 L / 8)
// and never above the surface average phi2 b (the arithmetic-mean bound) nor above the shear-free value.
TEST(StripedSlip, VanishesWithTheGasFraction) {
    EXPECT_EQ(longitudinalSlip(wall(0.0, kInf)), 0.0);
    EXPECT_EQ(transverseSlip(wall(0.0, 0.1)), 0.0);
    EXPECT_EQ(longitudinalSlip(wall(0.5, 0.0)), 0.0);
    for (double phi2 : {0.02, 0.01, 0.005}) {
        EXPECT_NEAR(longitudinalSlip(wall(phi2, kInf)) / (kPi * phi2 * phi2 / 8.0), 1.0, 1e-3) << "phi2 " << phi2;
        EXPECT_NEAR(transverseSlip(wall(phi2, kInf)) / (kPi * phi2 * phi2 / 16.0), 1.0, 1e-3) << "phi2 " << phi2;
        for (double b : {0.001, 0.1}) {
            const SlipTensor t = stripedSlipTensor(wall(phi2, b));
            EXPECT_GT(t.perpendicular, 0.0);
            EXPECT_LE(t.perpendicular, t.parallel);
            EXPECT_LE(t.parallel, phi2 * b);
            EXPECT_LE(t.parallel, philipLongitudinalSlip(1.0, phi2));
        }
    }
}

// Asmolov and Vinogradova (2012): for a single wall in shear b_perp[b] = b_par[2b] / 2, here between the
// Laplace solution and the biharmonic one at finite b.
TEST(StripedSlip, TransverseIsHalfTheLongitudinalAtTwiceTheSlip) {
    for (double phi2 : {0.2, 0.5, 0.8})
        for (double b : {0.01, 0.1, 1.0, 10.0})
            EXPECT_LT(relative(transverseSlip(wall(phi2, b)), 0.5 * longitudinalSlip(wall(phi2, 2.0 * b))), 1e-4)
                << "phi2 " << phi2 << " b " << b;
}

// The wall responses against the modes solved here: the biharmonic four-exponential systems, the Laplace
// forms, and the lubrication limits (shear 4/H and 6/H for a unit slip with no net flux, 1/H for a linear
// profile, k^2 H / 2 for the free plug).
TEST(StripedSlip, ModeResponsesSolveTheirEquations) {
    for (double h : {0.05, 0.3, 1.0, 3.0, 10.0, 40.0}) {
        for (int walls : {1, 2}) {
            const double k = 2.0 * kPi, height = h / k;
            EXPECT_LT(relative(stripedModeResponse(StripedFlow::transverse, k, height, walls),
                               biharmonicResponse(k, height, walls)),
                      1e-8)
                << "h " << h << " walls " << walls;
        }
        EXPECT_NEAR(stripedModeResponse(StripedFlow::longitudinal, 1.0, h, 1), std::cosh(h) / std::sinh(h), 1e-12);
        EXPECT_NEAR(stripedModeResponse(StripedFlow::longitudinal, 1.0, h, 2), std::tanh(0.5 * h), 1e-12);
    }
    EXPECT_EQ(stripedModeResponse(StripedFlow::transverse, 3.0, kInf, 1), 6.0);
    EXPECT_EQ(stripedModeResponse(StripedFlow::longitudinal, 3.0, kInf, 1), 3.0);
    const double h = 1e-3;
    EXPECT_NEAR(stripedModeResponse(StripedFlow::transverse, 1.0, h, 1) * h, 4.0, 1e-5);
    EXPECT_NEAR(stripedModeResponse(StripedFlow::transverse, 1.0, h, 2) * h, 6.0, 1e-5);
    EXPECT_NEAR(stripedModeResponse(StripedFlow::longitudinal, 1.0, h, 1) * h, 1.0, 1e-5);
    EXPECT_NEAR(stripedModeResponse(StripedFlow::longitudinal, 1.0, h, 2) / h, 0.5, 1e-5);
}

// At finite b the sector-function Galerkin solution against a plain Fourier collocation (no edge
// functions, Richardson-extrapolated, about 1e-5 off), with its own mean flow: unit shear for the single
// wall; T0 = H/2, sigma = 1/H and b_eff from the flux H^3/12 + a0 H / 2 for the channel.
TEST(StripedSlip, AgreesWithPlainFourierCollocation) {
    const double height = 0.5;
    for (double phi2 : {0.2, 0.5}) {
        for (double b : {0.05, 1.0}) {
            auto laplace = [](double k) { return k; };
            auto biharmonic = [](double k) { return 2.0 * k; };
            EXPECT_LT(relative(longitudinalSlip(wall(phi2, b)), richardsonMeanSlip(phi2, b, laplace, 1.0, 0.0)), 1e-4);
            EXPECT_LT(relative(transverseSlip(wall(phi2, b)), richardsonMeanSlip(phi2, b, biharmonic, 1.0, 0.0)), 1e-4);
            auto channel = [height](double k) { return stripedModeResponse(StripedFlow::transverse, k, height, 1); };
            const double a0 = richardsonMeanSlip(phi2, b, channel, 0.5 * height, 1.0 / height);
            // (H + 4 beta)/(H + beta) = Q / (H^3/12) = 1 + 6 a0 / H^2.
            const double r = 2.0 * a0 / (height * height);
            EXPECT_LT(relative(transverseSlip(wall(phi2, b, height)), r * height / (1.0 - r)), 1e-4);
        }
    }
}

// Belyaev and Vinogradova's formulas are Philip's for b -> infinity and interpolate below. Measured here
// and in docs/analysis.md 5.1: they lie below the solution at every b, the gap closing like L/b; as
// b/L -> 0 they tend to b ln sec / ln(sec + tan) (at x = pi phi2 / 2) instead of the surface average phi2 b,
// so the gap tends to 1 - R, R = ln sec x / (phi2 ln(sec x + tan x)), at most 1 - pi/4 = 21.5 % (phi2 -> 0).
TEST(StripedSlip, BelyaevVinogradovaWithinItsMeasuredBound) {
    for (double phi2 : {0.2, 0.5, 0.8}) {
        const double x = 0.5 * kPi * phi2;
        const double smallSlipRatio = std::log(1.0 / std::cos(x)) / (phi2 * std::log((1.0 + std::sin(x)) / std::cos(x)));
        EXPECT_EQ(belyaevVinogradovaLongitudinalSlip(1.0, phi2, kInf), philipLongitudinalSlip(1.0, phi2));
        EXPECT_EQ(belyaevVinogradovaTransverseSlip(1.0, phi2, kInf), philipTransverseSlip(1.0, phi2));
        double previousGap = 1.0;
        for (double b : {0.001, 0.01, 0.1, 1.0, 10.0, 100.0}) {
            const SlipTensor t = stripedSlipTensor(wall(phi2, b));
            const double gapPar = 1.0 - belyaevVinogradovaLongitudinalSlip(1.0, phi2, b) / t.parallel;
            const double gapPerp = 1.0 - belyaevVinogradovaTransverseSlip(1.0, phi2, b) / t.perpendicular;
            for (double gap : {gapPar, gapPerp}) {
                EXPECT_GT(gap, -1e-4) << "phi2 " << phi2 << " b " << b;
                EXPECT_LT(gap, 1.0 - smallSlipRatio + 1e-3) << "phi2 " << phi2 << " b " << b;
                EXPECT_LT(gap, 0.12 / b) << "phi2 " << phi2 << " b " << b;  // closes like L / b (0.084 L/b at 0.8)
            }
            EXPECT_LT(gapPar, previousGap);
            previousGap = gapPar;
            if (b == 0.001) EXPECT_NEAR(gapPar, 1.0 - smallSlipRatio, 0.02);  // 0.0096 off at phi2 = 0.2
        }
    }
}

// Thin channels (H << L): lubrication over each stripe. Along the stripes the local flux factor
// f(b) = (H + 4b)/(H + b) (one striped wall) or 1 + 6b/H (two) averages over the period; across them the
// flux is the same everywhere and 1/f averages. The formulas against those averages written here, and the
// numerical solution against the formulas: below them by (0.9 to 5.5) H/L (measured), closing like H/L.
TEST(StripedSlip, ThinChannelLimits) {
    auto factor = [](double b, double h, int walls) {
        if (walls == 2) return 1.0 + 6.0 * b / h;
        return std::isinf(b) ? 4.0 : (h + 4.0 * b) / (h + b);
    };
    auto slipOfFactor = [](double f, double h, int walls) {
        return walls == 2 ? (f - 1.0) * h / 6.0 : h * (f - 1.0) / (4.0 - f);
    };
    for (int walls : {1, 2}) {
        for (double b : {0.01, kInf}) {
            const StripedWall w = wall(0.5, b, 0.01, walls);
            const double along = 0.5 * factor(0.0, 0.01, walls) + 0.5 * factor(b, 0.01, walls);
            const double across = 1.0 / (0.5 / factor(0.0, 0.01, walls) + 0.5 / factor(b, 0.01, walls));
            if (std::isfinite(along))
                EXPECT_LT(relative(thinChannelLongitudinalSlip(w), slipOfFactor(along, 0.01, walls)), 1e-12);
            EXPECT_LT(relative(thinChannelTransverseSlip(w), slipOfFactor(across, 0.01, walls)), 1e-12);
            for (auto [solve, thin] : {std::pair{&longitudinalSlip, &thinChannelLongitudinalSlip},
                                       std::pair{&transverseSlip, &thinChannelTransverseSlip}}) {
                if (std::isinf(thin(w))) continue;  // two shear-free walls along the stripes: no thin limit
                const double gap = relative(solve(w, {}), thin(w));
                StripedWall thinner = w;
                thinner.height = 0.005;
                if (std::isfinite(b)) thinner.localSlip = 0.005;  // b / H kept
                const double thinnerGap = relative(solve(thinner, {}), thin(thinner));
                EXPECT_LT(gap, 0.06) << "walls " << walls << " b " << b;
                EXPECT_LT(thinnerGap, 0.6 * gap) << "walls " << walls << " b " << b;
            }
        }
    }
}

// Far from the stripes (H = 3 L) the channel's wall problem is the single wall's under the mean wall shear,
// and b_eff defined through the flux is the single wall's b_eff, up to e^(-2 pi H / L).
TEST(StripedSlip, DeepChannelIsTheSingleWall) {
    for (double b : {0.1, kInf}) {
        const SlipTensor single = stripedSlipTensor(wall(0.5, b));
        for (int walls : {1, 2}) {
            const SlipTensor deep = stripedSlipTensor(wall(0.5, b, 3.0, walls));
            EXPECT_LT(relative(deep.parallel, single.parallel), 1e-6) << "walls " << walls;
            EXPECT_LT(relative(deep.perpendicular, single.perpendicular), 1e-6) << "walls " << walls;
        }
    }
}

// b_eff(theta) = b_par cos^2 + b_perp sin^2 against the slip tensor rotated here.
TEST(StripedSlip, EffectiveSlipProjectsTheTensor) {
    const SlipTensor t = stripedSlipTensor(wall(0.5, 0.2));
    const Eigen::Matrix2d tensor = Eigen::Vector2d(t.parallel, t.perpendicular).asDiagonal();
    for (double theta : {0.0, 0.3, kPi / 4, 1.2, kPi / 2, 2.5}) {
        const Eigen::Vector2d direction(std::cos(theta), std::sin(theta));
        EXPECT_NEAR(effectiveSlip(t, theta), direction.dot(tensor * direction), 1e-15);
    }
    EXPECT_EQ(effectiveSlip(t, 0.0), t.parallel);
}

// The flux of a channel driven at angle theta to the stripes, from the flux tensor rotated here: the part
// across the driving force over the part along it. Zero at 0 and pi/2, towards the stripes (positive) on
// both sides of pi/4, odd in theta, largest at tan theta = sqrt(Q_par / Q_perp) with
// (Q_par - Q_perp) / (2 sqrt(Q_par Q_perp)).
TEST(StripedSlip, TransverseFluxRatio) {
    const StripedWall w = wall(0.5, kInf, 0.5, 2);
    const SlipTensor t = stripedSlipTensor(w);
    const double qPar = 1.0 + 6.0 * t.parallel / w.height, qPerp = 1.0 + 6.0 * t.perpendicular / w.height;
    EXPECT_NEAR(channelFluxFactor(t.parallel, w.height, 2), qPar, 1e-14);
    const Eigen::Matrix2d flux = Eigen::Vector2d(qPar, qPerp).asDiagonal();
    for (double theta : {0.1, 0.4, kPi / 4, 1.0, 1.4}) {
        const Eigen::Vector2d force(std::cos(theta), std::sin(theta)), towardStripes(std::sin(theta), -std::cos(theta));
        const Eigen::Vector2d q = flux * force;
        const double ratio = transverseFluxRatio(w, theta);
        EXPECT_NEAR(ratio, q.dot(towardStripes) / q.dot(force), 1e-12);
        EXPECT_GT(ratio, 0.0);
        EXPECT_GT(transverseFluxRatio(t, w.height, 2, kPi / 2 - theta), 0.0);
        EXPECT_NEAR(transverseFluxRatio(t, w.height, 2, -theta), -ratio, 1e-14);
        EXPECT_NEAR(transverseFluxRatio(t, w.height, 2, theta + kPi), ratio, 1e-12);
    }
    EXPECT_NEAR(transverseFluxRatio(t, w.height, 2, 0.0), 0.0, 1e-15);
    EXPECT_NEAR(transverseFluxRatio(t, w.height, 2, kPi / 2), 0.0, 1e-15);
    const double best = std::atan(std::sqrt(qPar / qPerp));
    const double largest = (qPar - qPerp) / (2.0 * std::sqrt(qPar * qPerp));
    EXPECT_NEAR(transverseFluxRatio(t, w.height, 2, best), largest, 1e-12);
    EXPECT_LT(transverseFluxRatio(t, w.height, 2, best + 0.01), largest);
    EXPECT_LT(transverseFluxRatio(t, w.height, 2, best - 0.01), largest);
    // One striped wall facing a no-slip wall: the flux factor (H + 4 b)/(H + b).
    EXPECT_NEAR(channelFluxFactor(0.1, 0.5, 1), 0.9 / 0.6, 1e-15);
    EXPECT_GT(transverseFluxRatio(wall(0.5, kInf, 0.5, 1), 0.5), 0.0);
    EXPECT_THROW(transverseFluxRatio(wall(0.5, kInf), 0.5), std::invalid_argument);
}

TEST(StripedSlip, RejectsInvalidWalls) {
    EXPECT_THROW(longitudinalSlip(wall(1.2, 0.1)), std::invalid_argument);
    EXPECT_THROW(longitudinalSlip(wall(-0.1, 0.1)), std::invalid_argument);
    EXPECT_THROW(transverseSlip(wall(0.5, -1.0)), std::invalid_argument);
    EXPECT_THROW(transverseSlip(wall(0.5, 0.1, 0.0)), std::invalid_argument);
    EXPECT_THROW(transverseSlip(wall(0.5, 0.1, kInf, 2)), std::invalid_argument);
    EXPECT_THROW(transverseSlip(wall(0.5, 0.1, 1.0, 3)), std::invalid_argument);
    EXPECT_THROW(transverseSlip(wall(0.5, std::nan(""))), std::invalid_argument);
    EXPECT_THROW(thinChannelLongitudinalSlip(wall(0.5, 0.1)), std::invalid_argument);
    StripedWall w = wall(0.5, 0.1);
    w.period = 0.0;
    EXPECT_THROW(longitudinalSlip(w), std::invalid_argument);
}

}  // namespace dpd
