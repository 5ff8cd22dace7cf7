#pragma once
// Couette flow between two plates sliding in their own planes (docs/analysis.md section 5): the steady
// profile is the line u(y) = c0 + c1 y over the central part of the channel (next to the walls the
// fluid is layered and the profile bends). From the fitted line:
//   shear rate  du/dy = c1;
//   at each wall, as in Poiseuille mode (PoiseuilleFit.hpp: navierSlipAtWall), the slip velocity
//   u_fit(wall) - U_wall (its size is |U_wall - u_fit(wall)|, "wall speed minus the fitted velocity")
//   and the Navier slip length beta = slip velocity / (du/dn), n pointing into the fluid, so beta > 0
//   at both walls when the fluid lags behind them;
//   with the shear stress profile sigma_xy(y) (uniform in steady Couette flow by momentum balance),
//   the dynamic viscosity eta = <sigma> / (du/dy) and nu = eta / rho.
// Errors: the line's covariance (weighted fit scaled by the reduced chi^2, or from the profile's blocks:
// Profile1D.hpp), propagated to first order.
#include "analysis/PoiseuilleFit.hpp"

#include <vector>

namespace dpd {

struct CouetteFitResult {
    double shearRate = 0.0, shearRateErr = 0.0;  // du/dy of the line
    WallFitResult lower, upper;
    double fitLow = 0.0, fitHigh = 0.0;          // the range of y fitted
    double chi2PerDof = 0.0;
    int dof = 0;
    std::vector<double> coefficients;            // c0 c1
    BlockErrorInfo blockErrors;                  // blocks 0: errors from the points' errors alone
    std::vector<double> blockShearRates;         // the line's slope in each block (with blocks)
};

// Fits the line to the points with fitLow <= y <= fitHigh. Throws std::invalid_argument when the arrays
// differ in size, yHigh <= yLow, the range is empty or outside the walls, or fewer than 3 points lie in it
// (2 coefficients + 1 degree of freedom for the scatter).
CouetteFitResult fitCouette(const Profile1D& p, double yLow, double yHigh, double fitLow, double fitHigh,
                            double uWallLow, double uWallHigh);

struct StressViscosity {
    double stress = 0.0, stressErr = 0.0;  // mean shear stress over the fitted range
    double eta = 0.0, etaErr = 0.0;        // <sigma> / shear rate
    double nu = 0.0, nuErr = 0.0;          // eta / rho
    int points = 0;
};

// The mean of the stress over the bins in [fitLow, fitHigh], divided by the fitted shear rate. With the
// stress of each block (sigmaBlocks[k][i], the fit's blocks) the errors come from the block series of
// the mean stress and of eta itself (linearised in stress and shear rate, which move together);
// without, the bins' block means are taken as independent (error sqrt(sum err^2) / n) and the
// relative errors of stress and shear rate add in quadrature. Throws std::invalid_argument when no
// bin lies in range, the shear rate is zero, or the blocks do not match the fit's.
StressViscosity viscosityFromStress(const std::vector<double>& y, const std::vector<double>& sigma,
                                    const std::vector<double>& sigmaErr, const CouetteFitResult& fit, double density,
                                    const std::vector<std::vector<double>>& sigmaBlocks = {});

}  // namespace dpd
