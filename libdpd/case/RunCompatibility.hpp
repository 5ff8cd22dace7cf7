#pragma once
// The one check pass over what a run's parts declare (core/Capabilities.hpp): before the first step,
// a part that cannot run beside the features the others bring is refused, as an InputError at the
// keyword that asked for it, naming the parts that bring them. Every tool that builds a run calls it
// with the parts it knows: the case's (integrator, walls, bonds) when dpdProperties is read, and the
// ranks and function objects with them when a run starts.
#include "core/Capabilities.hpp"

#include <string>
#include <vector>

namespace dpd {

class Dictionary;
class FunctionObjects;
struct DpdModel;

struct RunPart {
    std::string name;  // as messages name it: "Shardlow", "wall 'top' (tunableSlip)", "function 'profile'"
    Capabilities capabilities;
    const Dictionary* where = nullptr;  // the entry that asks for it (a part that refuses must have one)
    std::string keyword;                // its keyword there for a refusal that names none
    // The types the user could take instead (an integrator's): a refusal names those it would not hit.
    std::vector<RunPart> alternatives;
};

// Throws an InputError for the first refusal whose features are all present among the parts.
void checkCompatibility(const std::vector<RunPart>& parts);

// The case's parts: its integrator (with the other integrator types as alternatives), its walls and
// its bonded pairs.
std::vector<RunPart> caseParts(const DpdModel& model);
// A run decomposed over `ranks` ranks (no features on one).
RunPart ranksPart(int ranks);
// controlDict's function objects, each at its entry in `functions`.
std::vector<RunPart> functionParts(const FunctionObjects& objects, const Dictionary& functions);

}  // namespace dpd
