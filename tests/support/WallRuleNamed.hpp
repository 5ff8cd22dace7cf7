#pragma once
// For tests of walls: a reflection rule by the name a dictionary gives it, read as a case reads it.
#include "io/Dictionary.hpp"
#include "walls/WallRuleTypes.hpp"

#include <memory>
#include <sstream>
#include <string>

namespace dpd::test {

// alpha: the bounce layer's thickness (cutoff 1), used by bounceLayer only; lab: bounceForward's
// reverseFrame lab.
inline std::shared_ptr<const WallRule> ruleNamed(const std::string& name, double alpha = 0.0, bool lab = false) {
    std::ostringstream text;
    text.precision(17);
    text << "reflection " << name << ";";
    if (name == "bounceLayer") text << " alpha " << alpha << ";";
    if (lab) text << " reverseFrame lab;";
    return readWallRule(Dictionary::parse(text.str(), "test wall"), "bounceBack", 1.0);
}

}  // namespace dpd::test
