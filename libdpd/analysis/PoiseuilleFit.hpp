#pragma once
// Viscosity and wall slip from steady velocity profiles driven by a body force (DPD reduced units).
//
// Plane Poiseuille flow: body force g per unit mass along the flow, walls at y = yLow and y = yHigh. The
// steady profile is the parabola u(y) = c0 + c1 y + c2 y^2 with c2 = -g / (2 nu), so the curvature of a
// fitted parabola gives the kinematic viscosity nu. Navier slip at a wall:
//     u(wall) - U_wall = beta * du/dn,
// with n the unit normal pointing from the wall into the fluid (so du/dn = +du/dy at the lower wall and
// -du/dy at the upper one). For the usual flow du/dn > 0 and du/dn = |du/dy|; defining beta through du/dn
// keeps beta > 0 whenever the fluid slides along the wall in the direction of the flow, also for g < 0.
// beta < 0 means the fluid lags the wall (the no-slip plane lies inside the fluid).
//
// Uncertainties: all derived quantities are smooth functions f(c) of the fitted coefficients c = (c0, c1,
// c2). Linear error propagation (delta method) gives var f = grad f^T C grad f, with C the covariance of
// the coefficients: from the weighted fit scaled by the reduced chi^2, or, when the profile carries its
// blocks, propagated from the blocks' covariance of the bins (Profile1D.hpp). This is accurate while the relative errors are
// small (the quantities are ratios, so their distributions become skewed when they are not).
#include "analysis/Profile1D.hpp"

#include <vector>

namespace dpd {

struct WallFitResult {
    double position = 0.0;         // y of the wall
    double wallVelocity = 0.0;     // U_wall, the wall's own velocity (as given)
    double slipVelocity = 0.0;     // u_fit(wall) - U_wall
    double slipVelocityErr = 0.0;
    double slipLength = 0.0;       // beta = slipVelocity / shearRate
    double slipLengthErr = 0.0;
    double shearRate = 0.0;        // du/dn at the wall, n pointing into the fluid (> 0 for g > 0)
    double shearRateErr = 0.0;
};

// Navier slip at the wall y = yw of a fitted polynomial profile (any degree), with inward normal
// +1 (lower wall) or -1 (upper wall), and delta-method errors from the fit's covariance.
WallFitResult navierSlipAtWall(const PolyFitResult& fit, double yw, double uWall, double inwardNormal);

struct PoiseuilleFitResult {
    double nu = 0.0;     // kinematic viscosity, -g / (2 c2)
    double nuErr = 0.0;
    WallFitResult lower, upper;
    double centre = 0.0;       // where du/dy = 0: -c1 / (2 c2)
    double maxVelocity = 0.0;  // u_fit(centre) (the extreme velocity; a minimum when g < 0)
    double chi2PerDof = 0.0;   // with the given errors; about 1 when they are right and the flow is parabolic
    int dof = 0;
    std::vector<double> coefficients;  // c0 c1 c2
    BlockErrorInfo blockErrors;        // blocks 0: errors from the points' errors alone
};

// Fits a parabola to the points with yLow + exclude <= y <= yHigh - exclude (exclude drops the layers next
// to the walls, where the density and velocity are structured by the wall potential). uWallLow and
// uWallHigh are the walls' own velocities. Throws std::invalid_argument when g is zero or not finite,
// yHigh <= yLow, exclude < 0, the profile arrays differ in size, the errors are invalid, or fewer than 4
// points lie in range (3 coefficients plus at least one degree of freedom for the scatter).
PoiseuilleFitResult fitPoiseuille(const Profile1D& p, double g, double yLow, double yHigh, double exclude = 0.0,
                                  double uWallLow = 0.0, double uWallHigh = 0.0);

struct ReversePoiseuilleResult {
    double nu = 0.0, nuErr = 0.0;                  // inverse-variance weighted mean of the two halves
    double nuFirstHalf = 0.0, nuFirstHalfErr = 0.0;    // y in [yLo, yLo + L/2), force +g
    double nuSecondHalf = 0.0, nuSecondHalfErr = 0.0;  // y in [yLo + L/2, yLo + L), force -g
    double chi2PerDof = 0.0;                       // both halves together, with the given errors
    BlockErrorInfo blockErrors;                    // blocks 0: errors from the points' errors alone
};

// Periodic "reverse Poiseuille" flow: force +g on [yLo, yLo + L/2), -g on the other half. Each half is fitted
// with its own parabola (curvature -g/(2 nu) and +g/(2 nu)). Points within `exclude` of a plane where the
// force jumps (y = yLo, yLo + L/2, and yLo + L, the periodic image of yLo) are ignored: DPD smooths the cusp
// there over about one cutoff. Coordinates outside [yLo, yLo + L) are wrapped into the box. All errors are
// scaled by one reduced chi^2 pooled over both halves (they share the noise model; a per-half scale would be
// noisier and would bias the inverse-variance weights of the combination). Throws
// std::invalid_argument for g zero or not finite, length <= 0, exclude outside [0, L/4), or fewer than 4
// points in either half. With the profile's blocks, each half's error comes from its blocks and the
// combined error from the block series of the combination (the halves move together); without them the
// points are taken as independent.
ReversePoiseuilleResult fitReversePoiseuille(const Profile1D& p, double g, double yLo, double length,
                                             double exclude = 1.0);

// Kinetic-theory estimate of the kinematic viscosity for the standard DPD weight w_D = (1 - r/rc)^2
// (Groot & Warren 1997): nu = 45 kT / (4 pi gamma rho rc^3) + 2 pi gamma rho rc^5 / 1575. The first term
// is the kinetic (momentum carried by particles) part, the second the dissipative (pair friction) part.
double kineticTheoryViscosity(double kT, double gamma, double rho, double rc = 1.0);

}  // namespace dpd
