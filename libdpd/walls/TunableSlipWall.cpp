#include "walls/TunableSlipWall.hpp"

#include "walls/WallBlocks.hpp"

#include <algorithm>
#include <stdexcept>

namespace dpd {

TunableSlipWall::TunableSlipWall(PlanarWallSettings settings, std::size_t index)
    : PlanarWall(std::move(settings)), stream_(tunableSlipStream(index)) {
    if (!this->settings().hasTunableSlip) throw std::invalid_argument("a tunable-slip wall needs its parameters");
}

void TunableSlipWall::addForces(WallStep& s) const {
    const PlanarWallSettings& w = settings();
    const TunableSlipParameters& ts = w.tunableSlip;
    const double reach = ts.reach();
    const bool threeD = s.box.isActiveAxis(1);
    Particles& p = s.particles;
    const long n = static_cast<long>(p.size());
    // Particle by particle only in the blocks with one within the wall's reach (WallBlocks.hpp).
#pragma omp parallel for schedule(static)
    for (long b = 0; b < n; b += kWallBlock) {
        const long e = std::min(b + kWallBlock, n);
        if (!anyWithin(w, p, b, e, reach)) continue;
        for (long i = b; i < e; ++i) {
            if (s.frozenOfSpecies[p.species[i]]) continue;
            const double z = w.signedDistance(p.rx[i], p.ry[i], p.rz[i]);
            if (!(z > 0.0) || z >= reach) continue;
            TunableSlipParameters here = ts;
            here.gammaL = frictionAt(p.rx[i], p.ry[i], p.rz[i]);
            const Eigen::Vector3d v = s.frictionVelocity(i) - w.velocity;
            Eigen::Vector3d xi = Eigen::Vector3d::Zero();
            if (ts.frictionWeight(z) > 0.0) {
                const auto g = s.random.particleGaussians(s.step, p.id[i], stream_);
                xi = Eigen::Vector3d(g[0], threeD ? g[1] : 0.0, g[2]);
            }
            const Eigen::Vector3d f = here.force(z, w.normal, v, xi, s.kT, s.dt);
            p.fx[i] += f.x();
            if (threeD) p.fy[i] += f.y();
            p.fz[i] += f.z();
        }
    }
}

}  // namespace dpd
