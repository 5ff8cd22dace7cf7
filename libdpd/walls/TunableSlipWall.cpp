#include "walls/TunableSlipWall.hpp"

#include "core/Box.hpp"
#include "core/Particles.hpp"
#include "random/PairRandom.hpp"
#include "walls/PlanarWall.hpp"
#include "walls/WallBlocks.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace dpd {

double TunableSlipParameters::wcaRange() const { return std::pow(2.0, 1.0 / 6.0) * sigma; }

double TunableSlipParameters::frictionWeight(double z) const { return z >= 0.0 && z < zc ? 1.0 - z / zc : 0.0; }

double TunableSlipParameters::wcaForce(double z) const {
    if (!(z > 0.0) || z >= wcaRange()) return 0.0;
    const double s6 = std::pow(sigma / z, 6);
    // -dV/dz = 4 eps (12 s^12 / z^13 - 6 s^6 / z^7) = 24 eps (2 (s/z)^12 - (s/z)^6) / z
    return 24.0 * epsilon * (2.0 * s6 * s6 - s6) / z;
}

Eigen::Vector3d TunableSlipParameters::force(double z, const Eigen::Vector3d& n, const Eigen::Vector3d& vRelative,
                                             const Eigen::Vector3d& xi, double kT, double dt) const {
    Eigen::Vector3d f = wcaForce(z) * n;
    const double w = frictionWeight(z);
    if (w > 0.0) f += -gammaL * w * vRelative + std::sqrt(2.0 * kT * gammaL * w / dt) * xi;
    return f;
}

std::uint32_t tunableSlipStream(std::size_t wallIndex) {
    // Streams are 15 bits: 7 for the wall above the 8 of the stream's name.
    if (wallIndex >= 128) throw std::invalid_argument("at most 128 tunable-slip walls");
    return kStreamTunableSlip | static_cast<std::uint32_t>(wallIndex) << 8;
}

void addTunableSlipForces(const PlanarWall& w, std::size_t wallIndex, Particles& p,
                          const std::vector<std::uint8_t>& frozen, const Box& box, const PairRandom& random,
                          std::uint64_t step, double kT, double dt) {
    const TunableSlipParameters& ts = w.tunableSlip;
    const double reach = std::max(ts.zc, ts.wcaRange());
    const std::uint32_t stream = tunableSlipStream(wallIndex);
    const bool threeD = box.isActiveAxis(1);
    const long n = static_cast<long>(p.size());
    // Particle by particle only in the blocks with one within the wall's reach (WallBlocks.hpp).
#pragma omp parallel for schedule(static)
    for (long b = 0; b < n; b += kWallBlock) {
        const long e = std::min(b + kWallBlock, n);
        if (!anyWithin(w, p, b, e, reach)) continue;
        for (long i = b; i < e; ++i) {
            if (frozen[p.species[i]]) continue;
            const double z = w.signedDistance(p.rx[i], p.ry[i], p.rz[i]);
            if (!(z > 0.0) || z >= reach) continue;
            const Eigen::Vector3d v = Eigen::Vector3d(p.vx[i], p.vy[i], p.vz[i]) - w.velocity;
            Eigen::Vector3d xi = Eigen::Vector3d::Zero();
            if (ts.frictionWeight(z) > 0.0) {
                const auto g = random.particleGaussians(step, p.id[i], stream);
                xi = Eigen::Vector3d(g[0], threeD ? g[1] : 0.0, g[2]);
            }
            const Eigen::Vector3d f = ts.force(z, w.normal, v, xi, kT, dt);
            p.fx[i] += f.x();
            if (threeD) p.fy[i] += f.y();
            p.fz[i] += f.z();
        }
    }
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

}  // namespace dpd
