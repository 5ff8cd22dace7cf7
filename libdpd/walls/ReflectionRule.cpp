#include "walls/ReflectionRule.hpp"

#include "walls/WallVelocityRules.hpp"

#include <iterator>
#include <stdexcept>
#include <utility>

namespace dpd {

namespace {

// Every rule by the name a dictionary gives it, in the order the names are listed to users.
constexpr std::pair<ReflectionRule, const char*> kRuleNames[] = {
    {ReflectionRule::none, "none"},
    {ReflectionRule::specular, "specular"},
    {ReflectionRule::bounceBack, "bounceBack"},
    {ReflectionRule::maxwellian, "maxwellian"},
    {ReflectionRule::bounceLayer, "bounceLayer"},
    {ReflectionRule::bounceForward, "bounceForward"},
};

}  // namespace

ReflectionRule reflectionRuleFromName(const std::string& name) {
    std::string list;
    const std::size_t n = std::size(kRuleNames);
    for (std::size_t k = 0; k < n; ++k) {
        if (name == kRuleNames[k].second) return kRuleNames[k].first;
        list += (k == 0 ? "" : (k + 1 == n ? " or " : ", ")) + std::string(kRuleNames[k].second);
    }
    throw std::invalid_argument("unknown reflection rule '" + name + "' (expected " + list + ")");
}

std::string reflectionRuleName(ReflectionRule rule) {
    for (const auto& [r, name] : kRuleNames)
        if (r == rule) return name;
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
