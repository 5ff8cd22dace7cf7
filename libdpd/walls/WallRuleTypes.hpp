#pragma once
// The reflection rules a wall can name (`reflection <name>;` in its dictionary): each rule reads its
// own parameters from the wall's dictionary. Adding a rule adds its files and one line in
// WallRuleTypes.cpp.
#include "core/Registry.hpp"
#include "walls/WallRule.hpp"

#include <memory>
#include <string>
#include <vector>

namespace dpd {

class Dictionary;

using WallRuleRegistry = Registry<WallRule, const Dictionary&, double /*cutoff*/>;
const WallRuleRegistry& wallRuleRegistry();

// The keys of a wall's dictionary that belong to its rule (the wall's own checkKeys allows them).
std::vector<std::string> wallRuleKeys();

// The rule the wall's dictionary names (`fallback` when it names none), with its parameters. Every
// error names the dictionary's file, line and keyword.
std::shared_ptr<const WallRule> readWallRule(const Dictionary& wallDict, const std::string& fallback, double cutoff);

}  // namespace dpd
