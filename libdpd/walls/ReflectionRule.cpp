#include "walls/ReflectionRule.hpp"

#include "walls/WallVelocityRules.hpp"

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

Eigen::Vector3d reflectedVelocity(ReflectionRule rule, const Eigen::Vector3d& v, const Eigen::Vector3d& n,
                                  const Box& box, const PairRandom& random, std::uint64_t step, std::uint64_t id,
                                  double kT, std::uint32_t stream) {
    switch (rule) {
        case ReflectionRule::specular: return v - 2.0 * v.dot(n) * n;
        case ReflectionRule::bounceBack: return -v;
        case ReflectionRule::maxwellian: return diffuseVelocity(n, box, random, step, id, kT, stream);
        case ReflectionRule::bounceLayer: return turnedRound(n, v, random, step, id, kT, stream);
        case ReflectionRule::none:
        case ReflectionRule::bounceForward: break;
    }
    return v;
}

}  // namespace dpd
