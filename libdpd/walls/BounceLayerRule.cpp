#include "walls/BounceLayerRule.hpp"

#include <sstream>
#include <stdexcept>

namespace dpd {

BounceLayerRule::BounceLayerRule(double layer) : layer_(layer) {
    if (!(layer > 0.0)) throw std::invalid_argument("a bounce layer needs a positive thickness");
}

std::string BounceLayerRule::description() const {
    std::ostringstream os;
    os << "bounceLayer (layer " << layer_ << ")";
    return os.str();
}

}  // namespace dpd
