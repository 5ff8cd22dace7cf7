#pragma once
// The wall types a case can name in constant/dpdProperties' walls block (`type plane;`): each type
// reads its own sub-dictionary. Adding a type adds its files and one line in WallTypes.cpp.
#include "core/Registry.hpp"
#include "walls/Wall.hpp"

#include <cstddef>
#include <string>

namespace dpd {

class Dictionary;

// What a wall's dictionary is read against.
struct WallReadContext {
    std::string name;       // the wall's key in the walls block
    std::size_t index = 0;  // its place in the list (keeps its random streams apart)
    int dimension = 3;
    double cutoff = 1.0;
};

using WallRegistry = Registry<Wall, const Dictionary&, const WallReadContext&>;
const WallRegistry& wallRegistry();

}  // namespace dpd
