#include "forces/NoBodyForce.hpp"

#include "io/Dictionary.hpp"

namespace dpd {

std::unique_ptr<BodyForce> NoBodyForce::New(const Dictionary& d, int) {
    d.checkKeys({"type"});
    return std::make_unique<NoBodyForce>();
}

}  // namespace dpd
