// The wall types a case can name: one line per type.
#include "walls/GeometryWallDictionary.hpp"
#include "walls/PlanarWallDictionary.hpp"
#include "walls/WallTypes.hpp"

namespace dpd {

const WallRegistry& wallRegistry() {
    static const WallRegistry types = [] {
        WallRegistry r;
        r.add("plane", &readPlanarWall);
        r.add("geometry", &readGeometryWall);
        return r;
    }();
    return types;
}

}  // namespace dpd
