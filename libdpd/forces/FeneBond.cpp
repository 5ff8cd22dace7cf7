#include "forces/FeneBond.hpp"

#include "forces/BondForceLoop.hpp"
#include "io/Dictionary.hpp"

#include <cmath>
#include <sstream>

namespace dpd {

std::unique_ptr<BondPotential> FeneBond::New(const Dictionary& d) {
    d.checkKeys({"type", "H", "rMax", "bondedPairs"});
    return std::make_unique<FeneBond>(d.getPositive<double>("H"), d.getPositive<double>("rMax"));
}

std::string FeneBond::description() const {
    std::ostringstream os;
    os << "FENE, H " << H_ << ", rMax " << maxLength_;
    return os.str();
}

double FeneBond::energy(double r) const {
    const double x = r / maxLength_;
    return -0.5 * H_ * maxLength_ * maxLength_ * std::log1p(-x * x);
}

BondPassResult FeneBond::addForces(ChainBonds& bonds, Particles& p, const Box& box) const {
    return accumulateBondForces(bonds, p, box, evaluator(), maxLength_ * maxLength_);
}

}  // namespace dpd
