#include "walls/Wall.hpp"

#include "walls/WallBlocks.hpp"

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

void setPosition(Particles& p, std::size_t i, const Eigen::Vector3d& r) {
    p.rx[i] = r.x();
    p.ry[i] = r.y();
    p.rz[i] = r.z();
}

}  // namespace

Wall::Wall(std::string name, std::shared_ptr<WallShape> shape, std::shared_ptr<const WallRule> rule)
    : name_(std::move(name)),
      shape_(std::move(shape)),
      rule_(std::move(rule)),
      layer_(rule_->layer()),
      returns_(rule_->returnsFluid()),
      defers_(rule_->defersCrossing()),
      stream_(shape_->reflectionStream()) {}

Wall& Wall::sliding(const Eigen::Vector3d& velocity) {
    velocity_ = velocity;
    carries_ = true;
    return *this;
}

Wall& Wall::withForce(std::shared_ptr<const SurfaceForce> force) {
    force_ = std::move(force);
    return *this;
}

Wall& Wall::askingSlipLength(double b) {
    askedSlipLength_ = b;
    return *this;
}

std::string Wall::description() const {
    std::ostringstream os;
    os << "reflection " << rule_->description();
    if (force_) os << ", " << force_->description();
    const std::string shape = shape_->description();
    if (!shape.empty()) os << ", " << shape;
    if (carries_)
        os << std::setprecision(6) << ", velocity (" << velocity_.x() << " " << velocity_.y() << " " << velocity_.z() << ")";
    return os.str();
}

Capabilities Wall::capabilities() const {
    Capabilities c;
    if (force_) c.features.add(Feature::velocityForce);
    if (defers_ && shape_->returnsAlong(0)) c.features.add(Feature::movesAlongXAfterSort);
    return c;
}

void Wall::markFlowAxes(const Box& box, std::array<bool, 3>& varies) const {
    shape_->markFlowAxes(box, varies);
    if (force_) force_->markFlowAxes(box, varies);
}

void Wall::addForces(WallStep& s) const {
    if (force_) force_->addForces(s, *shape_, velocity_);
}

void Wall::reflectParticle(WallStep& s, std::uint32_t index, std::size_t i, WallCount& counts) const {
    Particles& p = s.particles;
    SurfaceDistance atEnd;
    const ShapeCrossing c = shape_->crossing(p, i, s.box, layer_, atEnd);
    if (!c.found && !(atEnd.distance < layer_)) return;  // the usual case: nothing to do
    const RuleDraw draw{s.box, s.random, s.step, p.id[i], s.kT, stream_};
    if (c.found) {
        ++counts.crossed;
        if (!returns_) {
            ++counts.leftInside;
            return;
        }
        ++counts.returned;
        if (defers_) {
#pragma omp critical(dpdDeferredCrossing)
            s.deferred.push_back({p.id[i], index, c.back.x(), c.back.y(), c.back.z()});
            return;
        }
        const Eigen::Vector3d back = shape_->placed(c.back, s.box);
        setPosition(p, i, back);
        if (c.normal.squaredNorm() > 0.0)
            setVelocity(p, i, rule_->atSurface(velocityOf(p, i) - velocity_, c.normal, draw) + velocity_);
        if (shape_->signedDistance(back) < 0.0) ++counts.leftInside;
        return;
    }
    // In the rule's layer and moving towards the surface: turned round.
    if (atEnd.normal.squaredNorm() > 0.0 &&
        (velocityOf(p, i) - velocity_).dot(atEnd.normal) < 0.0) {
        setVelocity(p, i, rule_->inLayer(velocityOf(p, i) - velocity_, atEnd.normal, draw) + velocity_);
        ++counts.returned;
    }
}

WallCount Wall::reflect(WallStep& s, std::uint32_t index) const {
    return forParticlesNear(*shape_, s.particles, s.frozenOfSpecies, layer_,
                            [&](std::size_t i, WallCount& counts) { reflectParticle(s, index, i, counts); });
}

void Wall::completeCrossing(Particles& p, std::size_t i, const DeferredCrossing& d, const Box& box) const {
    Eigen::Vector3d r(d.x, d.y, d.z);
    for (int a = 0; a < 3; ++a)
        if (box.isActiveAxis(a)) r[a] = box.wrap(r[a], a);
    setPosition(p, i, r);
    setVelocity(p, i, rule_->completed(velocityOf(p, i), velocity_));
}

std::shared_ptr<Wall> Wall::withShape(std::shared_ptr<WallShape> shape) const {
    if (!shape) return nullptr;
    auto wall = std::make_shared<Wall>(*this);
    wall->shape_ = std::move(shape);
    return wall;
}

std::shared_ptr<Wall> Wall::builtOn(const ShapeBuildContext& c) const { return withShape(shape_->builtOn(c)); }

std::shared_ptr<Wall> Wall::ownCopy() const { return withShape(shape_->ownCopy()); }

}  // namespace dpd
