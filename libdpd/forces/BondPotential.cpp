#include "forces/BondPotential.hpp"

#include "io/Dictionary.hpp"

namespace dpd {

std::shared_ptr<const BondPotential> readBondPotential(const Dictionary& d) {
    if (!d.found("bonds")) return nullptr;
    const Dictionary& bd = d.subDict("bonds");
    const std::string type = bd.get<std::string>("type");
    if (!bondPotentialRegistry().has(type))
        bd.fail("type", "unknown bond type '" + type + "' (expected " + bondPotentialRegistry().nameList() + ")");
    return bondPotentialRegistry().make(type, bd);
}

}  // namespace dpd
