#include "analysis/PoiseuilleFit.hpp"

#include "analysis/CorrelatedMean.hpp"
#include "analysis/WeightedPolyFit.hpp"

#include <algorithm>

#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>

namespace dpd {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr std::size_t kMinPoints = 4;  // 3 coefficients + 1 degree of freedom to measure the scatter

void checkProfile(const Profile1D& p, const char* who) {
    if (p.u.size() != p.y.size() || (!p.uErr.empty() && p.uErr.size() != p.y.size()))
        throw std::invalid_argument(std::string(who) + ": the profile arrays y, u, uErr differ in size");
}

void checkBodyForce(double g, const char* who) {
    // The viscosity comes from the curvature per unit force; without a force there is nothing to measure.
    if (!std::isfinite(g) || g == 0.0)
        throw std::invalid_argument(std::string(who) + ": the body force g must be finite and nonzero");
}

void requireEnoughPoints(const Profile1D& s, const std::string& where) {
    if (s.y.size() < kMinPoints)
        throw std::invalid_argument(where + ": " + std::to_string(s.y.size()) +
                                    " profile points in the fit range, at least " + std::to_string(kMinPoints) +
                                    " are needed (3 coefficients + 1 degree of freedom)");
}


// nu = -g / (2 c2), hence dnu/dc2 = g / (2 c2^2) and only var(c2) enters. The `sign` is -1 where the
// force is +g (curvature -g/(2 nu)) and +1 where it is -g.
struct Viscosity {
    double value, error;
};

Viscosity viscosityFromCurvature(const PolyFitResult& fit, double g, double sign) {
    const double c2 = fit.coefficients(2);
    return {sign * g / (2.0 * c2), std::abs(g / (2.0 * c2 * c2)) * fit.standardError(2)};
}

PolyFitResult fitParabola(const Profile1D& s) { return fitPolynomial(s.y, s.u, s.uErr, 2, false); }

// chi^2 per degree of freedom with respect to the errors as given (the fit stores the unscaled chi^2).
double chi2PerDof(double chi2, int dof) { return dof > 0 ? chi2 / dof : 0.0; }

Viscosity scaled(Viscosity v, double factor) { return {v.value, v.error * factor}; }

// Inverse-variance weighted mean of two estimates. A zero error (exact data) would give infinite weight:
// such estimates are then averaged among themselves.
Viscosity combine(Viscosity a, Viscosity b) {
    if (a.error == 0.0 && b.error == 0.0) return {0.5 * (a.value + b.value), 0.0};
    if (a.error == 0.0) return a;
    if (b.error == 0.0) return b;
    const double wa = 1.0 / (a.error * a.error), wb = 1.0 / (b.error * b.error);
    return {(wa * a.value + wb * b.value) / (wa + wb), 1.0 / std::sqrt(wa + wb)};
}

ReversePoiseuilleResult reverseResult(Viscosity nu, Viscosity nu1, Viscosity nu2, double chi2PerDofBoth) {
    ReversePoiseuilleResult r;
    r.nu = nu.value;
    r.nuErr = nu.error;
    r.nuFirstHalf = nu1.value;
    r.nuFirstHalfErr = nu1.error;
    r.nuSecondHalf = nu2.value;
    r.nuSecondHalfErr = nu2.error;
    r.chi2PerDof = chi2PerDofBoth;
    return r;
}

// The standard error of the mean of a block series, times the chi^2 factor.
double seriesError(const std::vector<double>& values, double scale, BlockErrorInfo* info = nullptr) {
    return correlatedStandardError(values, info) * std::sqrt(scale);
}

// Reverse Poiseuille with blocks: each half's viscosity block by block (linearised in its curvature),
// their mean, and its error from the block series of the mean itself: the halves share the flow's
// modes, so they are not independent.
ReversePoiseuilleResult reverseFromBlocks(const Profile1D& first, const Profile1D& second, double g) {
    const PolyFitResult fit1 = fitProfilePolynomial(first, 2), fit2 = fitProfilePolynomial(second, 2);
    const int dof = fit1.dof + fit2.dof;
    const double scale = std::max(1.0, (fit1.chi2 + fit2.chi2) / dof);
    const double c1 = fit1.coefficients(2), c2 = fit2.coefficients(2);
    // nu1 = -g / (2 c1), nu2 = +g / (2 c2): their slopes in the curvatures.
    const double slope1 = g / (2.0 * c1 * c1), slope2 = -g / (2.0 * c2 * c2);
    std::vector<double> d1, d2;
    for (std::size_t k = 0; k < fit1.blockCoefficients.size(); ++k) {
        d1.push_back(slope1 * fit1.blockCoefficients[k](2));
        d2.push_back(slope2 * fit2.blockCoefficients[k](2));
    }
    const Viscosity nu1{-g / (2.0 * c1), seriesError(d1, scale)}, nu2{g / (2.0 * c2), seriesError(d2, scale)};
    // The halves are mirror images with the same points: equal weights (weights from the noisy block
    // errors would favour whichever half fluctuated less and make the combined error too small).
    const Viscosity weighted{0.5 * (nu1.value + nu2.value), 0.0};
    std::vector<double> both;
    for (std::size_t k = 0; k < d1.size(); ++k) both.push_back(0.5 * (d1[k] + d2[k]));
    BlockErrorInfo info;
    const double error = seriesError(both, scale, &info);
    ReversePoiseuilleResult r = reverseResult({weighted.value, error}, nu1, nu2, chi2PerDof(fit1.chi2 + fit2.chi2, dof));
    r.blockErrors = info;
    return r;
}

}  // namespace

