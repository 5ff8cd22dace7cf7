#include "walls/PlanarWall.hpp"

#include "walls/WallBlocks.hpp"
#include "walls/WallVelocityRules.hpp"

#include <algorithm>
#include <iomanip>
#include <sstream>

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
Eigen::Vector3d mirrored(const PlanarWallSettings& w, const Particles& p, std::size_t i, double depth) {
    return Eigen::Vector3d(p.rx[i], p.ry[i], p.rz[i]) - 2.0 * depth * w.normal;
}

// The rules that act at the plane, for a particle found `depth` (< 0) behind it.
void reflectAtPlane(const PlanarWallSettings& w, double depth, WallStep& s, std::size_t i) {
    Particles& p = s.particles;
    setWrappedPosition(p, i, mirrored(w, p, i, depth), s.box);
    const Eigen::Vector3d v = velocityOf(p, i) - w.velocity;
    setVelocity(p, i, reflectedVelocity(w.rule, v, w.normal, s.box, s.random, s.step, p.id[i], s.kT, kStreamReflection) +
                          w.velocity);
}

// A bounce-layer wall on mobile particle i: in the layer and moving towards the solid, it is turned
// round; behind the plane, mirrored back, turned round and counted as a crossing.
void bounceLayerParticle(const PlanarWallSettings& w, WallStep& s, std::size_t i, WallCount& counts) {
    Particles& p = s.particles;
    const double depth = w.signedDistance(p.rx[i], p.ry[i], p.rz[i]);
    if (depth >= w.layer) return;
    if (depth < 0.0) {
        ++counts.crossed;
        reflectAtPlane(w, depth, s, i);
    } else if ((velocityOf(p, i) - w.velocity).dot(w.normal) >= 0.0) {
        return;  // in the layer but already leaving it
    } else {
        setVelocity(p, i, turnedRound(w.normal, velocityOf(p, i) - w.velocity, s.random, s.step, p.id[i], s.kT,
                                      kStreamReflection) +
                              w.velocity);
    }
    ++counts.returned;
}

// A wall whose rule acts at the plane, on mobile particle i: behind the plane, it is reflected (or,
// bounce-forward, its crossing recorded to be completed after the step) and counted.
void atPlaneParticle(const PlanarWallSettings& w, std::uint32_t wallIndex, WallStep& s, std::size_t i,
                     WallCount& counts) {
    Particles& p = s.particles;
    const double depth = w.signedDistance(p.rx[i], p.ry[i], p.rz[i]);
    if (depth >= 0.0) return;
    ++counts.crossed;
    ++counts.returned;
    if (w.rule == ReflectionRule::bounceForward) {
        const Eigen::Vector3d m = mirrored(w, p, i, depth);
#pragma omp critical(dpdDeferredCrossing)
        s.deferred.push_back({p.id[i], wallIndex, m.x(), m.y(), m.z()});
        return;
    }
    reflectAtPlane(w, depth, s, i);
}

// visit(i, counts) for the mobile particles of the blocks that hold a particle closer to wall w than
// `reach`, in parallel, then the particles of those blocks still behind the plane (unless the rule
// defers its crossings); the counts summed.
template <class Visit>
WallCount forParticlesNearWall(const PlanarWallSettings& w, WallStep& s, double reach, const Visit& visit) {
    const Particles& p = s.particles;
    const std::vector<std::uint8_t>& frozen = s.frozenOfSpecies;
    const bool deferring = w.rule == ReflectionRule::bounceForward;
    const long n = static_cast<long>(p.size());
    long returned = 0, crossed = 0, inside = 0;
#pragma omp parallel for reduction(+ : returned, crossed, inside) schedule(static)
    for (long b = 0; b < n; b += kWallBlock) {
        const long e = std::min(b + kWallBlock, n);
        if (!anyWithin(w, p, b, e, reach)) continue;
        WallCount counts;
        for (long i = b; i < e; ++i)
            if (!frozen[p.species[i]]) visit(static_cast<std::size_t>(i), counts);
        for (long i = b; i < e && !deferring; ++i)
            if (!frozen[p.species[i]] && w.signedDistance(p.rx[i], p.ry[i], p.rz[i]) < 0.0) ++counts.leftInside;
        returned += counts.returned;
        crossed += counts.crossed;
        inside += counts.leftInside;
    }
    return {returned, crossed, inside};
}

}  // namespace

PlanarWall::PlanarWall(PlanarWallSettings settings) : Wall(settings.name), settings_(std::move(settings)) {}

std::string PlanarWall::description() const {
    const PlanarWallSettings& w = settings_;
    std::ostringstream os;
    os << "reflection " << reflectionRuleName(w.rule);
    if (w.rule == ReflectionRule::bounceLayer) os << " (layer " << w.layer << ")";
    if (w.hasTunableSlip) {
        const TunableSlipParameters& t = w.tunableSlip;
        os << ", tunable slip (gammaL " << t.gammaL << ", zc " << t.zc << ", WCA epsilon " << t.epsilon << ", sigma "
           << t.sigma << (t.tangentialOnly ? ", friction tangential" : "");
        if (t.behindDensity > 0.0) os << ", fluid behind a " << t.behindA << " density " << t.behindDensity;
        os << ")";
    }
    os << std::setprecision(6) << ", velocity (" << w.velocity.x() << " " << w.velocity.y() << " " << w.velocity.z()
       << ")";
    return os.str();
}

void PlanarWall::markFlowAxes(const Box&, std::array<bool, 3>& varies) const {
    if (settings_.normalAxis() >= 0) varies[settings_.normalAxis()] = true;
}

WallCount PlanarWall::reflect(WallStep& s, std::uint32_t index) const {
    const PlanarWallSettings& w = settings_;
    if (w.rule == ReflectionRule::none)  // nothing returned: only the particles left behind it counted
        return forParticlesNearWall(w, s, 0.0, [](std::size_t, WallCount&) {});
    if (w.rule == ReflectionRule::bounceLayer)
        return forParticlesNearWall(w, s, w.layer, [&](std::size_t i, WallCount& c) { bounceLayerParticle(w, s, i, c); });
    return forParticlesNearWall(w, s, 0.0, [&](std::size_t i, WallCount& c) { atPlaneParticle(w, index, s, i, c); });
}

void PlanarWall::completeCrossing(Particles& p, std::size_t i, const DeferredCrossing& d, const Box& box) const {
    // Bounce-forward: to the mirrored position, with the velocity relative to the wall reversed (or,
    // reverseFrame lab, the velocity itself).
    setWrappedPosition(p, i, Eigen::Vector3d(d.x, d.y, d.z), box);
    const Eigen::Vector3d frame = settings_.reverseInLabFrame ? Eigen::Vector3d::Zero() : settings_.velocity;
    setVelocity(p, i, frame - (velocityOf(p, i) - frame));
}

}  // namespace dpd
