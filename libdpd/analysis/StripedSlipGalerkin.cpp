#include "analysis/StripedSlipGalerkin.hpp"

// GCC 12 flags Eigen's AVX-512 product kernels as maybe-uninitialized (a false positive, in Eigen's code).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <Eigen/Dense>
#pragma GCC diagnostic pop

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace dpd {

namespace {

constexpr double kPi = 3.14159265358979323846;

double sinc(double u) { return u == 0.0 ? 1.0 : std::sin(u) / u; }

// The sector functions on quadrature nodes. theta = theta_c cos(chi) with the midpoint rule in chi:
// sqrt(cos theta - cos theta_c) = theta_c sin(chi) sqrt(E), E = (cos theta - cos theta_c) / (theta_c^2 - theta^2)
// smooth and positive, so every integrand below is a smooth periodic function of chi (spectral accuracy).
struct SectorQuadrature {
    Eigen::VectorXd theta;   // nodes
    Eigen::VectorXd weight;  // d theta = theta_c sin(chi) d chi, times pi / nodes
    Eigen::MatrixXd basis;   // nodes x basis: sqrt(cos theta - cos theta_c) U_2j(theta / theta_c)
};

SectorQuadrature sectorQuadrature(double thetaC, int basis, int nodes) {
    SectorQuadrature q;
    q.theta.resize(nodes);
    q.weight.resize(nodes);
    q.basis.resize(nodes, basis);
    for (int i = 0; i < nodes; ++i) {
        const double chi = kPi * (i + 0.5) / nodes;
        const double theta = thetaC * std::cos(chi);
        // (cos theta - cos theta_c) / (theta_c^2 - theta^2) as a product of sincs: no cancellation at the edges.
        const double e = 0.5 * sinc(0.5 * (thetaC + theta)) * sinc(0.5 * (thetaC - theta));
        q.theta(i) = theta;
        q.weight(i) = kPi / nodes * thetaC * std::sin(chi);
        for (int j = 0; j < basis; ++j) q.basis(i, j) = thetaC * std::sqrt(e) * std::sin((2 * j + 1) * chi);
    }
    return q;
}

// S(n - 1, j) = (1/pi) int phi_j cos(n theta) d theta, n = 1..modes: blocks of nodes, cos(n theta) by the
// Chebyshev recurrence, and one matrix product per block.
Eigen::MatrixXd sectorFourierCoefficients(const SectorQuadrature& q, int modes) {
    const int nodes = static_cast<int>(q.theta.size());
    const int basis = static_cast<int>(q.basis.cols());
    const Eigen::MatrixXd weighted = (q.weight / kPi).asDiagonal() * q.basis;
    Eigen::MatrixXd s = Eigen::MatrixXd::Zero(modes, basis);
    const int block = 256;
    Eigen::MatrixXd c(modes, block);
    for (int first = 0; first < nodes; first += block) {
        const int count = std::min(block, nodes - first);
        for (int b = 0; b < count; ++b) {
            const double c1 = std::cos(q.theta(first + b));
            double previous = 1.0, current = c1;
            for (int n = 0; n < modes; ++n) {
                c(n, b) = current;
                const double next = 2.0 * c1 * current - previous;
                previous = current;
                current = next;
            }
        }
        s.noalias() += c.leftCols(count) * weighted.middleRows(first, count);
    }
    return s;
}

// sum_{n > N} 1/n^2 (Euler-Maclaurin).
double inverseSquareTail(double n) { return 1.0 / n - 0.5 / (n * n) + 1.0 / (6.0 * n * n * n) - 1.0 / (30.0 * std::pow(n, 5)); }

// K_jm = sum_n g(k_n) S_nj S_nm. Beyond the last mode S_nj ~ D_j n^(-3/2) cos(n theta_c - 3 pi / 4) from the
// square-root edges, D_j = (2j + 1) sqrt(sin(theta_c) / pi), and g ~ slope k n: the tail adds
// slope k D_j D_m sum_{n > N} 1 / (2 n^2) (the oscillating half averages out to O(N^-2)).
Eigen::MatrixXd modeCoupling(const StripedWallProblem& p, const Eigen::MatrixXd& s, double thetaC) {
    const int modes = static_cast<int>(s.rows());
    const int basis = static_cast<int>(s.cols());
    const double k = 2.0 * kPi / p.period;
    Eigen::VectorXd g(modes);
    for (int n = 0; n < modes; ++n) g(n) = p.response(k * (n + 1));
    Eigen::MatrixXd coupling = s.transpose() * g.asDiagonal() * s;
    Eigen::VectorXd edge(basis);
    for (int j = 0; j < basis; ++j) edge(j) = (2 * j + 1) * std::sqrt(std::sin(thetaC) / kPi);
    coupling += 0.5 * p.responseSlope * k * inverseSquareTail(modes) * edge * edge.transpose();
    return coupling;
}

void checkProblem(const StripedWallProblem& p, int basis, int modes) {
    if (!(p.period > 0.0) || !(p.slipFraction > 0.0 && p.slipFraction < 1.0) || !(p.inverseSlip >= 0.0) ||
        !std::isfinite(p.inverseSlip) || !p.response || basis < 1 || modes < 1)
        throw std::invalid_argument("meanSlipVelocity: needs L > 0, 0 < phi2 < 1, 0 <= 1/b finite, a response, "
                                    "basis and modes >= 1");
}

}  // namespace

double meanSlipVelocity(const StripedWallProblem& p, int basis, int modes) {
    checkProblem(p, basis, modes);
    const double thetaC = kPi * p.slipFraction;
    // Enough nodes for cos(n theta) up to the last mode: n theta_c cos(chi) has bandwidth n theta_c in chi.
    const int nodes = static_cast<int>(std::ceil(0.6 * modes * thetaC)) + 2 * basis + 64;
    const SectorQuadrature q = sectorQuadrature(thetaC, basis, nodes);
    // Averages over the period: F_j = <phi_j>, G_jm = <phi_j phi_m>, <phi_j cos n theta> = S_nj / 2.
    const Eigen::VectorXd mean = q.basis.transpose() * q.weight / (2.0 * kPi);
    const Eigen::MatrixXd gram = q.basis.transpose() * q.weight.asDiagonal() * q.basis / (2.0 * kPi);
    const Eigen::MatrixXd coupling = modeCoupling(p, sectorFourierCoefficients(q, modes), thetaC);
    // <phi_j (s/b - tau)> = 0 with tau = T0 - sigma a0 - sum g s_n cos, a0 = F . alpha.
    const Eigen::MatrixXd system =
        p.inverseSlip * gram + 0.5 * coupling + p.meanShearPerSlip * mean * mean.transpose();
    const Eigen::VectorXd alpha = system.ldlt().solve(p.meanShear * mean);
    return mean.dot(alpha);
}

}  // namespace dpd
