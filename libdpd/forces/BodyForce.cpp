#include "forces/BodyForce.hpp"

#include <stdexcept>

namespace dpd {

BodyForce::Type bodyForceTypeFromName(const std::string& name) {
    if (name == "none") return BodyForce::Type::none;
    if (name == "uniform") return BodyForce::Type::uniform;
    if (name == "reversePoiseuille") return BodyForce::Type::reversePoiseuille;
    throw std::invalid_argument("unknown body force type '" + name + "' (expected none, uniform or reversePoiseuille)");
}

Eigen::Vector3d BodyForce::at(double coordinate, const Box& box) const {
    if (type == Type::none) return Eigen::Vector3d::Zero();
    if (type == Type::uniform) return g;
    const double mid = 0.5 * (box.lo[gradientAxis] + box.hi[gradientAxis]);
    return coordinate < mid ? g : Eigen::Vector3d(-g);
}

void BodyForce::apply(Particles& p, const std::vector<std::uint8_t>& frozenOfSpecies, const Box& box) const {
    if (!active()) return;
    const long n = static_cast<long>(p.size());
    const double mid = 0.5 * (box.lo[gradientAxis] + box.hi[gradientAxis]);
    const std::vector<double>& coordinate = p.position(gradientAxis);
    const bool reverse = type == Type::reversePoiseuille;
#pragma omp parallel for schedule(static)
    for (long i = 0; i < n; ++i) {
        if (frozenOfSpecies[p.species[i]]) continue;
        const double sign = (reverse && coordinate[i] >= mid) ? -1.0 : 1.0;
        p.fx[i] += sign * g.x();
        p.fy[i] += sign * g.y();
        p.fz[i] += sign * g.z();
    }
}

}  // namespace dpd
