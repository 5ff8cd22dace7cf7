#include "forces/ReversePoiseuilleBodyForce.hpp"

#include "forces/AddBodyForce.hpp"
#include "io/Dictionary.hpp"

#include <stdexcept>

namespace dpd {

ReversePoiseuilleBodyForce::ReversePoiseuilleBodyForce(const Eigen::Vector3d& g, int gradientAxis)
    : g_(g), axis_(gradientAxis) {
    if (axis_ < 0 || axis_ > 2) throw std::invalid_argument("the gradient axis must be x, y or z");
    if (g_[axis_] != 0.0) throw std::invalid_argument("the force must be perpendicular to its gradient axis");
}

std::unique_ptr<BodyForce> ReversePoiseuilleBodyForce::New(const Dictionary& d, int dimension) {
    d.checkKeys({"type", "value", "gradientAxis"});
    const Eigen::Vector3d g = readBodyForceValue(d, dimension);
    const int axis = d.getAxis("gradientAxis");
    if (g[axis] != 0.0) d.fail("value", "must be perpendicular to gradientAxis");
    return std::make_unique<ReversePoiseuilleBodyForce>(g, axis);
}

void ReversePoiseuilleBodyForce::apply(Particles& p, const std::vector<std::uint8_t>& frozenOfSpecies,
                                       const Box& box) const {
    if (!active()) return;
    const double mid = 0.5 * (box.lo[axis_] + box.hi[axis_]);
    const double* coordinate = p.position(axis_).data();
    addBodyForce(p, frozenOfSpecies, g_, [=](long i) { return coordinate[i] >= mid ? -1.0 : 1.0; });
}

}  // namespace dpd
