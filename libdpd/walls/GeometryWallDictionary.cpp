#include "walls/GeometryWallDictionary.hpp"

#include "io/Dictionary.hpp"
#include "walls/GeometryShape.hpp"
#include "walls/WallRuleTypes.hpp"
#include "walls/WallTypes.hpp"

#include <vector>

namespace dpd {

std::unique_ptr<Wall> readGeometryWall(const Dictionary& d, const WallReadContext& c) {
    std::vector<std::string> keys{"type"};
    for (const std::string& k : wallRuleKeys()) keys.push_back(k);
    d.checkKeys(keys);
    if (!c.geometry) d.fail("type", "a geometry wall needs the geometry block it acts on (constant/dpdProperties' geometry)");
    return std::make_unique<Wall>(c.name, std::make_shared<GeometryShape>(c.geometry), readWallRule(d, "bounceBack", c.cutoff));
}

}  // namespace dpd
