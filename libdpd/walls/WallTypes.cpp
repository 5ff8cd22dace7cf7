// The wall types a case can name: one line per type.
#include "walls/PlanarWall.hpp"
#include "walls/WallTypes.hpp"

namespace dpd {

const WallRegistry& wallRegistry() {
    static const WallRegistry types = [] {
        WallRegistry r;
        r.add("plane", &PlanarWall::New);
        return r;
    }();
    return types;
}

}  // namespace dpd
