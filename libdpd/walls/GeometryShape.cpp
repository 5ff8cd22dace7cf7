#include "walls/GeometryShape.hpp"

#include "geometry/GeometryDictionary.hpp"
#include "io/Dictionary.hpp"
#include "random/PairRandom.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace dpd {

namespace {

// The shortest periodic image of a displacement.
Eigen::Vector3d minimumImage(Eigen::Vector3d d, const Box& box) {
    const Eigen::Vector3d l = box.length();
    for (int a = 0; a < 3; ++a)
        if (box.isActiveAxis(a)) d[a] -= l[a] * std::round(d[a] / l[a]);
    return d;
}

// Half the smallest grid cell along an axis the field varies along.
double probeSpacingOf(const BackgroundGrid& g) {
    double spacing = 0.0;
    for (int a = 0; a < 3; ++a)
        if (g.n[a] > 1 && (spacing == 0.0 || 0.5 * g.spacing[a] < spacing)) spacing = 0.5 * g.spacing[a];
    return spacing == 0.0 ? 0.5 * g.spacing.minCoeff() : spacing;
}

}  // namespace

GeometryShape::GeometryShape(SignedDistanceField field, double surfaceOffset)
    : field_(std::make_shared<const SignedDistanceField>(std::move(field))),
      offset_(surfaceOffset),
      probeSpacing_(probeSpacingOf(field_->grid())),
      clearance_(std::make_shared<const DistanceClearance>(*field_)) {}

GeometryShape::GeometryShape(std::shared_ptr<const Dictionary> geometryDict, double surfaceOffset)
    : geometryDict_(std::move(geometryDict)), offset_(surfaceOffset) {}

const SignedDistanceField& GeometryShape::field() const {
    if (!field_) throw std::logic_error("a geometry wall was used before it was built on the run's box");
    return *field_;
}

std::shared_ptr<WallShape> GeometryShape::builtOn(const ShapeBuildContext& c) const {
    if (field_) return nullptr;
    return std::make_shared<GeometryShape>(readSolidRegion(*geometryDict_, c.caseDir, c.box, c.cutoff).distance, offset_);
}

std::shared_ptr<WallShape> GeometryShape::ownCopy() const {
    return field_ ? std::make_shared<GeometryShape>(*this) : nullptr;
}

std::string GeometryShape::description() const {
    if (!field_) return "distance field of the geometry block";
    const BackgroundGrid& g = field_->grid();
    std::ostringstream os;
    os << "distance field " << g.n[0] << " x " << g.n[1] << " x " << g.n[2] << " cells";
    if (offset_ != 0.0) os << ", acting " << offset_ << " behind its surface";
    return os.str();
}

void GeometryShape::markFlowAxes(const Box& box, std::array<bool, 3>& varies) const {
    for (int k = 0; k < 3; ++k)
        if (field().grid().n[k] > 1 && box.isActiveAxis(k)) varies[k] = true;
}

std::uint32_t GeometryShape::reflectionStream() const { return kStreamGeometryWall; }

void GeometryShape::recordPositions(const Particles& p, const std::vector<std::uint8_t>& /*frozenOfSpecies*/) {
    const long n = static_cast<long>(p.size());
    startX_.resize(p.size());
    startY_.resize(p.size());
    startZ_.resize(p.size());
    startId_.resize(p.size());
#pragma omp parallel for schedule(static)
    for (long i = 0; i < n; ++i) {
        startX_[i] = p.rx[i];
        startY_[i] = p.ry[i];
        startZ_[i] = p.rz[i];
        startId_[i] = p.id[i];
    }
}

