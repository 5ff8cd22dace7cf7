#include "walls/WallSet.hpp"

#include <cmath>

namespace dpd {

namespace {

// New velocity, relative to the wall, for a particle returned by a Maxwellian (diffuse) wall: the
// tangential components are Gaussian at the wall temperature, the normal one is drawn from the
// flux-weighted (Rayleigh) distribution kT-scaled, which is what a wall at temperature kT emits.
Eigen::Vector3d diffuseVelocity(const PlanarWall& w, const Box& box, const PairRandom& random, std::uint64_t step,
                                std::uint64_t id, double kT) {
    const auto g = random.particleGaussians(step, id, kStreamReflection);
    const auto u = random.particleUniforms(step, id, kStreamReflection + 16);
    const double s = std::sqrt(kT);
    Eigen::Vector3d v(s * g[0], box.isActiveAxis(1) ? s * g[1] : 0.0, s * g[2]);
    v -= v.dot(w.normal) * w.normal;  // tangential part only
    v += s * std::sqrt(-2.0 * std::log(u[0])) * w.normal;
    return v;
}

void reflectOne(const PlanarWall& w, double depth, Particles& p, std::size_t i, const Box& box,
                const PairRandom& random, std::uint64_t step, double kT) {
    // Mirror the position across the plane (depth < 0 behind the wall).
    p.rx[i] -= 2.0 * depth * w.normal.x();
    p.ry[i] -= 2.0 * depth * w.normal.y();
    p.rz[i] -= 2.0 * depth * w.normal.z();
    for (int a = 0; a < 3; ++a) {
        double& x = a == 0 ? p.rx[i] : (a == 1 ? p.ry[i] : p.rz[i]);
        if (box.isActiveAxis(a)) x = box.wrap(x, a);
    }
    Eigen::Vector3d v(p.vx[i] - w.velocity.x(), p.vy[i] - w.velocity.y(), p.vz[i] - w.velocity.z());
    switch (w.rule) {
        case ReflectionRule::specular: v -= 2.0 * v.dot(w.normal) * w.normal; break;
        case ReflectionRule::bounceBack: v = -v; break;
        case ReflectionRule::maxwellian: v = diffuseVelocity(w, box, random, step, p.id[i], kT); break;
        case ReflectionRule::none: break;
    }
    p.vx[i] = v.x() + w.velocity.x();
    p.vy[i] = v.y() + w.velocity.y();
    p.vz[i] = v.z() + w.velocity.z();
}

}  // namespace

std::string WallSet::thinWall(const Box& box, double depth) const {
    for (const auto& w : walls_) {
        // Probe just short of `depth` behind the plane, wrapped into the box: it must still be solid.
        Eigen::Vector3d probe = w.point - w.normal * depth * 0.999;
        for (int a = 0; a < 3; ++a)
            if (box.isActiveAxis(a)) probe[a] = box.wrap(probe[a], a);
        if (!isInsideSolid(probe.x(), probe.y(), probe.z())) return w.name;
        // The plane itself must lie inside the box, not on a face: the solid behind a face wall
        // would be the fluid at the far side of the periodic box.
        const int axis = w.normalAxis();
        if (axis >= 0 && (w.point[axis] <= box.lo[axis] || w.point[axis] >= box.hi[axis])) return w.name;
    }
    return {};
}

bool WallSet::isInsideSolid(double x, double y, double z) const {
    for (const auto& w : walls_)
        if (w.signedDistance(x, y, z) < 0.0) return true;
    return false;
}

WallCounters WallSet::reflect(Particles& p, const std::vector<std::uint8_t>& frozenOfSpecies, const Box& box,
                              const PairRandom& random, std::uint64_t step, double kT) const {
    WallCounters counts;
    counts.reflected.assign(walls_.size(), 0);
    const long n = static_cast<long>(p.size());
    for (std::size_t k = 0; k < walls_.size(); ++k) {
        const PlanarWall& w = walls_[k];
        if (w.rule == ReflectionRule::none) continue;
        long reflected = 0;
#pragma omp parallel for reduction(+ : reflected) schedule(static)
        for (long i = 0; i < n; ++i) {
            if (frozenOfSpecies[p.species[i]]) continue;
            const double depth = w.signedDistance(p.rx[i], p.ry[i], p.rz[i]);
            if (depth >= 0.0) continue;
            reflectOne(w, depth, p, static_cast<std::size_t>(i), box, random, step, kT);
            ++reflected;
        }
        counts.reflected[k] = reflected;
    }
    long inside = 0;
#pragma omp parallel for reduction(+ : inside) schedule(static)
    for (long i = 0; i < n; ++i)
        if (!frozenOfSpecies[p.species[i]] && isInsideSolid(p.rx[i], p.ry[i], p.rz[i])) ++inside;
    counts.insideAfter = inside;
    return counts;
}

}  // namespace dpd
