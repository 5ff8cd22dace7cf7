// The reflection rules a wall can name: one line per rule.
#include "walls/WallRuleTypes.hpp"

#include "io/Dictionary.hpp"
#include "walls/BounceBackRule.hpp"
#include "walls/BounceForwardRule.hpp"
#include "walls/BounceLayerRule.hpp"
#include "walls/MaxwellianRule.hpp"
#include "walls/NoReflectionRule.hpp"
#include "walls/SpecularRule.hpp"

#include <stdexcept>

namespace dpd {

namespace {

// alpha: the bounce layer's thickness in cutoffs (docs/walls.md 3.2 step 5: about 0.06-0.1 works).
std::unique_ptr<WallRule> readBounceLayer(const Dictionary& d, double cutoff) {
    return std::make_unique<BounceLayerRule>(d.getPositive<double>("alpha") * cutoff);
}

// reverseFrame wall | lab (read for every rule in readWallRule; only bounceForward may say lab).
std::unique_ptr<WallRule> readBounceForward(const Dictionary& d, double) {
    return std::make_unique<BounceForwardRule>(d.getOrDefault<std::string>("reverseFrame", "wall") == "lab");
}

template <class Rule>
std::unique_ptr<WallRule> plain(const Dictionary&, double) {
    return std::make_unique<Rule>();
}

// Every rule reverses relative to the wall (reverseFrame wall); bounceForward may do it in the lab frame.
void checkReverseFrame(const Dictionary& d, const WallRule& rule) {
    if (!d.found("reverseFrame")) return;
    const std::string frame = d.get<std::string>("reverseFrame");
    if (frame != "wall" && frame != "lab") d.fail("reverseFrame", "expected wall or lab, not '" + frame + "'");
    if (frame == "lab" && !rule.defersCrossing())
        d.fail("reverseFrame", "lab: only a wall with reflection bounceForward reverses in the lab frame");
}

}  // namespace

const WallRuleRegistry& wallRuleRegistry() {
    static const WallRuleRegistry rules = [] {
        WallRuleRegistry r;
        r.add("none", &plain<NoReflectionRule>);
        r.add("specular", &plain<SpecularRule>);
        r.add("bounceBack", &plain<BounceBackRule>);
        r.add("maxwellian", &plain<MaxwellianRule>);
        r.add("bounceLayer", &readBounceLayer);
        r.add("bounceForward", &readBounceForward);
        return r;
    }();
    return rules;
}

std::vector<std::string> wallRuleKeys() { return {"reflection", "alpha", "reverseFrame"}; }

std::shared_ptr<const WallRule> readWallRule(const Dictionary& d, const std::string& fallback, double cutoff) {
    const std::string name = d.getOrDefault<std::string>("reflection", fallback);
    if (!wallRuleRegistry().has(name))
        d.fail("reflection", "unknown reflection rule '" + name + "' (expected " + wallRuleRegistry().nameList() + ")");
    std::shared_ptr<const WallRule> rule = wallRuleRegistry().make(name, d, cutoff);
    if (d.found("alpha") && rule->layer() == 0.0)
        d.fail("alpha", "only a wall with reflection bounceLayer has a layer thickness alpha");
    checkReverseFrame(d, *rule);
    return rule;
}

}  // namespace dpd
