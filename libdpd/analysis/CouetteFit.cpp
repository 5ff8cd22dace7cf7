#include "analysis/CouetteFit.hpp"

#include "analysis/CorrelatedMean.hpp"
#include "analysis/WeightedPolyFit.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace dpd {

CouetteFitResult fitCouette(const Profile1D& p, double yLow, double yHigh, double fitLow, double fitHigh,
                            double uWallLow, double uWallHigh) {
    if (p.u.size() != p.y.size() || (!p.uErr.empty() && p.uErr.size() != p.y.size()))
        throw std::invalid_argument("fitCouette: the profile arrays y, u, uErr differ in size");
    if (!(yHigh > yLow)) throw std::invalid_argument("fitCouette: the upper wall must lie above the lower one");
    if (!(fitHigh > fitLow) || fitLow < yLow || fitHigh > yHigh)
        throw std::invalid_argument("fitCouette: the fit range [" + std::to_string(fitLow) + ", " +
                                    std::to_string(fitHigh) + "] must be a nonempty range between the walls");
    const Profile1D s = selectProfilePoints(p, [](double y) { return y; },
                                            [&](double y) { return y >= fitLow && y <= fitHigh; });
    if (s.y.size() < 3)
        throw std::invalid_argument("fitCouette: " + std::to_string(s.y.size()) + " profile points in [" +
                                    std::to_string(fitLow) + ", " + std::to_string(fitHigh) +
                                    "], at least 3 are needed (2 coefficients + 1 degree of freedom)");
    const PolyFitResult fit = fitProfilePolynomial(s, 1);
    CouetteFitResult r;
    r.shearRate = fit.coefficients(1);
    r.shearRateErr = fit.standardError(1);
    r.lower = navierSlipAtWall(fit, yLow, uWallLow, +1.0);
    r.upper = navierSlipAtWall(fit, yHigh, uWallHigh, -1.0);
    r.fitLow = fitLow;
    r.fitHigh = fitHigh;
    r.dof = fit.dof;
    r.chi2PerDof = fit.dof > 0 ? fit.chi2 / fit.dof : 0.0;
    r.coefficients = {fit.coefficients(0), fit.coefficients(1)};
    r.blockErrors = fit.blockErrors;
    for (const Eigen::VectorXd& c : fit.blockCoefficients) r.blockShearRates.push_back(c(1));
    return r;
}

namespace {

// The errors of the mean stress and of eta from the blocks: per block the mean stress over the range
// and eta linearised about the means, d eta = d sigma / gamma - sigma d gamma / gamma^2.
void blockStressErrors(const std::vector<double>& y, const std::vector<std::vector<double>>& sigmaBlocks,
                       const CouetteFitResult& fit, StressViscosity& v) {
    if (sigmaBlocks.size() != fit.blockShearRates.size())
        throw std::invalid_argument("viscosityFromStress: " + std::to_string(sigmaBlocks.size()) + " stress blocks for " +
                                    std::to_string(fit.blockShearRates.size()) + " blocks of the fit");
    std::vector<double> stress, eta;
    for (std::size_t k = 0; k < sigmaBlocks.size(); ++k) {
        if (sigmaBlocks[k].size() != y.size()) throw std::invalid_argument("viscosityFromStress: a stress block differs in size");
        double sum = 0.0;
        for (std::size_t i = 0; i < y.size(); ++i)
            if (y[i] >= fit.fitLow && y[i] <= fit.fitHigh) sum += sigmaBlocks[k][i];
        const double s = sum / v.points;
        stress.push_back(s);
        eta.push_back(s / fit.shearRate - v.stress * fit.blockShearRates[k] / (fit.shearRate * fit.shearRate));
    }
    v.stressErr = correlatedStandardError(stress);
    v.etaErr = correlatedStandardError(eta);
}

}  // namespace

StressViscosity viscosityFromStress(const std::vector<double>& y, const std::vector<double>& sigma,
                                    const std::vector<double>& sigmaErr, const CouetteFitResult& fit, double density,
                                    const std::vector<std::vector<double>>& sigmaBlocks) {
    if (sigma.size() != y.size() || sigmaErr.size() != y.size())
        throw std::invalid_argument("viscosityFromStress: the arrays differ in size");
    if (fit.shearRate == 0.0) throw std::invalid_argument("viscosityFromStress: the shear rate is zero");
    StressViscosity v;
    double sumSq = 0.0;
    for (std::size_t i = 0; i < y.size(); ++i) {
        if (y[i] < fit.fitLow || y[i] > fit.fitHigh) continue;
        v.stress += sigma[i];
        sumSq += sigmaErr[i] * sigmaErr[i];
        ++v.points;
    }
    if (v.points == 0) throw std::invalid_argument("viscosityFromStress: no stress bin in the fit range");
    v.stress /= v.points;
    v.stressErr = std::sqrt(sumSq) / v.points;
    v.eta = v.stress / fit.shearRate;
    // d eta = d sigma / gamma - sigma d gamma / gamma^2, the two errors independent.
    v.etaErr = std::hypot(v.stressErr / fit.shearRate, v.stress * fit.shearRateErr / (fit.shearRate * fit.shearRate));
    if (!sigmaBlocks.empty()) blockStressErrors(y, sigmaBlocks, fit, v);
    v.nu = v.eta / density;
    v.nuErr = v.etaErr / density;
    return v;
}

}  // namespace dpd