// For a fitted polynomial u(y) = sum_k c_k y^k, at the wall y = yw with inward normal n (+1 lower
// wall, -1 upper wall):
//   s     = u(yw) - U_wall                 ds/dc_k     = yw^k
//   gamma = n u'(yw)                        dgamma/dc_k = n k yw^(k-1)
//   beta  = s / gamma                       dbeta/dc    = (ds/dc - beta dgamma/dc) / gamma
// and each error is the delta-method sqrt(grad^T C grad).
WallFitResult navierSlipAtWall(const PolyFitResult& fit, double yw, double uWall, double inwardNormal) {
    const Eigen::VectorXd& c = fit.coefficients;
    const int n = static_cast<int>(c.size());
    Eigen::VectorXd dSlip(n), dShear(n);
    double power = 1.0;  // yw^k
    for (int k = 0; k < n; ++k) {
        dSlip(k) = power;
        dShear(k) = k == 0 ? 0.0 : inwardNormal * k * std::pow(yw, k - 1);
        power *= yw;
    }
    WallFitResult w;
    w.position = yw;
    w.wallVelocity = uWall;
    w.slipVelocity = fit.evaluate(yw) - uWall;
    w.shearRate = dShear.dot(c);
    w.slipLength = w.slipVelocity / w.shearRate;
    const auto error = [&](const Eigen::VectorXd& grad) { return fit.errorOf(grad); };
    w.slipVelocityErr = error(dSlip);
    w.shearRateErr = error(dShear);
    w.slipLengthErr = error((dSlip - w.slipLength * dShear) / w.shearRate);
    return w;
}

PoiseuilleFitResult fitPoiseuille(const Profile1D& p, double g, double yLow, double yHigh, double exclude,
                                  double uWallLow, double uWallHigh) {
    const char* who = "fitPoiseuille";
    checkProfile(p, who);
    checkBodyForce(g, who);
    if (!(yHigh > yLow)) throw std::invalid_argument("fitPoiseuille: yHigh must be above yLow");
    if (!(exclude >= 0.0)) throw std::invalid_argument("fitPoiseuille: exclude must be >= 0");

    const double lo = yLow + exclude, hi = yHigh - exclude;
    const Profile1D s = selectProfilePoints(p, [](double y) { return y; }, [&](double y) { return y >= lo && y <= hi; });
    requireEnoughPoints(s, "fitPoiseuille: y in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
    const PolyFitResult fit = fitProfilePolynomial(s, 2);
    const Eigen::VectorXd& c = fit.coefficients;

    PoiseuilleFitResult r;
    const Viscosity nu = viscosityFromCurvature(fit, g, -1.0);
    r.nu = nu.value;
    r.nuErr = nu.error;
    r.lower = navierSlipAtWall(fit, yLow, uWallLow, +1.0);
    r.upper = navierSlipAtWall(fit, yHigh, uWallHigh, -1.0);
    r.centre = -c(1) / (2.0 * c(2));
    r.maxVelocity = fit.evaluate(r.centre);
    r.dof = fit.dof;
    r.chi2PerDof = chi2PerDof(fit.chi2, fit.dof);
    r.coefficients = {c(0), c(1), c(2)};
    r.blockErrors = fit.blockErrors;
    return r;
}

ReversePoiseuilleResult fitReversePoiseuille(const Profile1D& p, double g, double yLo, double length,
                                             double exclude) {
    const char* who = "fitReversePoiseuille";
    checkProfile(p, who);
    checkBodyForce(g, who);
    if (!(length > 0.0) || !std::isfinite(length))
        throw std::invalid_argument("fitReversePoiseuille: the box length must be positive");
    const double half = 0.5 * length;
    if (!(exclude >= 0.0 && exclude < 0.5 * half))
        throw std::invalid_argument("fitReversePoiseuille: exclude must lie in [0, L/4)");

    // Work in the offset s = y - yLo wrapped into [0, L): each half is then one contiguous interval.
    const auto wrap = [&](double y) {
        const double s = y - yLo;
        return s - length * std::floor(s / length);
    };
    const auto inFirst = [&](double s) { return s < half && s >= exclude && half - s >= exclude; };
    const auto inSecond = [&](double s) { return s >= half && s - half >= exclude && length - s >= exclude; };
    const Profile1D first = selectProfilePoints(p, wrap, inFirst);
    const Profile1D second = selectProfilePoints(p, wrap, inSecond);
    requireEnoughPoints(first, "fitReversePoiseuille: first half (force +g)");
    requireEnoughPoints(second, "fitReversePoiseuille: second half (force -g)");
    if (!p.blocks.empty()) return reverseFromBlocks(first, second, g);

    // Both halves share one noise model, so the scatter factor (reduced chi^2) is estimated once from both
    // together: scaling each half by its own, noisier, chi^2 would feed that noise into the weights of the
    // combination and make the combined error too small (it then covers the truth clearly less than 68%).
    const PolyFitResult fit1 = fitParabola(first), fit2 = fitParabola(second);
    const int dof = fit1.dof + fit2.dof;
    const double scatter = std::sqrt((fit1.chi2 + fit2.chi2) / dof);
    const Viscosity nu1 = scaled(viscosityFromCurvature(fit1, g, -1.0), scatter);
    const Viscosity nu2 = scaled(viscosityFromCurvature(fit2, g, +1.0), scatter);
    const Viscosity nu = combine(nu1, nu2);

    return reverseResult(nu, nu1, nu2, chi2PerDof(fit1.chi2 + fit2.chi2, dof));
}

double kineticTheoryViscosity(double kT, double gamma, double rho, double rc) {
    const double kinetic = 45.0 * kT / (4.0 * kPi * gamma * rho * rc * rc * rc);
    const double dissipative = 2.0 * kPi * gamma * rho * std::pow(rc, 5) / 1575.0;
    return kinetic + dissipative;
}

}  // namespace dpd
