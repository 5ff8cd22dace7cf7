#include "walls/TunableSlipLayer.hpp"

#include "core/Axis.hpp"
#include "walls/WallBlocks.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace dpd {

TunableSlipLayer::TunableSlipLayer(const TunableSlipParameters& parameters, std::optional<TunableSlipStripes> stripes,
                                   std::size_t wallIndex)
    : parameters_(parameters), stripes_(std::move(stripes)), stream_(tunableSlipStream(wallIndex)) {}

std::string TunableSlipLayer::description() const {
    const TunableSlipParameters& t = parameters_;
    std::ostringstream os;
    os << "tunable slip (gammaL " << t.gammaL << ", zc " << t.zc << ", WCA epsilon " << t.epsilon << ", sigma "
       << t.sigma << (t.tangentialOnly ? ", friction tangential" : "");
    if (t.behindDensity > 0.0) os << ", fluid behind a " << t.behindA << " density " << t.behindDensity;
    os << ")";
    if (stripes_) {
        const TunableSlipStripes& s = *stripes_;
        os << ", stripes across " << axisLetter(s.axis) << " (period " << s.period << ", gas fraction "
           << s.gasFraction << " at gammaL " << s.gammaGas << ", offset " << s.offset << ")";
    }
    return os.str();
}

std::string TunableSlipLayer::unfitFor(const Box& box) const {
    if (!stripes_) return {};
    const TunableSlipStripes& s = *stripes_;
    const double periods = box.length()[s.axis] / s.period;
    if (std::abs(periods - std::round(periods)) <= 1e-9 * periods) return {};
    std::ostringstream os;
    os << "the box is " << box.length()[s.axis] << " long along " << axisLetter(s.axis)
       << ", not a whole number of stripe periods " << s.period << " (the stripes would not meet across the periodic boundary)";
    return os.str();
}

void TunableSlipLayer::markFlowAxes(const Box&, std::array<bool, 3>& varies) const {
    if (stripes_) varies[stripes_->axis] = true;  // the mean flow also varies across the stripes
}

double TunableSlipLayer::frictionAt(double x, double y, double z) const {
    if (!stripes_) return parameters_.gammaL;
    const TunableSlipStripes& s = *stripes_;
    const double along = s.axis == 0 ? x : (s.axis == 1 ? y : z);
    return s.isGas(along) ? s.gammaGas : parameters_.gammaL;
}

void TunableSlipLayer::addForces(WallStep& s, const WallShape& shape, const Eigen::Vector3d& wallVelocity) const {
    const TunableSlipParameters& ts = parameters_;
    const double reach = ts.reach();
    const bool threeD = s.box.isActiveAxis(1);
    Particles& p = s.particles;
    // Particle by particle only where the shape marks one within the wall's reach (WallBlocks.hpp).
    forParticlesNear(shape, p, s.frozenOfSpecies, reach, [&](std::size_t i, WallCount&) {
        const SurfaceDistance at = shape.surfaceAt({p.rx[i], p.ry[i], p.rz[i]});
        const double z = at.distance;
        if (!(z > 0.0) || z >= reach) return;
        TunableSlipParameters here = ts;
        here.gammaL = frictionAt(p.rx[i], p.ry[i], p.rz[i]);
        const Eigen::Vector3d v = s.frictionVelocity(i) - wallVelocity;
        Eigen::Vector3d xi = Eigen::Vector3d::Zero();
        if (ts.frictionWeight(z) > 0.0) {
            const auto g = s.random.particleGaussians(s.step, p.id[i], stream_);
            xi = Eigen::Vector3d(g[0], threeD ? g[1] : 0.0, g[2]);
        }
        const Eigen::Vector3d f = here.force(z, at.normal, v, xi, s.kT, s.dt);
        p.fx[i] += f.x();
        if (threeD) p.fy[i] += f.y();
        p.fz[i] += f.z();
    });
}

}  // namespace dpd
