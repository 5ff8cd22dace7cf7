#include "walls/PlanarWall.hpp"

#include <cmath>
#include <stdexcept>

namespace dpd {

ReflectionRule reflectionRuleFromName(const std::string& name) {
    if (name == "none") return ReflectionRule::none;
    if (name == "specular") return ReflectionRule::specular;
    if (name == "bounceBack") return ReflectionRule::bounceBack;
    if (name == "maxwellian") return ReflectionRule::maxwellian;
    if (name == "bounceLayer") return ReflectionRule::bounceLayer;
    if (name == "bounceForward") return ReflectionRule::bounceForward;
    throw std::invalid_argument("unknown reflection rule '" + name +
                                "' (expected none, specular, bounceBack, maxwellian, bounceLayer or bounceForward)");
}

std::string reflectionRuleName(ReflectionRule rule) {
    switch (rule) {
        case ReflectionRule::none: return "none";
        case ReflectionRule::specular: return "specular";
        case ReflectionRule::bounceBack: return "bounceBack";
        case ReflectionRule::maxwellian: return "maxwellian";
        case ReflectionRule::bounceLayer: return "bounceLayer";
        case ReflectionRule::bounceForward: return "bounceForward";
    }
    return "unknown";
}

int PlanarWall::normalAxis() const {
    for (int a = 0; a < 3; ++a)
        if (std::abs(std::abs(normal[a]) - 1.0) < 1e-12) return a;
    return -1;
}

}  // namespace dpd
