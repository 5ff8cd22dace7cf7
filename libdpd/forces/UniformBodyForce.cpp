#include "forces/UniformBodyForce.hpp"

#include "forces/AddBodyForce.hpp"
#include "io/Dictionary.hpp"

namespace dpd {

std::unique_ptr<BodyForce> UniformBodyForce::New(const Dictionary& d, int dimension) {
    d.checkKeys({"type", "value"});
    return std::make_unique<UniformBodyForce>(readBodyForceValue(d, dimension));
}

void UniformBodyForce::apply(Particles& p, const std::vector<std::uint8_t>& frozenOfSpecies, const Box&) const {
    if (!active()) return;
    addBodyForce(p, frozenOfSpecies, g_, [](long) { return 1.0; });
}

}  // namespace dpd
