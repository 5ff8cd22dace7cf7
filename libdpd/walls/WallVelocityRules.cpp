#include "walls/WallVelocityRules.hpp"

#include <cmath>

namespace dpd {

double emittedNormalSpeed(const PairRandom& random, std::uint64_t step, std::uint64_t id, double kT,
                          std::uint32_t stream) {
    const auto u = random.particleUniforms(step, id, stream + 16);
    return std::sqrt(kT) * std::sqrt(-2.0 * std::log(u[0]));
}

Eigen::Vector3d diffuseVelocity(const Eigen::Vector3d& normal, const Box& box, const PairRandom& random,
                                std::uint64_t step, std::uint64_t id, double kT, std::uint32_t stream) {
    const auto g = random.particleGaussians(step, id, stream);
    const double s = std::sqrt(kT);
    Eigen::Vector3d v(s * g[0], box.isActiveAxis(1) ? s * g[1] : 0.0, s * g[2]);
    v -= v.dot(normal) * normal;  // tangential part only
    return v + emittedNormalSpeed(random, step, id, kT, stream) * normal;
}

Eigen::Vector3d turnedRound(const Eigen::Vector3d& normal, const Eigen::Vector3d& relative, const PairRandom& random,
                            std::uint64_t step, std::uint64_t id, double kT, std::uint32_t stream) {
    const Eigen::Vector3d tangential = relative - relative.dot(normal) * normal;
    return -tangential + emittedNormalSpeed(random, step, id, kT, stream) * normal;
}

}  // namespace dpd
