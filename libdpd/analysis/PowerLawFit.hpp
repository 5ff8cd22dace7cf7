#pragma once
// A power law y = A x^p fitted as the straight line ln y = p ln x + ln A, each point weighted by the
// error of its logarithm (err / y). The exponent's error comes from the fit's covariance, scaled up by
// chi^2/dof where the points scatter more than their errors say (never scaled down).
#include <vector>

namespace dpd {

struct PowerLawFitResult {
    double exponent = 0.0, exponentError = 0.0;
    double logAmplitude = 0.0;  // ln A
    double chi2PerDof = 0.0;
    int dof = 0;
};

// Throws std::invalid_argument for fewer than 3 points, sizes that differ, or an x, y or error that is
// not positive and finite.
PowerLawFitResult fitPowerLaw(const std::vector<double>& x, const std::vector<double>& y, const std::vector<double>& yError);

}  // namespace dpd
