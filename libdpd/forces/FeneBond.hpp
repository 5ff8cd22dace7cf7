#pragma once
// `type FENE; H 6; rMax 3;`: the finitely extensible nonlinear elastic spring,
//   F = -H r / (1 - (r/r_max)^2),   U = -(H r_max^2 / 2) ln(1 - (r/r_max)^2),
// harmonic (stiffness H) for short bonds and impossible to stretch to r_max.
#include "forces/BondPotential.hpp"

namespace dpd {

struct FeneEvaluator {
    double H;
    double invMaxLength2;
    // F_second / r (negative: the spring pulls the second particle back towards the first).
    double forceOverR(double r2) const { return -H / (1.0 - r2 * invMaxLength2); }
};

class FeneBond : public BondPotential {
public:
    FeneBond(double H, double maxLength) : H_(H), maxLength_(maxLength) {}
    static std::unique_ptr<BondPotential> New(const Dictionary& d);
    std::string typeName() const override { return "FENE"; }
    std::string description() const override;
    double maxLength() const override { return maxLength_; }
    double energy(double r) const override;
    double forceOverR(double r2) const override { return evaluator().forceOverR(r2); }
    BondPassResult addForces(ChainBonds& bonds, Particles& p, const Box& box) const override;
    double H() const { return H_; }

private:
    FeneEvaluator evaluator() const { return {H_, 1.0 / (maxLength_ * maxLength_)}; }
    double H_;
    double maxLength_;
};

}  // namespace dpd
