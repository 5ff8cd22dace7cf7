#include "walls/TunableSlipParameters.hpp"

#include "random/PairRandom.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace dpd {

double TunableSlipParameters::wcaRange() const { return std::pow(2.0, 1.0 / 6.0) * sigma; }

double TunableSlipParameters::reach() const {
    const double behind = behindDensity > 0.0 ? sigma + cutoff : 0.0;
    return std::max({zc, wcaRange(), behind});
}

double TunableSlipParameters::frictionWeight(double z) const { return z >= 0.0 && z < zc ? 1.0 - z / zc : 0.0; }

double TunableSlipParameters::wcaForce(double z) const {
    if (!(z > 0.0) || z >= wcaRange()) return 0.0;
    const double s6 = std::pow(sigma / z, 6);
    // -dV/dz = 4 eps (12 s^12 / z^13 - 6 s^6 / z^7) = 24 eps (2 (s/z)^12 - (s/z)^6) / z
    return 24.0 * epsilon * (2.0 * s6 * s6 - s6) / z;
}

double TunableSlipParameters::fluidBehindForce(double z) const {
    if (!(behindDensity > 0.0)) return 0.0;
    const double x = std::max(z - sigma, 0.0) / cutoff;
    if (x >= 1.0) return 0.0;
    const double u = 1.0 - x;
    return M_PI * behindA * behindDensity * cutoff * cutoff * cutoff * u * u * u * (1.0 + 3.0 * x) / 12.0;
}

Eigen::Vector3d TunableSlipParameters::force(double z, const Eigen::Vector3d& n, const Eigen::Vector3d& vRelative,
                                             const Eigen::Vector3d& xi, double kT, double dt) const {
    Eigen::Vector3d f = (wcaForce(z) + fluidBehindForce(z)) * n;
    const double w = frictionWeight(z);
    if (w <= 0.0) return f;
    const Eigen::Vector3d bath = -gammaL * w * vRelative + std::sqrt(2.0 * kT * gammaL * w / dt) * xi;
    // Fluctuation-dissipation holds component by component, so projecting both keeps the bath at kT.
    return f + (tangentialOnly ? Eigen::Vector3d(bath - bath.dot(n) * n) : bath);
}

std::uint32_t tunableSlipStream(std::size_t wallIndex) {
    // Streams are 15 bits: 7 for the wall above the 8 of the stream's name.
    if (wallIndex >= 128) throw std::invalid_argument("at most 128 tunable-slip walls");
    return kStreamTunableSlip | static_cast<std::uint32_t>(wallIndex) << 8;
}

double tunableSlipAlpha(double gammaL, double zc, double rho, double eta) {
    if (!(gammaL > 0.0 && zc > 0.0 && rho > 0.0 && eta > 0.0))
        throw std::invalid_argument("the predicted slip length needs positive gammaL, zc, density and viscosity");
    return zc * zc * gammaL * rho / eta;
}

double predictedTunableSlipLength(double gammaL, double zc, double rho, double eta) {
    const double alpha = tunableSlipAlpha(gammaL, zc, rho, eta);
    return zc * (2.0 / alpha - 7.0 / 15.0 - 19.0 * alpha / 1800.0);
}

bool TunableSlipStripes::isGas(double coordinate) const {
    double phase = std::fmod(coordinate - offset, period);
    if (phase < 0.0) phase += period;
    return phase < gasFraction * period;
}

}  // namespace dpd
