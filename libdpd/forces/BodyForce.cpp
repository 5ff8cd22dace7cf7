#include "forces/BodyForce.hpp"

#include "forces/NoBodyForce.hpp"
#include "io/Dictionary.hpp"

namespace dpd {

std::shared_ptr<const BodyForce> noBodyForce() {
    static const std::shared_ptr<const BodyForce> none = std::make_shared<NoBodyForce>();
    return none;
}

Eigen::Vector3d readBodyForceValue(const Dictionary& d, int dimension) {
    const Eigen::Vector3d g = d.get<Eigen::Vector3d>("value");
    if (dimension == 2 && g.y() != 0.0) d.fail("value", "a 2-D scene lies in the x-z plane: the y component must be 0");
    return g;
}

std::shared_ptr<const BodyForce> readBodyForce(const Dictionary& d, int dimension) {
    if (!d.found("bodyForce")) return noBodyForce();
    const Dictionary& bd = d.subDict("bodyForce");
    const std::string type = bd.get<std::string>("type");
    if (!bodyForceRegistry().has(type))
        bd.fail("type", "unknown body force type '" + type + "' (expected " + bodyForceRegistry().nameList() + ")");
    return bodyForceRegistry().make(type, bd, dimension);
}

}  // namespace dpd
