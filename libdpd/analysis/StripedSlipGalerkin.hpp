#pragma once
// The mixed wall problem every striped-wall case reduces to (docs/analysis.md 5.1, "The wall
// problem" and "Method"). Along the wall (x, period L, theta = 2 pi x / L) the slip velocity is
//   s(x) = a0 + sum_n s_n cos(n theta),   the wall shear  tau(x) = T0 - sigma a0 - sum_n g(k_n) s_n cos(n theta),
// with s = 0 on the no-slip part and s = b tau on the gas sectors |theta| < theta_c = pi phi2.
// s is expanded on the gas sector as sqrt(cos theta - cos theta_c) U_2j(theta / theta_c), which vanishes
// on the no-slip part and carries the square-root edge of a shear-free stripe; a Galerkin projection of
// s - b tau = 0 onto the same functions gives a small symmetric positive definite system, and its
// solution the mean slip velocity a0.
#include <functional>

namespace dpd {

struct StripedWallProblem {
    double period = 1.0;                   // L
    double slipFraction = 0.5;             // phi2, 0 < phi2 < 1
    double inverseSlip = 0.0;              // 1/b of the gas sectors; 0: shear-free
    double meanShear = 1.0;                // T0: the wall shear of the mean flow when a0 = 0
    double meanShearPerSlip = 0.0;         // sigma: the fall of the mean wall shear per unit a0
    std::function<double(double)> response;  // g(k) (analysis/StripedSlipModes.hpp)
    double responseSlope = 1.0;            // g(k) / k for k -> infinity, for the tail of the mode sums
};

// The mean slip velocity a0 with `basis` sector functions and `modes` Fourier modes (the sums beyond
// are added from the modes' large-n asymptote). Needs modes >> basis^2 / theta_c and g(k) close to
// responseSlope k beyond the last mode.
double meanSlipVelocity(const StripedWallProblem& problem, int basis, int modes);

}  // namespace dpd
