#include "walls/WallSet.hpp"

#include "walls/WallBlocks.hpp"
#include "walls/WallVelocityRules.hpp"

#include <algorithm>
#include <cmath>

namespace dpd {

namespace {

Eigen::Vector3d velocityOf(const Particles& p, std::size_t i) { return {p.vx[i], p.vy[i], p.vz[i]}; }

void setVelocity(Particles& p, std::size_t i, const Eigen::Vector3d& v) {
    p.vx[i] = v.x();
    p.vy[i] = v.y();
    p.vz[i] = v.z();
}

void setWrappedPosition(Particles& p, std::size_t i, Eigen::Vector3d r, const Box& box) {
    for (int a = 0; a < 3; ++a)
        if (box.isActiveAxis(a)) r[a] = box.wrap(r[a], a);
    p.rx[i] = r.x();
    p.ry[i] = r.y();
    p.rz[i] = r.z();
}

// The position mirrored across the plane (depth < 0 behind the wall), not wrapped.
Eigen::Vector3d mirrored(const PlanarWall& w, const Particles& p, std::size_t i, double depth) {
    return Eigen::Vector3d(p.rx[i], p.ry[i], p.rz[i]) - 2.0 * depth * w.normal;
}

// The rules that act at the plane, for a particle found `depth` (< 0) behind it.
void reflectAtPlane(const PlanarWall& w, double depth, Particles& p, std::size_t i, const Box& box,
                    const PairRandom& random, std::uint64_t step, double kT) {
    setWrappedPosition(p, i, mirrored(w, p, i, depth), box);
    const Eigen::Vector3d v = velocityOf(p, i) - w.velocity;
    setVelocity(p, i, reflectedVelocity(w.rule, v, w.normal, box, random, step, p.id[i], kT, kStreamReflection) + w.velocity);
}

struct RuleCounts {
    long returned = 0, crossed = 0;
};

// A bounce-layer wall on mobile particle i: in the layer and moving towards the solid, it is turned
// round; behind the plane, mirrored back, turned round and counted as a crossing.
void bounceLayerParticle(const PlanarWall& w, Particles& p, std::size_t i, const Box& box, const PairRandom& random,
                         std::uint64_t step, double kT, RuleCounts& counts) {
    const double depth = w.signedDistance(p.rx[i], p.ry[i], p.rz[i]);
    if (depth >= w.layer) return;
    if (depth < 0.0) {
        ++counts.crossed;
        reflectAtPlane(w, depth, p, i, box, random, step, kT);
    } else if ((velocityOf(p, i) - w.velocity).dot(w.normal) >= 0.0) {
        return;  // in the layer but already leaving it
    } else {
        setVelocity(p, i, turnedRound(w.normal, velocityOf(p, i) - w.velocity, random, step, p.id[i], kT, kStreamReflection) + w.velocity);
    }
    ++counts.returned;
}

// A wall whose rule acts at the plane, on mobile particle i: behind the plane, it is reflected (or,
// bounce-forward, its crossing recorded to be finished after the step) and counted.
void atPlaneParticle(const PlanarWall& w, std::uint32_t wallIndex, Particles& p, std::size_t i, const Box& box,
                     const PairRandom& random, std::uint64_t step, double kT, std::vector<DeferredBounce>& deferred,
                     RuleCounts& counts) {
    const double depth = w.signedDistance(p.rx[i], p.ry[i], p.rz[i]);
    if (depth >= 0.0) return;
    ++counts.crossed;
    ++counts.returned;
    if (w.rule == ReflectionRule::bounceForward) {
        const Eigen::Vector3d m = mirrored(w, p, i, depth);
#pragma omp critical(dpdDeferredBounce)
        deferred.push_back({p.id[i], wallIndex, m.x(), m.y(), m.z()});
        return;
    }
    reflectAtPlane(w, depth, p, i, box, random, step, kT);
}

// visit(i, counts) for the mobile particles of the blocks that hold a particle closer to wall w than
// `reach`, in parallel; the counts summed.
template <class Visit>
RuleCounts forParticlesNearWall(const PlanarWall& w, const Particles& p, const std::vector<std::uint8_t>& frozen,
                                double reach, const Visit& visit) {
    const long n = static_cast<long>(p.size());
    long returned = 0, crossed = 0;
#pragma omp parallel for reduction(+ : returned, crossed) schedule(static)
    for (long b = 0; b < n; b += kWallBlock) {
        const long e = std::min(b + kWallBlock, n);
        if (!anyWithin(w, p, b, e, reach)) continue;
        RuleCounts counts;
        for (long i = b; i < e; ++i)
            if (!frozen[p.species[i]]) visit(static_cast<std::size_t>(i), counts);
        returned += counts.returned;
        crossed += counts.crossed;
    }
    return {returned, crossed};
}

RuleCounts applyBounceLayer(const PlanarWall& w, Particles& p, const std::vector<std::uint8_t>& frozen,
                            const Box& box, const PairRandom& random, std::uint64_t step, double kT) {
    return forParticlesNearWall(w, p, frozen, w.layer, [&](std::size_t i, RuleCounts& counts) {
        bounceLayerParticle(w, p, i, box, random, step, kT, counts);
    });
}

RuleCounts applyAtPlane(const PlanarWall& w, std::uint32_t wallIndex, Particles& p,
                        const std::vector<std::uint8_t>& frozen, const Box& box, const PairRandom& random,
                        std::uint64_t step, double kT, std::vector<DeferredBounce>& deferred) {
    return forParticlesNearWall(w, p, frozen, 0.0, [&](std::size_t i, RuleCounts& counts) {
        atPlaneParticle(w, wallIndex, p, i, box, random, step, kT, deferred, counts);
    });
}

// The deferred crossing of a particle (the list is sorted by id), or nullptr.
const DeferredBounce* findDeferred(const std::vector<DeferredBounce>& deferred, std::uint64_t id) {
    const auto it = std::lower_bound(deferred.begin(), deferred.end(), id,
                                     [](const DeferredBounce& d, std::uint64_t x) { return d.id < x; });
    return it != deferred.end() && it->id == id ? &*it : nullptr;
}

}  // namespace

void WallCounters::accumulate(const WallCounters& o) {
    if (returned.size() < o.returned.size()) returned.resize(o.returned.size(), 0);
    if (crossed.size() < o.crossed.size()) crossed.resize(o.crossed.size(), 0);
    for (std::size_t w = 0; w < o.returned.size(); ++w) returned[w] += o.returned[w];
    for (std::size_t w = 0; w < o.crossed.size(); ++w) crossed[w] += o.crossed[w];
    insideAfter += o.insideAfter;
}

bool WallSet::anyRule(ReflectionRule rule) const {
    return std::any_of(walls_.begin(), walls_.end(), [&](const PlanarWall& w) { return w.rule == rule; });
}

bool WallSet::anyTunableSlip() const {
    return std::any_of(walls_.begin(), walls_.end(), [](const PlanarWall& w) { return w.hasTunableSlip; });
}

void WallSet::addTunableSlipForces(Particles& p, const std::vector<std::uint8_t>& frozen, const Box& box,
                                   const PairRandom& random, std::uint64_t step, double kT, double dt) const {
    for (std::size_t k = 0; k < walls_.size(); ++k)
        if (walls_[k].hasTunableSlip) dpd::addTunableSlipForces(walls_[k], k, p, frozen, box, random, step, kT, dt);
}

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

int WallSet::owningWall(double x, double y, double z) const {
    int best = -1;
    double bestDepth = 0.0;
    for (std::size_t k = 0; k < walls_.size(); ++k) {
        const double d = walls_[k].signedDistance(x, y, z);
        if (d < 0.0 && (best < 0 || d > bestDepth)) {
            best = static_cast<int>(k);
            bestDepth = d;
        }
    }
    return best;
}

std::vector<long> WallSet::assignFrozenVelocities(Particles& p, const std::vector<std::uint8_t>& frozen) const {
    std::vector<long> owned(walls_.size(), 0);
    for (std::size_t i = 0; i < p.size(); ++i) {
        if (!frozen[p.species[i]]) continue;
        const int w = owningWall(p.rx[i], p.ry[i], p.rz[i]);
        if (w < 0) continue;
        setVelocity(p, i, walls_[w].velocity);
        ++owned[w];
    }
    return owned;
}

WallCounters WallSet::reflect(Particles& p, const std::vector<std::uint8_t>& frozen, const Box& box,
                              const PairRandom& random, std::uint64_t step, double kT,
                              std::vector<DeferredBounce>& deferred) const {
    WallCounters counts;
    counts.returned.assign(walls_.size(), 0);
    counts.crossed.assign(walls_.size(), 0);
    deferred.clear();
    for (std::size_t k = 0; k < walls_.size(); ++k) {
        const PlanarWall& w = walls_[k];
        RuleCounts c;
        if (w.rule == ReflectionRule::none) continue;
        if (w.rule == ReflectionRule::bounceLayer) c = applyBounceLayer(w, p, frozen, box, random, step, kT);
        else c = applyAtPlane(w, static_cast<std::uint32_t>(k), p, frozen, box, random, step, kT, deferred);
        counts.returned[k] = c.returned;
        counts.crossed[k] = c.crossed;
    }
    // Threads append in any order: sort so the list (and its binary search) is the same on any count.
    std::sort(deferred.begin(), deferred.end(), [](const DeferredBounce& a, const DeferredBounce& b) { return a.id < b.id; });
    const long n = static_cast<long>(p.size());
    long inside = 0;
#pragma omp parallel for reduction(+ : inside) schedule(static)
    for (long b = 0; b < n; b += kWallBlock) {
        const long e = std::min(b + kWallBlock, n);
        if (std::none_of(walls_.begin(), walls_.end(), [&](const PlanarWall& w) { return anyWithin(w, p, b, e, 0.0); }))
            continue;
        for (long i = b; i < e; ++i)
            if (!frozen[p.species[i]] && isInsideSolid(p.rx[i], p.ry[i], p.rz[i]) && !findDeferred(deferred, p.id[i]))
                ++inside;
    }
    counts.insideAfter = inside;
    return counts;
}

void WallSet::completeBounceForward(Particles& p, const Box& box, const std::vector<DeferredBounce>& deferred) const {
    if (deferred.empty()) return;
    const long n = static_cast<long>(p.size());
#pragma omp parallel for schedule(static)
    for (long i = 0; i < n; ++i) {
        const DeferredBounce* it = findDeferred(deferred, p.id[i]);
        if (!it) continue;
        const std::size_t k = static_cast<std::size_t>(i);
        const PlanarWall& w = walls_[it->wall];
        setWrappedPosition(p, k, Eigen::Vector3d(it->x, it->y, it->z), box);
        setVelocity(p, k, w.velocity - (velocityOf(p, k) - w.velocity));
    }
}

}  // namespace dpd
