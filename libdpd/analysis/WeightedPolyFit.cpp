#include "analysis/WeightedPolyFit.hpp"

#include "analysis/CorrelatedMean.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace dpd {

namespace {

void checkInputs(const std::vector<double>& x, const std::vector<double>& y, int degree) {
    if (degree < 0) throw std::invalid_argument("fitPolynomial: degree must be >= 0");
    if (x.size() != y.size())
        throw std::invalid_argument("fitPolynomial: x has " + std::to_string(x.size()) + " values but y has " +
                                    std::to_string(y.size()));
    if (x.size() < static_cast<std::size_t>(degree) + 1)
        throw std::invalid_argument("fitPolynomial: " + std::to_string(x.size()) +
                                    " points cannot determine a polynomial of degree " + std::to_string(degree));
    for (std::size_t i = 0; i < x.size(); ++i)
        if (!std::isfinite(x[i]) || !std::isfinite(y[i]))
            throw std::invalid_argument("fitPolynomial: point " + std::to_string(i) + " is not finite");
}

bool allZero(const std::vector<double>& v) {
    return std::all_of(v.begin(), v.end(), [](double e) { return e == 0.0; });
}

// Square roots of the weights, 1/err. Empty or all-zero errors mean "unknown": unit weights.
std::vector<double> sqrtWeights(const std::vector<double>& yErr, std::size_t n, bool& unitWeights) {
    unitWeights = yErr.empty() || allZero(yErr);
    if (unitWeights) return std::vector<double>(n, 1.0);
    if (yErr.size() != n)
        throw std::invalid_argument("fitPolynomial: " + std::to_string(yErr.size()) + " errors for " +
                                    std::to_string(n) + " points");
    std::vector<double> w(n);
    for (std::size_t i = 0; i < n; ++i) {
        if (!(std::isfinite(yErr[i]) && yErr[i] > 0.0))
            throw std::invalid_argument("fitPolynomial: the error of point " + std::to_string(i) +
                                        " must be positive and finite (got " + std::to_string(yErr[i]) + ")");
        w[i] = 1.0 / yErr[i];
    }
    return w;
}

// The fit runs in t = (x - centre) / halfWidth, which lies in [-1, 1]: the columns 1, t, t^2, ... of the
// design matrix are then of similar size and far from parallel.
struct AbscissaScaling {
    double centre = 0.0;
    double halfWidth = 1.0;
};

AbscissaScaling scalingFor(const std::vector<double>& x) {
    const auto [lo, hi] = std::minmax_element(x.begin(), x.end());
    AbscissaScaling s;
    s.centre = 0.5 * (*lo + *hi);
    // All x equal: any scale will do; the rank check then reports the degenerate fit (for degree > 0).
    if (*hi > *lo) s.halfWidth = 0.5 * (*hi - *lo);
    return s;
}

Eigen::MatrixXd weightedDesignMatrix(const std::vector<double>& x, const std::vector<double>& sqrtW, int degree,
                                     const AbscissaScaling& s) {
    Eigen::MatrixXd a(static_cast<Eigen::Index>(x.size()), degree + 1);
    for (std::size_t i = 0; i < x.size(); ++i) {
        const double t = (x[i] - s.centre) / s.halfWidth;
        double power = sqrtW[i];
        for (int k = 0; k <= degree; ++k, power *= t) a(static_cast<Eigen::Index>(i), k) = power;
    }
    return a;
}

// Matrix T with c = T a, where a are the coefficients in t = (x - m)/h and c those in x:
// a_k t^k = a_k h^-k (x - m)^k = a_k h^-k sum_j binom(k, j) x^j (-m)^(k-j).
Eigen::MatrixXd toOriginalVariable(int degree, const AbscissaScaling& s) {
    const int n = degree + 1;
    Eigen::MatrixXd t = Eigen::MatrixXd::Zero(n, n);
    for (int k = 0; k < n; ++k) {
        double binom = 1.0;  // binom(k, j), built up along j
        for (int j = 0; j <= k; ++j) {
            t(j, k) = binom * std::pow(-s.centre, k - j) / std::pow(s.halfWidth, k);
            binom = binom * (k - j) / (j + 1);
        }
    }
    return t;
}

}  // namespace

double PolyFitResult::reducedChi2() const {
    return dof > 0 ? chi2 / dof : std::numeric_limits<double>::quiet_NaN();
}

double PolyFitResult::evaluate(double x) const { return evaluatePolynomial(coefficients, x); }

double PolyFitResult::standardError(int k) const {
    return errorOf(Eigen::VectorXd::Unit(coefficients.size(), k));
}

double PolyFitResult::errorOf(const Eigen::VectorXd& grad) const {
    if (blockCoefficients.empty()) return std::sqrt(grad.dot(covariance * grad));
    std::vector<double> series;
    series.reserve(blockCoefficients.size());
    for (const Eigen::VectorXd& c : blockCoefficients) series.push_back(grad.dot(c));
    return correlatedStandardError(series) * std::sqrt(blockScale);
}

double evaluatePolynomial(const Eigen::VectorXd& coefficients, double x) {
    double p = 0.0;
    for (Eigen::Index k = coefficients.size() - 1; k >= 0; --k) p = p * x + coefficients(k);
    return p;
}

