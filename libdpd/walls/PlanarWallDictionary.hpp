#pragma once
// The `plane` wall type (constant/dpdProperties' walls block): point, normal, velocity, the reflection
// rule and its parameters, and an optional tunableSlip block (docs/walls.md 3.5-3.6).
#include "walls/PlanarWallSettings.hpp"
#include "walls/Wall.hpp"

#include <cstddef>
#include <memory>

namespace dpd {

class Dictionary;
struct WallReadContext;

// The wall of these settings: a PlaneShape with the settings' rule, sliding at their velocity, with a
// TunableSlipLayer when they have tunable slip. index: its place in the list of walls.
std::unique_ptr<Wall> makePlanarWall(const PlanarWallSettings& settings, std::size_t index);
std::unique_ptr<Wall> readPlanarWall(const Dictionary& dict, const WallReadContext& context);

}  // namespace dpd
