#include "case/RunCompatibility.hpp"

#include "case/DpdProperties.hpp"
#include "io/Dictionary.hpp"
#include "sampling/FunctionObjects.hpp"

#include <stdexcept>

namespace dpd {

namespace {

Features featuresOf(const std::vector<RunPart>& parts) {
    Features all;
    for (const RunPart& p : parts) all |= p.capabilities.features;
    return all;
}

const Refusal* firstRefusal(const Capabilities& c, const Features& present) {
    for (const Refusal& r : c.refusals)
        if (present.containsAll(r.together)) return &r;
    return nullptr;
}

// "A, B and C" (lastJoin " and ") or "A, B or C" (" or ").
std::string listed(const std::vector<std::string>& names, const char* lastJoin) {
    std::string list;
    for (std::size_t k = 0; k < names.size(); ++k)
        list += (k == 0 ? "" : (k + 1 == names.size() ? lastJoin : ", ")) + names[k];
    return list;
}

// "the run on 2 ranks and wall 'top' (tunableSlip)": the parts that bring the refused features.
std::string bringing(const std::vector<RunPart>& parts, const Features& refused) {
    std::vector<std::string> names;
    for (const RunPart& p : parts)
        if (p.capabilities.features.sharesAny(refused)) names.push_back(p.name);
    return listed(names, " and ");
}

std::string insteadOf(const RunPart& part, const Features& present) {
    std::vector<std::string> fit;
    for (const RunPart& a : part.alternatives)
        if (!firstRefusal(a.capabilities, present)) fit.push_back(a.name);
    return fit.empty() ? std::string() : ": use " + listed(fit, " or ");
}

}  // namespace

void checkCompatibility(const std::vector<RunPart>& parts) {
    const Features present = featuresOf(parts);
    for (const RunPart& p : parts) {
        const Refusal* r = firstRefusal(p.capabilities, present);
        if (!r) continue;
        if (!p.where) throw std::logic_error("checkCompatibility: the part " + p.name + " refuses but has no entry");
        p.where->fail(r->keyword.empty() ? p.keyword : r->keyword,
                      p.name + " " + r->why + " (with " + bringing(parts, r->together) + ")" + insteadOf(p, present));
    }
}

std::vector<RunPart> caseParts(const DpdModel& model) {
    RunPart integrator{model.integrator.type, makeIntegrator(model.integrator)->capabilities(), &model.integrator.coeffs,
                       "type", {}};
    for (const std::string& type : integratorTypes()) {
        if (type == model.integrator.type) continue;
        const Dictionary coeffs = Dictionary::parse("type " + type + ";", "integrator");
        integrator.alternatives.push_back({type, makeIntegrator(IntegratorSettings::read(coeffs))->capabilities(), nullptr, "", {}});
    }
    std::vector<RunPart> parts{integrator};
    for (std::size_t w = 0; w < model.walls.size(); ++w) {
        const Wall& wall = model.walls[w];
        const SurfaceForce* force = wall.surfaceForce();
        parts.push_back({"wall '" + wall.name() + "' (" + (force ? force->keyword() : wall.rule().description()) + ")",
                         wall.capabilities(), nullptr, "", {}});
    }
    if (model.bondPotential) parts.push_back({"bondedPairs (" + model.bondedPairs.description() + ")", model.bondedPairs.capabilities(), nullptr, "", {}});
    return parts;
}

RunPart ranksPart(int ranks) {
    RunPart p{"the run on " + std::to_string(ranks) + " ranks", {}, nullptr, "", {}};
    if (ranks > 1) p.capabilities.features.add(Feature::severalRanks);
    return p;
}

std::vector<RunPart> functionParts(const FunctionObjects& objects, const Dictionary& functions) {
    std::vector<RunPart> parts;
    for (std::size_t k = 0; k < objects.size(); ++k) {
        const FunctionObject& f = objects[k];
        parts.push_back({"function object '" + f.name() + "'", f.capabilities(), &functions.subDict(f.name()), "type", {}});
    }
    return parts;
}

}  // namespace dpd
