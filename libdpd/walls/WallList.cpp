#include "walls/WallList.hpp"

#include "walls/PlanarWallDictionary.hpp"

#include <algorithm>

namespace dpd {

namespace {

// The deferred crossing of a particle (the list is sorted by id), or nullptr.
const DeferredCrossing* findDeferred(const std::vector<DeferredCrossing>& deferred, std::uint64_t id) {
    const auto it = std::lower_bound(deferred.begin(), deferred.end(), id,
                                     [](const DeferredCrossing& d, std::uint64_t x) { return d.id < x; });
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

void WallList::addPlane(const PlanarWallSettings& settings) {
    add(makePlanarWall(settings, walls_.size()));
}

bool WallList::anyActsWithForces() const {
    return std::any_of(walls_.begin(), walls_.end(), [](const auto& w) { return w->actsWithForces(); });
}

bool WallList::isInsideSolid(const Eigen::Vector3d& r) const {
    return std::any_of(walls_.begin(), walls_.end(), [&](const auto& w) { return w->isInsideSolid(r); });
}

std::string WallList::thinWall(const std::vector<const PlanarWallSettings*>& planes, const Box& box, double depth) const {
    for (const PlanarWallSettings* w : planes) {
        // Probe just short of `depth` behind the plane, wrapped into the box: it must still be solid.
        Eigen::Vector3d probe = w->actingPoint() - w->normal * depth * 0.999;
        for (int a = 0; a < 3; ++a)
            if (box.isActiveAxis(a)) probe[a] = box.wrap(probe[a], a);
        if (!isInsideSolid(probe)) return w->name;
        // The plane itself must lie inside the box, not on a face: the solid behind a face wall
        // would be the fluid at the far side of the periodic box.
        const int axis = w->normalAxis();
        if (axis >= 0 && (w->actingPoint()[axis] <= box.lo[axis] || w->actingPoint()[axis] >= box.hi[axis])) return w->name;
    }
    return {};
}

std::vector<long> WallList::assignFrozenVelocities(Particles& p, const std::vector<std::uint8_t>& frozen) const {
    std::vector<long> carried(walls_.size(), 0);
    for (std::size_t i = 0; i < p.size(); ++i) {
        if (!frozen[p.species[i]]) continue;
        const Eigen::Vector3d r(p.rx[i], p.ry[i], p.rz[i]);
        int owner = -1;
        double ownerDepth = 0.0;
        for (std::size_t k = 0; k < walls_.size(); ++k) {
            if (!walls_[k]->carriesFrozenParticles()) continue;
            const double d = walls_[k]->signedDistance(r);
            if (d < 0.0 && (owner < 0 || d > ownerDepth)) {
                owner = static_cast<int>(k);
                ownerDepth = d;
            }
        }
        if (owner < 0) continue;
        const Eigen::Vector3d v = walls_[owner]->velocity();
        p.vx[i] = v.x();
        p.vy[i] = v.y();
        p.vz[i] = v.z();
        ++carried[owner];
    }
    return carried;
}

WallList::WallList(const WallList& other) {
    walls_.reserve(other.walls_.size());
    for (const auto& w : other.walls_) {
        std::shared_ptr<Wall> own = w->ownCopy();
        walls_.push_back(own ? own : w);
    }
}

WallList& WallList::operator=(const WallList& other) {
    if (this != &other) *this = WallList(other);
    return *this;
}

WallList WallList::builtOn(const ShapeBuildContext& c) const {
    WallList built;
    for (const auto& w : walls_) {
        std::shared_ptr<Wall> b = w->builtOn(c);
        built.add(b ? b : w);
    }
    return built;
}

void WallList::recordPositions(const Particles& p, const std::vector<std::uint8_t>& frozen) {
    for (const auto& w : walls_) w->recordPositions(p, frozen);
}

void WallList::addForces(WallStep& s) const {
    for (const auto& w : walls_)
        if (w->actsWithForces()) w->addForces(s);
}

WallCounters WallList::reflect(WallStep& s) const {
    WallCounters counts;
    counts.returned.assign(walls_.size(), 0);
    counts.crossed.assign(walls_.size(), 0);
    s.deferred.clear();
    for (std::size_t k = 0; k < walls_.size(); ++k) {
        const WallCount c = walls_[k]->reflect(s, static_cast<std::uint32_t>(k));
        counts.returned[k] = c.returned;
        counts.crossed[k] = c.crossed;
        counts.insideAfter += c.leftInside;
    }
    // Threads append in any order: sort so the list (and its binary search) is the same on any count.
    std::sort(s.deferred.begin(), s.deferred.end(),
              [](const DeferredCrossing& a, const DeferredCrossing& b) { return a.id < b.id; });
    return counts;
}

void WallList::completeStep(Particles& p, const std::vector<std::uint8_t>& frozen, const Box& box,
                            std::vector<DeferredCrossing>& deferred) {
    if (!deferred.empty()) {
        const long n = static_cast<long>(p.size());
#pragma omp parallel for schedule(static)
        for (long i = 0; i < n; ++i) {
            const DeferredCrossing* d = findDeferred(deferred, p.id[i]);
            if (d) walls_[d->wall]->completeCrossing(p, static_cast<std::size_t>(i), *d, box);
        }
        deferred.clear();
    }
    recordPositions(p, frozen);
}

}  // namespace dpd
