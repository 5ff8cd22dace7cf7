#include "setup/InitialConditions.hpp"

#include <cmath>

namespace dpd {

namespace {

Eigen::Vector3d randomPoint(const Box& box, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                            const PairRandom& random, std::uint64_t purpose, std::uint64_t counter) {
    const auto u = random.particleUniforms(purpose, counter, kStreamInitialPosition);
    Eigen::Vector3d r;
    for (int a = 0; a < 3; ++a) r[a] = lo[a] + u[a] * (hi[a] - lo[a]);
    if (!box.isActiveAxis(1)) r.y() = 0.5 * (box.lo.y() + box.hi.y());
    return r;
}

double regionMeasure(const Box& box, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
    const Eigen::Vector3d l = hi - lo;
    return box.dimension == 3 ? l.x() * l.y() * l.z() : l.x() * l.z();
}

}  // namespace

std::size_t fillRandom(Particles& p, const Box& box, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                       double density, int species, const RegionTest& inside, const PairRandom& random,
                       std::uint64_t firstId) {
    // Estimate the accepted fraction of the sub-box with a fixed sample, then place exactly that many.
    // The sample and the placement draw from separate counters ("purpose" 1 and 2, keyed by firstId
    // so that two regions filled with one seed differ).
    constexpr std::uint64_t kSamples = 200000;
    const std::uint64_t samplePurpose = 2 * firstId + 1, placePurpose = 2 * firstId + 2;
    std::uint64_t accepted = 0;
    for (std::uint64_t k = 0; k < kSamples; ++k) {
        const Eigen::Vector3d r = randomPoint(box, lo, hi, random, samplePurpose, k);
        accepted += inside(r.x(), r.y(), r.z()) ? 1 : 0;
    }
    const double volume = regionMeasure(box, lo, hi) * static_cast<double>(accepted) / kSamples;
    const auto target = static_cast<std::size_t>(std::llround(density * volume));
    std::size_t placed = 0;
    for (std::uint64_t k = 0; placed < target; ++k) {
        const Eigen::Vector3d r = randomPoint(box, lo, hi, random, placePurpose, k);
        if (!inside(r.x(), r.y(), r.z())) continue;
        p.add(firstId + placed, species, r.x(), r.y(), r.z());
        ++placed;
    }
    return placed;
}

void maxwellVelocities(Particles& p, std::size_t begin, std::size_t end, int dimension, double kT,
                       const PairRandom& random) {
    if (end <= begin) return;
    Eigen::Vector3d mean(0, 0, 0);
    for (std::size_t i = begin; i < end; ++i) {
        const auto g = random.particleGaussians(0, p.id[i], kStreamInitialVelocity);
        p.vx[i] = g[0];
        p.vy[i] = dimension == 3 ? g[1] : 0.0;
        p.vz[i] = g[2];
        mean += Eigen::Vector3d(p.vx[i], p.vy[i], p.vz[i]);
    }
    const double n = static_cast<double>(end - begin);
    mean /= n;
    double twiceKinetic = 0.0;
    for (std::size_t i = begin; i < end; ++i) {
        p.vx[i] -= mean.x(); p.vy[i] -= mean.y(); p.vz[i] -= mean.z();
        twiceKinetic += p.vx[i] * p.vx[i] + p.vy[i] * p.vy[i] + p.vz[i] * p.vz[i];
    }
    const double dof = dimension * (n - 1.0);
    const double scale = (twiceKinetic > 0.0 && dof > 0.0) ? std::sqrt(kT * dof / twiceKinetic) : 0.0;
    for (std::size_t i = begin; i < end; ++i) { p.vx[i] *= scale; p.vy[i] *= scale; p.vz[i] *= scale; }
}

}  // namespace dpd
