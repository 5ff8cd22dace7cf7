#include "forces/BondedPairs.hpp"

#include "io/Dictionary.hpp"

#include <cmath>
#include <sstream>

namespace dpd {

std::string BondedPairs::description() const {
    if (mode == Mode::all) return "bonded pairs feel the whole DPD force";
    if (mode == Mode::none) return "bonded pairs feel no DPD force";
    std::ostringstream os;
    os << "bonded pairs feel the DPD force with gamma x " << weight << " and sigma x " << std::sqrt(weight);
    return os.str();
}

Capabilities BondedPairs::capabilities() const {
    if (keepsAll()) return {};
    return {{Feature::velocityForce, Feature::pairForceTakenBack}, {}};
}

BondedPairs BondedPairs::read(const Dictionary& bonds) {
    BondedPairs b;
    if (!bonds.found("bondedPairs")) return b;
    const Dictionary& d = bonds.subDict("bondedPairs");
    d.checkKeys({"dpd", "weight"});
    const std::string mode = d.get<std::string>("dpd");
    if (mode == "all") b.mode = Mode::all;
    else if (mode == "none") b.mode = Mode::none;
    else if (mode == "weighted") b.mode = Mode::weighted;
    else d.fail("dpd", "must be all, none or weighted, not '" + mode + "'");
    if (b.mode == Mode::weighted) {
        b.weight = d.get<double>("weight");
        if (!(b.weight >= 0.0 && b.weight <= 1.0)) d.fail("weight", "must lie in [0, 1]");
    } else if (d.found("weight")) {
        d.fail("weight", "is read only with dpd weighted");
    }
    return b;
}

}  // namespace dpd
