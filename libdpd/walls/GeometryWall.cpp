#include "walls/GeometryWall.hpp"

#include "walls/WallVelocityRules.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace dpd {

namespace {

Eigen::Vector3d positionOf(const Particles& p, std::size_t i) { return {p.rx[i], p.ry[i], p.rz[i]}; }
Eigen::Vector3d velocityOf(const Particles& p, std::size_t i) { return {p.vx[i], p.vy[i], p.vz[i]}; }

void setPosition(Particles& p, std::size_t i, const Eigen::Vector3d& r) {
    p.rx[i] = r.x();
    p.ry[i] = r.y();
    p.rz[i] = r.z();
}

void setVelocity(Particles& p, std::size_t i, const Eigen::Vector3d& v) {
    p.vx[i] = v.x();
    p.vy[i] = v.y();
    p.vz[i] = v.z();
}

// The shortest periodic image of a displacement.
Eigen::Vector3d minimumImage(Eigen::Vector3d d, const Box& box) {
    const Eigen::Vector3d l = box.length();
    for (int a = 0; a < 3; ++a)
        if (box.isActiveAxis(a)) d[a] -= l[a] * std::round(d[a] / l[a]);
    return d;
}

}  // namespace

GeometryWall::GeometryWall(SignedDistanceField field, ReflectionRule rule, double layer)
    : Wall("geometry"), field_(std::move(field)), rule_(rule), layer_(layer) {
    if (rule_ == ReflectionRule::bounceForward)
        throw std::invalid_argument("bounceForward is for planar walls only");
    const BackgroundGrid& g = field_.grid();
    probeSpacing_ = 0.0;
    for (int a = 0; a < 3; ++a)
        if (g.n[a] > 1 && (probeSpacing_ == 0.0 || 0.5 * g.spacing[a] < probeSpacing_)) probeSpacing_ = 0.5 * g.spacing[a];
    if (probeSpacing_ == 0.0) probeSpacing_ = 0.5 * g.spacing.minCoeff();
}

std::string GeometryWall::description() const {
    std::ostringstream os;
    os << "reflection " << reflectionRuleName(rule_);
    if (rule_ == ReflectionRule::bounceLayer) os << " (layer " << layer_ << ")";
    const BackgroundGrid& g = field_.grid();
    os << ", distance field " << g.n[0] << " x " << g.n[1] << " x " << g.n[2] << " cells";
    return os.str();
}

void GeometryWall::markFlowAxes(const Box& box, std::array<bool, 3>& varies) const {
    for (int k = 0; k < 3; ++k)
        if (field_.grid().n[k] > 1 && box.isActiveAxis(k)) varies[k] = true;
}

void GeometryWall::recordPositions(const Particles& p, const std::vector<std::uint8_t>& frozen) {
    std::uint64_t maxId = 0;
    for (const std::uint64_t id : p.id) maxId = std::max(maxId, id);
    if (previous_.size() < 3 * (maxId + 1)) previous_.resize(3 * (maxId + 1), 0.0);
    const long n = static_cast<long>(p.size());
#pragma omp parallel for schedule(static)
    for (long i = 0; i < n; ++i) {
        if (frozen[p.species[i]]) continue;
        double* r = &previous_[3 * p.id[i]];
        r[0] = p.rx[i];
        r[1] = p.ry[i];
        r[2] = p.rz[i];
    }
}

GeometryWall::Entry GeometryWall::findEntry(const Eigen::Vector3d& from, const Eigen::Vector3d& delta,
                                            SurfaceDistance& atEnd) const {
    // Probes at equal fractions of the path, the last one at its end; a step shorter than the probe
    // spacing (the usual case) costs one lookup.
    const int probes = std::max(1, static_cast<int>(std::ceil(delta.norm() / probeSpacing_)));
    Entry entry;
    entry.fluidPoint = from;
    for (int k = 1; k <= probes; ++k) {
        const Eigen::Vector3d r = from + (static_cast<double>(k) / probes) * delta;
        const SurfaceDistance s = field_.at(r);
        if (k == probes) atEnd = s;
        if (s.distance < 0.0) {
            entry.found = true;
            if (k == 1) entry.atFluidPoint = field_.at(from);
            return entry;
        }
        entry.fluidPoint = r;
        entry.atFluidPoint = s;
    }
    return entry;
}

bool GeometryWall::returnParticle(Particles& p, std::size_t i, const Entry& entry, const Eigen::Vector3d& end,
                                  const Box& box, const PairRandom& random, std::uint64_t step, double kT) const {
    // The tangent plane of the surface where the path entered, seen from the fluid it came from.
    const Eigen::Vector3d n = entry.atFluidPoint.normal;
    const Eigen::Vector3d surfacePoint = entry.fluidPoint - entry.atFluidPoint.distance * n;
    const double depth = std::min(0.0, (end - surfacePoint).dot(n));
    Eigen::Vector3d back = end - 2.0 * depth * n;
    // A concave corner (or a normal the field could not give) can leave the mirror image in the
    // solid or behind another part of it: the last point of the path still in the fluid is safe.
    // (A particle that started the step inside, which only a failure leaves, is just mirrored.)
    const bool cameFromFluid = entry.atFluidPoint.distance >= 0.0;
    SurfaceDistance unused;
    if (cameFromFluid && (n.squaredNorm() == 0.0 ||
                          findEntry(entry.fluidPoint, minimumImage(back - entry.fluidPoint, box), unused).found))
        back = entry.fluidPoint;
    setPosition(p, i, back);
    if (n.squaredNorm() > 0.0)
        setVelocity(p, i, reflectedVelocity(rule_, velocityOf(p, i), n, box, random, step, p.id[i], kT, kStreamGeometryWall));
    return field_.distance(back) >= 0.0;
}

WallCount GeometryWall::reflect(WallStep& s, std::uint32_t) const {
    Particles& p = s.particles;
    const std::vector<std::uint8_t>& frozen = s.frozenOfSpecies;
    const Box& box = s.box;
    const PairRandom& random = s.random;
    const std::uint64_t step = s.step;
    const double kT = s.kT;
    const long n = static_cast<long>(p.size());
    long returned = 0, crossed = 0, inside = 0;
    const bool act = rule_ != ReflectionRule::none;
#pragma omp parallel for reduction(+ : returned, crossed, inside) schedule(static)
    for (long k = 0; k < n; ++k) {
        const std::size_t i = static_cast<std::size_t>(k);
        if (frozen[p.species[i]]) continue;
        const Eigen::Vector3d end = positionOf(p, i);
        const std::uint64_t id = p.id[i];
        const bool known = 3 * id + 2 < previous_.size();
        const Eigen::Vector3d start = known ? Eigen::Vector3d(previous_[3 * id], previous_[3 * id + 1], previous_[3 * id + 2]) : end;
        SurfaceDistance atEnd;
        const Entry entry = findEntry(start, minimumImage(end - start, box), atEnd);
        if (entry.found) {
            ++crossed;
            if (!act) { ++inside; continue; }
            ++returned;
            if (!returnParticle(p, i, entry, end, box, random, step, kT)) ++inside;
            continue;
        }
        // Bounce layer: in front of the surface and moving towards it.
        if (rule_ == ReflectionRule::bounceLayer && atEnd.distance < layer_ && atEnd.normal.squaredNorm() > 0.0 &&
            velocityOf(p, i).dot(atEnd.normal) < 0.0) {
            setVelocity(p, i, turnedRound(atEnd.normal, velocityOf(p, i), random, step, id, kT, kStreamGeometryWall));
            ++returned;
        }
    }
    return {returned, crossed, inside};
}

}  // namespace dpd
