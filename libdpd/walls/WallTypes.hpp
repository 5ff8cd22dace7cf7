#pragma once
// The wall types a case can name in constant/dpdProperties' walls block (`type plane;`, `type geometry;`): each type
// reads its own sub-dictionary. Adding a type adds its files and one line in WallTypes.cpp.
#include "core/Registry.hpp"
#include "walls/PlanarWallSettings.hpp"
#include "walls/SlipLengthResolver.hpp"
#include "walls/Wall.hpp"

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace dpd {

class Dictionary;

// What a wall's dictionary is read against.
struct WallReadContext {
    std::string name;       // the wall's key in the walls block
    std::size_t index = 0;  // its place in the list (keeps its random streams apart)
    int dimension = 3;
    double cutoff = 1.0;
    std::shared_ptr<const Dictionary> geometry;  // the case's geometry block (null: none)
    // Where a planar wall leaves its settings, for the builders and post-processing that fit channels
    // between planes (null: nowhere).
    std::vector<PlanarWallSettings>* planes = nullptr;
    // What a wall that asks for a slip length is resolved against (null: such a wall is refused), and
    // where it says what was chosen, for the log.
    const SlipLengthResolver* slipLengths = nullptr;
    std::vector<std::string>* notes = nullptr;
};

using WallRegistry = Registry<Wall, const Dictionary&, const WallReadContext&>;
const WallRegistry& wallRegistry();

}  // namespace dpd