void GeometryShape::markWithin(const Particles& p, long begin, long end, double reach,
                               const std::vector<std::uint8_t>& frozenOfSpecies, std::uint8_t* near) const {
    const Eigen::Vector3d& span = clearance_->span();
    // The interpolated distance is a weighted mean of the table's: rounding may take it a few ulps
    // below their least.
    const double clear = reach + 1e-9 * (1.0 + std::abs(reach)) - offset_;
    for (long i = begin; i < end; ++i) {
        const std::size_t k = static_cast<std::size_t>(i);
        if (frozenOfSpecies[p.species[k]]) {  // a third of a porous box's particles, all near the surface
            near[i - begin] = 0;
            continue;
        }
        const Eigen::Vector3d r(p.rx[k], p.ry[k], p.rz[k]);
        if (!startInOrder(p, k)) {
            near[i - begin] = 1;
            continue;
        }
        const Eigen::Vector3d start(startX_[k], startY_[k], startZ_[k]);
        const bool shortStep = std::abs(r.x() - start.x()) <= span.x() && std::abs(r.y() - start.y()) <= span.y() &&
                               std::abs(r.z() - start.z()) <= span.z();
        near[i - begin] = !(shortStep && clearance_->clearanceAlong(start, r) > clear);
    }
}

GeometryShape::Entry GeometryShape::findEntry(const Eigen::Vector3d& from, const Eigen::Vector3d& delta) const {
    // Probes at equal fractions of the path, the last one at its end; a step shorter than the probe
    // spacing (the usual case) costs one lookup.
    const SignedDistanceField& f = field();
    const int probes = std::max(1, static_cast<int>(std::ceil(delta.norm() / probeSpacing_)));
    Entry entry;
    entry.fluidPoint = from;
    for (int k = 1; k <= probes; ++k) {
        const Eigen::Vector3d r = from + (static_cast<double>(k) / probes) * delta;
        const double d = f.distance(r) + offset_;
        if (k == probes) {
            entry.lastProbe = r;
            entry.distanceAtEnd = d;
        }
        if (d < 0.0) {
            entry.found = true;
            entry.atFluidPoint = shifted(f.at(entry.fluidPoint));
            return entry;
        }
        entry.fluidPoint = r;
    }
    return entry;
}

Eigen::Vector3d GeometryShape::returnPoint(const Entry& entry, const Eigen::Vector3d& end, const Box& box) const {
    // The tangent plane of the surface where the path entered, seen from the fluid it came from.
    const Eigen::Vector3d n = entry.atFluidPoint.normal;
    const Eigen::Vector3d surfacePoint = entry.fluidPoint - entry.atFluidPoint.distance * n;
    const double depth = std::min(0.0, (end - surfacePoint).dot(n));
    const Eigen::Vector3d back = end - 2.0 * depth * n;
    // A concave corner (or a normal the field could not give) can leave the mirror image in the
    // solid or behind another part of it: the last point of the path still in the fluid is safe.
    // (A particle that started the step inside, which only a failure leaves, is just mirrored.)
    const bool cameFromFluid = entry.atFluidPoint.distance >= 0.0;
    if (cameFromFluid && (n.squaredNorm() == 0.0 || findEntry(entry.fluidPoint, minimumImage(back - entry.fluidPoint, box)).found))
        return entry.fluidPoint;
    return back;
}

ShapeCrossing GeometryShape::crossing(const Particles& p, std::size_t i, const Box& box, double normalWithin,
                                      SurfaceDistance& atEnd) const {
    const Eigen::Vector3d end(p.rx[i], p.ry[i], p.rz[i]);
    const Eigen::Vector3d start = startInOrder(p, i) ? Eigen::Vector3d(startX_[i], startY_[i], startZ_[i]) : end;
    const Entry entry = findEntry(start, minimumImage(end - start, box));
    if (!entry.found) {
        atEnd = entry.distanceAtEnd < normalWithin ? shifted(field().at(entry.lastProbe))
                                                   : SurfaceDistance{entry.distanceAtEnd, {0, 0, 0}};
        return {};
    }
    return {true, returnPoint(entry, end, box), entry.atFluidPoint.normal};
}

}  // namespace dpd
