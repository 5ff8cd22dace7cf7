#include "forces/BodyForce.hpp"

#include "core/MobileSpecies.hpp"

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
    const double* coordinate = p.position(gradientAxis).data();
    const bool reverse = type == Type::reversePoiseuille;
    const std::uint8_t* species = p.species.data();
    double *fx = p.fx.data(), *fy = p.fy.data(), *fz = p.fz.data();
    const double gx = g.x(), gy = g.y(), gz = g.z();
    // g scaled by the particle's mobile factor (0: a frozen particle's f + 0 is its f), and by -1 in the
    // upper half of a reverse-Poiseuille box.
    const auto add = [=](long i, double mobile) {
        const double s = (reverse && coordinate[i] >= mid) ? -mobile : mobile;
        fx[i] += s * gx;
        fy[i] += s * gy;
        fz[i] += s * gz;
    };
    if (const std::optional<std::uint32_t> bits = mobileSpeciesBits(frozenOfSpecies)) {
        const std::uint32_t mobileBits = *bits;
#pragma omp parallel for simd schedule(static)
        for (long i = 0; i < n; ++i) add(i, mobileFactor(mobileBits, species[i]));
    } else {
#pragma omp parallel for schedule(static)
        for (long i = 0; i < n; ++i) add(i, frozenOfSpecies[species[i]] ? 0.0 : 1.0);
    }
}

}  // namespace dpd
