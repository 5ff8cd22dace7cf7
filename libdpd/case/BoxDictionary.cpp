#include "case/BoxDictionary.hpp"

#include "core/Axis.hpp"
#include "io/Dictionary.hpp"

#include <string>

namespace dpd {

Box readBoxDictionary(const Dictionary& d, int dimension, double cutoff) {
    const Dictionary& bd = d.subDict("box");
    bd.checkKeys({"min", "max"});
    Box box;
    box.dimension = dimension;
    box.lo = bd.get<Eigen::Vector3d>("min");
    box.hi = bd.get<Eigen::Vector3d>("max");
    if (dimension == 2) { box.lo.y() = -0.5; box.hi.y() = 0.5; }  // nominal: the y axis is inactive
    for (int a = 0; a < 3; ++a) {
        if (!box.isActiveAxis(a)) continue;
        if (!(box.hi[a] - box.lo[a] >= 2.0 * cutoff))
            bd.fail("max", std::string("the box must be at least two cutoffs long along ") + axisLetter(a));
    }
    return box;
}

}  // namespace dpd
