#include "analysis/CorrelatedMean.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace dpd {

namespace {

constexpr double kWindowFactor = 5.0;  // W >= 5 tau_int: the neglected tail of an exponential is e^-10

Eigen::MatrixXd autocovariance(const std::vector<Eigen::VectorXd>& d, std::size_t lag) {
    const Eigen::Index n = d.front().size();
    Eigen::MatrixXd g = Eigen::MatrixXd::Zero(n, n);
    for (std::size_t k = 0; k + lag < d.size(); ++k) g.noalias() += d[k] * d[k + lag].transpose();
    return g / static_cast<double>(d.size() - lag);
}

}  // namespace

CorrelatedMean correlatedMean(const std::vector<Eigen::VectorXd>& series) {
    const std::size_t m = series.size();
    if (m < 4) throw std::invalid_argument("correlatedMean: at least 4 values are needed");
    const Eigen::Index n = series.front().size();
    CorrelatedMean r;
    r.mean = Eigen::VectorXd::Zero(n);
    for (const auto& q : series) {
        if (q.size() != n) throw std::invalid_argument("correlatedMean: the vectors differ in size");
        r.mean += q;
    }
    r.mean /= static_cast<double>(m);
    std::vector<Eigen::VectorXd> d;
    d.reserve(m);
    for (const auto& q : series) d.push_back(q - r.mean);

    const Eigen::MatrixXd gamma0 = autocovariance(d, 0);
    Eigen::MatrixXd sum = gamma0;
    Eigen::VectorXd tau = Eigen::VectorXd::Constant(n, 0.5);
    const std::size_t maxWindow = m / 4;
    r.windowFound = false;
    std::size_t w = 0;
    while (w < maxWindow) {
        ++w;
        const Eigen::MatrixXd g = autocovariance(d, w);
        sum += g + g.transpose();
        bool enough = true;
        for (Eigen::Index i = 0; i < n; ++i) {
            if (gamma0(i, i) > 0.0) tau(i) += g(i, i) / gamma0(i, i);
            if (static_cast<double>(w) < kWindowFactor * tau(i)) enough = false;
        }
        if (enough) {
            r.windowFound = true;
            break;
        }
    }
    // A block mean cannot be better than independent blocks make it (tau_int >= 1/2): a window whose
    // sum falls below Gamma_0 for any component has caught noise (or anticorrelation, which flows do
    // not show), and the independent-block estimate is kept.
    bool below = false;
    for (Eigen::Index i = 0; i < n; ++i) below = below || sum(i, i) < gamma0(i, i);
    if (below) {
        sum = gamma0;
        w = 0;
        tau.setConstant(0.5);
    }
    r.window = static_cast<int>(w);
    r.maxTau = tau.maxCoeff();
    // Each autocovariance about the sample mean is low by about Var(mean): (2W + 1) of them make the
    // sum low by the factor 1 - (2W + 1)/m, corrected to first order (Wolff 2004).
    const double bias = 1.0 + (2.0 * static_cast<double>(w) + 1.0) / static_cast<double>(m);
    r.covariance = 0.5 * (sum + sum.transpose()) * (bias / static_cast<double>(m));
    return r;
}

double correlatedStandardError(const std::vector<double>& series, BlockErrorInfo* info) {
    std::vector<Eigen::VectorXd> values;
    values.reserve(series.size());
    for (double v : series) values.push_back(Eigen::VectorXd::Constant(1, v));
    const CorrelatedMean c = correlatedMean(values);
    if (info) *info = {static_cast<int>(series.size()), c.window, c.maxTau, c.windowFound};
    return std::sqrt(c.covariance(0, 0));
}

}  // namespace dpd
