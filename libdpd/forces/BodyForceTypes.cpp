// The body force types a case can name: one line per type.
#include "forces/NoBodyForce.hpp"
#include "forces/ReversePoiseuilleBodyForce.hpp"
#include "forces/UniformBodyForce.hpp"

namespace dpd {

const BodyForceRegistry& bodyForceRegistry() {
    static const BodyForceRegistry types = [] {
        BodyForceRegistry r;
        r.add("none", &NoBodyForce::New);
        r.add("uniform", &UniformBodyForce::New);
        r.add("reversePoiseuille", &ReversePoiseuilleBodyForce::New);
        return r;
    }();
    return types;
}

}  // namespace dpd
