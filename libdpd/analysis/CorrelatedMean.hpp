#pragma once
// The covariance of the mean of a correlated series of vectors (block values of several quantities, in
// time order), by summing its autocovariances up to a window chosen from the data (Sokal's automatic
// window; Madras & Sokal 1988, docs/analysis.md section 5.2):
//   C = (Gamma_0 + sum_{l=1..W} (Gamma_l + Gamma_l^T)) / m,   Gamma_l = <(q_k - qbar)(q_{k+l} - qbar)^T>,
// W the smallest window with W >= 5 tau_int(W) for every component, tau_int(W) = 1/2 + sum_{l<=W} rho_l,
// Gamma_l averaged over its m - l products and the sum corrected for the mean's own fluctuation by the
// factor 1 + (2W + 1)/m (Wolff, Comput. Phys. Commun. 156 (2004) 143).
// Where the sum falls below Gamma_0 for any component (tau_int < 1/2: noise in the window, or
// anticorrelation, which flows do not show) the plain Gamma_0 / m is kept, with window 0. Derived
// quantities are best taken one at a time (a scalar series each), so that one noisy component does not
// set back the others. Independent blocks give tau_int ~ 1/2 and C ~ Gamma_0 / m (the plain standard error); blocks shorter
// than the flow's slowest mode give tau_int > 1/2 and larger errors.
#include "analysis/WeightedPolyFit.hpp"

#include <vector>

namespace dpd {

struct CorrelatedMean {
    Eigen::VectorXd mean;
    Eigen::MatrixXd covariance;  // of the mean
    int window = 0;              // W, in blocks
    double maxTau = 0.0;         // the largest tau_int(W) of the components, in blocks
    bool windowFound = true;     // false: the window reached a quarter of the series (the errors are uncertain)
                                 // before the correlation had died out
};

// Throws std::invalid_argument for fewer than 4 values or vectors of different sizes.
CorrelatedMean correlatedMean(const std::vector<Eigen::VectorXd>& series);

// The same for a series of numbers: the standard error of its mean (and, when asked, how it was found:
// blocks, window, tau, whether the window was found).
double correlatedStandardError(const std::vector<double>& series, BlockErrorInfo* info = nullptr);

}  // namespace dpd
