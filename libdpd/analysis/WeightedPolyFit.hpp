#pragma once
// Weighted linear least squares of a polynomial p(x) = c_0 + c_1 x + ... + c_d x^d.
//
// Each point carries the standard error of its ordinate. Point i gets weight 1/err_i, the fit minimises
// chi^2 = sum_i ((y_i - p(x_i)) / err_i)^2, and the covariance of the coefficients is (A^T W A)^-1.
//
// Standard errors:
//   * every err_i > 0 and finite: the usual weighted fit;
//   * errors empty, or all exactly zero ("unknown"): unit weights, i.e. an ordinary least-squares fit;
//   * anything else (a negative, NaN or infinite error, or a zero among positive ones) is an error:
//     std::invalid_argument, because a zero error would give that point infinite weight.
//
// Covariance:
//   * scaleByChi2 = true (default): the covariance is multiplied by the reduced chi^2 = chi2/dof, so it
//     reflects the scatter actually seen about the fit (the convention of most fitting packages when the
//     absolute size of the errors is not trusted, and the only meaningful one for unit weights). With
//     dof = 0 there is no scatter to measure and the covariance is left unscaled.
//   * scaleByChi2 = false: the covariance is (A^T W A)^-1, i.e. it trusts the given errors as absolute
//     (with unit weights this assumes an error of 1 per point).
//
//   * with the ordinates of each block of the run (the overload below): the fit is the same (weights
//     1/err_i^2); the same linear map applied to each block gives a time series of coefficients, and
//     the covariance is that of their mean, autocorrelations included (CorrelatedMean.hpp), so that
//     points that fluctuate together are not counted as independent; errorOf() takes each derived
//     quantity's error from its own block series. It is multiplied by chi2/dof only
//     where that exceeds 1 (the model does not describe the points within their errors; the Particle
//     Data Group's scale factor).
//
// The abscissa is centred and scaled to [-1, 1] internally (a polynomial basis in x itself becomes badly
// conditioned when the points sit far from x = 0), and the coefficients and covariance are transformed
// back exactly, so callers always see coefficients in the original variable x.
// GCC 12 flags Eigen's AVX-512 product kernels as maybe-uninitialized (a false positive in Eigen's
// code, shown once libdpd is built with hidden visibility).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <Eigen/Dense>
#pragma GCC diagnostic pop
#include <vector>

namespace dpd {

// How the covariance was found from blocks (blocks 0: from the point errors alone).
struct BlockErrorInfo {
    int blocks = 0;
    int window = 0;           // lags summed (CorrelatedMean.hpp)
    double tau = 0.0;         // the largest integrated autocorrelation time of the coefficients, in blocks
    bool windowFound = true;  // false: the correlations outlast a quarter of the series
};

struct PolyFitResult {
    Eigen::VectorXd coefficients;  // c_0 ... c_degree, in the original variable x
    Eigen::MatrixXd covariance;    // (degree+1) x (degree+1), see the header comment for the scaling
    double chi2 = 0.0;             // with the given errors (unscaled), sum of squared weighted residuals
    int dof = 0;                   // number of points minus number of coefficients
    bool unitWeights = false;      // true when the errors were empty or all zero
    bool covarianceScaled = false; // true when the covariance was multiplied by chi2/dof
    BlockErrorInfo blockErrors;
    std::vector<Eigen::VectorXd> blockCoefficients;  // the fit applied to each block (empty without blocks)
    double blockScale = 1.0;       // chi2/dof where it exceeds 1 (blocks only), else 1

    double reducedChi2() const;    // chi2/dof; NaN when dof = 0
    double evaluate(double x) const;
    double standardError(int k) const;  // errorOf the unit vector of coefficient k
    // The standard error of grad . c, a linear combination of the coefficients (first-order propagation
    // for a smooth function of them): sqrt(grad^T C grad) without blocks; with blocks, from the series
    // grad . c_k with its own correlation window (CorrelatedMean.hpp), which stays positive where a
    // noisy estimate of the whole covariance matrix need not.
    double errorOf(const Eigen::VectorXd& grad) const;
};

// Throws std::invalid_argument when the sizes differ, degree < 0, a coordinate is not finite, the errors
// are invalid (see above), or the points cannot determine the polynomial (fewer than degree+1 distinct x).
PolyFitResult fitPolynomial(const std::vector<double>& x, const std::vector<double>& y,
                            const std::vector<double>& yErr, int degree, bool scaleByChi2 = true);

// The same fit with the covariance from the blocks (blocks[k][i]: point i in block k, blocks in time
// order; see above). Throws std::invalid_argument as above, for a block of another size, or for fewer
// than 4 blocks.
PolyFitResult fitPolynomial(const std::vector<double>& x, const std::vector<double>& y,
                            const std::vector<double>& yErr, int degree,
                            const std::vector<std::vector<double>>& blocks);

// p(x) by Horner's rule.
double evaluatePolynomial(const Eigen::VectorXd& coefficients, double x);

}  // namespace dpd
