#include "analysis/PowerLawFit.hpp"

#include "analysis/WeightedPolyFit.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace dpd {

namespace {

bool positive(double v) { return std::isfinite(v) && v > 0.0; }

}  // namespace

PowerLawFitResult fitPowerLaw(const std::vector<double>& x, const std::vector<double>& y, const std::vector<double>& yError) {
    if (x.size() != y.size() || x.size() != yError.size())
        throw std::invalid_argument("a power-law fit needs as many errors and ordinates as abscissae");
    if (x.size() < 3) throw std::invalid_argument("a power-law fit needs at least 3 points (2 coefficients and a scatter)");
    std::vector<double> lx, ly, le;
    for (std::size_t i = 0; i < x.size(); ++i) {
        if (!positive(x[i]) || !positive(y[i]) || !positive(yError[i]))
            throw std::invalid_argument("a power-law fit needs positive, finite x, y and errors");
        lx.push_back(std::log(x[i]));
        ly.push_back(std::log(y[i]));
        le.push_back(yError[i] / y[i]);
    }
    const PolyFitResult line = fitPolynomial(lx, ly, le, 1, false);
    PowerLawFitResult r;
    r.dof = line.dof;
    r.chi2PerDof = line.chi2 / r.dof;
    r.exponent = line.coefficients(1);
    r.logAmplitude = line.coefficients(0);
    r.exponentError = std::sqrt(line.covariance(1, 1) * std::max(r.chi2PerDof, 1.0));
    return r;
}

}  // namespace dpd
