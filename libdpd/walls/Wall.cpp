#include "walls/Wall.hpp"

#include <stdexcept>

namespace dpd {

void Wall::completeCrossing(Particles&, std::size_t, const DeferredCrossing&, const Box&) const {
    throw std::logic_error("wall '" + name_ + "' deferred no crossing it can complete");
}

}  // namespace dpd
