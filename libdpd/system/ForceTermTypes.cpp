// The force terms after the DPD pair force: one line per term, in the order their forces are added
// (the order of the sums fixes a run's bits).
#include "system/BodyForceTerm.hpp"
#include "system/BondForceTerm.hpp"
#include "system/BondedPairCorrectionTerm.hpp"
#include "system/WallForceTerm.hpp"

namespace dpd {

const ForceTermRegistry& forceTermRegistry() {
    static const ForceTermRegistry terms = [] {
        ForceTermRegistry r;
        r.add("bondedPairCorrection", &BondedPairCorrectionTerm::New);
        r.add("bodyForce", &BodyForceTerm::New);
        r.add("bonds", &BondForceTerm::New);
        r.add("wallForces", &WallForceTerm::New);
        return r;
    }();
    return terms;
}

}  // namespace dpd
