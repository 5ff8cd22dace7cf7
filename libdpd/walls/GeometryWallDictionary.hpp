#pragma once
// The `geometry` wall type (constant/dpdProperties' walls block): the solid of the case's geometry
// block, built on the run's box, with any reflection rule and its parameters:
//
//   walls { grains { type geometry; reflection bounceLayer; alpha 0.1; } }
#include "walls/Wall.hpp"

#include <memory>

namespace dpd {

class Dictionary;
struct WallReadContext;

std::unique_ptr<Wall> readGeometryWall(const Dictionary& dict, const WallReadContext& context);

}  // namespace dpd