namespace {

// The weighted problem in the scaled abscissa: coefficients, (A^T A)^-1 and the map from y to the
// coefficients, all in t = (x - centre) / halfWidth.
struct ScaledFit {
    AbscissaScaling scaling;
    Eigen::VectorXd coefficients;
    Eigen::MatrixXd inverseNormal;  // (A^T A)^-1, A the weighted design matrix
    Eigen::MatrixXd map;            // coefficients = map y
    double chi2 = 0.0;
    int dof = 0;
    bool unitWeights = false;
};

ScaledFit solveScaled(const std::vector<double>& x, const std::vector<double>& y, const std::vector<double>& yErr,
                      int degree) {
    checkInputs(x, y, degree);
    ScaledFit f;
    const std::vector<double> sqrtW = sqrtWeights(yErr, x.size(), f.unitWeights);
    f.scaling = scalingFor(x);
    const Eigen::MatrixXd a = weightedDesignMatrix(x, sqrtW, degree, f.scaling);
    Eigen::VectorXd b(a.rows());
    for (Eigen::Index i = 0; i < b.size(); ++i) b(i) = sqrtW[i] * y[i];

    // Column-pivoted QR solves the weighted problem without squaring its condition number (as the
    // normal equations would) and tells us when the points cannot determine all coefficients.
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(a);
    const int nCoeff = degree + 1;
    if (qr.rank() < nCoeff)
        throw std::invalid_argument("fitPolynomial: the points do not determine a polynomial of degree " +
                                    std::to_string(degree) + " (fewer than " + std::to_string(nCoeff) +
                                    " distinct abscissae)");
    f.coefficients = qr.solve(b);

    // A P = Q R, hence (A^T A)^-1 = P R^-1 R^-T P^T.
    const Eigen::MatrixXd r0 = qr.matrixR().topLeftCorner(nCoeff, nCoeff).triangularView<Eigen::Upper>();
    const Eigen::MatrixXd rInv =
        r0.triangularView<Eigen::Upper>().solve(Eigen::MatrixXd::Identity(nCoeff, nCoeff));
    f.inverseNormal = qr.colsPermutation() * (rInv * rInv.transpose()) * qr.colsPermutation().transpose();
    f.map = f.inverseNormal * a.transpose() * Eigen::Map<const Eigen::VectorXd>(sqrtW.data(), a.rows()).asDiagonal();

    f.chi2 = (a * f.coefficients - b).squaredNorm();
    f.dof = static_cast<int>(x.size()) - nCoeff;
    return f;
}

// The result in the original variable, from the covariance of the scaled coefficients.
PolyFitResult inOriginalVariable(const ScaledFit& f, int degree, const Eigen::MatrixXd& covScaled, bool scaled) {
    PolyFitResult r;
    r.chi2 = f.chi2;
    r.dof = f.dof;
    r.unitWeights = f.unitWeights;
    r.covarianceScaled = scaled;
    const Eigen::MatrixXd t = toOriginalVariable(degree, f.scaling);
    r.coefficients = t * f.coefficients;
    r.covariance = t * covScaled * t.transpose();
    return r;
}

}  // namespace

PolyFitResult fitPolynomial(const std::vector<double>& x, const std::vector<double>& y,
                            const std::vector<double>& yErr, int degree, bool scaleByChi2) {
    const ScaledFit f = solveScaled(x, y, yErr, degree);
    const bool scale = scaleByChi2 && f.dof > 0;
    return inOriginalVariable(f, degree, scale ? Eigen::MatrixXd(f.inverseNormal * (f.chi2 / f.dof)) : f.inverseNormal,
                              scale);
}

PolyFitResult fitPolynomial(const std::vector<double>& x, const std::vector<double>& y,
                            const std::vector<double>& yErr, int degree,
                            const std::vector<std::vector<double>>& blocks) {
    const ScaledFit f = solveScaled(x, y, yErr, degree);
    std::vector<Eigen::VectorXd> coefficients;
    for (const auto& block : blocks) {
        if (block.size() != x.size())
            throw std::invalid_argument("fitPolynomial: a block has " + std::to_string(block.size()) + " values for " +
                                        std::to_string(x.size()) + " points");
        coefficients.push_back(f.map * Eigen::Map<const Eigen::VectorXd>(block.data(), f.map.cols()));
    }
    const CorrelatedMean c = correlatedMean(coefficients);
    const bool scale = f.dof > 0 && f.chi2 > f.dof;
    PolyFitResult r = inOriginalVariable(f, degree, scale ? Eigen::MatrixXd(c.covariance * (f.chi2 / f.dof)) : c.covariance,
                                         scale);
    r.blockErrors = {static_cast<int>(blocks.size()), c.window, c.maxTau, c.windowFound};
    const Eigen::MatrixXd t = toOriginalVariable(degree, f.scaling);
    for (const Eigen::VectorXd& q : coefficients) r.blockCoefficients.push_back(t * q);
    r.blockScale = scale ? f.chi2 / f.dof : 1.0;
    return r;
}

}  // namespace dpd
