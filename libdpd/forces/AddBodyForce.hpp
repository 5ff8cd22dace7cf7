#pragma once
// The pass that adds a body force to the mobile particles: gScale(i) g for particle i, scaled by its
// mobile factor (0 for a frozen particle, whose f + 0 is its f) so that the loop vectorises
// (core/MobileSpecies.hpp).
#include "core/MobileSpecies.hpp"
#include "core/Particles.hpp"

#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace dpd {

template <class Scale>
void addBodyForce(Particles& p, const std::vector<std::uint8_t>& frozenOfSpecies, const Eigen::Vector3d& g,
                  const Scale& gScale) {
    const long n = static_cast<long>(p.size());
    const std::uint8_t* species = p.species.data();
    double *fx = p.fx.data(), *fy = p.fy.data(), *fz = p.fz.data();
    const double gx = g.x(), gy = g.y(), gz = g.z();
    const auto add = [=](long i, double mobile) {
        const double s = gScale(i) * mobile;
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
