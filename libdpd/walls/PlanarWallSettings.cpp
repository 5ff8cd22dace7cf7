#include "walls/PlanarWallSettings.hpp"

#include <cmath>
#include <stdexcept>

namespace dpd {

int PlanarWallSettings::normalAxis() const {
    for (int a = 0; a < 3; ++a)
        if (std::abs(std::abs(normal[a]) - 1.0) < 1e-12) return a;
    return -1;
}

}  // namespace dpd
