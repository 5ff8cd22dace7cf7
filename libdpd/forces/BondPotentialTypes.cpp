// The bond types a case can name: one line per type.
#include "forces/FeneBond.hpp"

namespace dpd {

const BondPotentialRegistry& bondPotentialRegistry() {
    static const BondPotentialRegistry types = [] {
        BondPotentialRegistry r;
        r.add("FENE", &FeneBond::New);
        return r;
    }();
    return types;
}

}  // namespace dpd
