#include "integrators/PartialPairForces.hpp"

#include "forces/PairForceLoop.hpp"
#include "system/System.hpp"

#include <cmath>

namespace dpd {

namespace {

// a (1 - r/rc) e only.
struct ConservativePairEvaluator {
    static constexpr bool kUsesRandom = false;
    static constexpr bool kUsesVelocity = false;
    double invCutoff;
    explicit ConservativePairEvaluator(const PairForceParameters& p) : invCutoff(1.0 / p.cutoff) {}
    inline double forceOverR(double r2, double /*rDotV*/, const PairCoeffs& c, double /*zeta*/) const {
        const double r = std::sqrt(r2);
        return c.a * (1.0 - r * invCutoff) / r;
    }
};

// -gamma w_D(r) (e . v_ij) e only, with w_D = (1 - r/rc)^s.
template <bool kStandardWeight>
struct DissipativePairEvaluator {
    static constexpr bool kUsesRandom = false;
    double invCutoff;
    double exponent;
    explicit DissipativePairEvaluator(const PairForceParameters& p)
        : invCutoff(1.0 / p.cutoff), exponent(p.weightExponent) {}
    inline double forceOverR(double r2, double rDotV, const PairCoeffs& c, double /*zeta*/) const {
        const double w = 1.0 - std::sqrt(r2) * invCutoff;
        const double wD = kStandardWeight ? w * w : std::pow(w, exponent);
        return -c.gamma * wD * rDotV / r2;
    }
};

PairLoopContext contextOf(const System& sys) {
    return {sys.cells(), sys.pairs, sys.random(), static_cast<std::uint64_t>(sys.step)};
}

}  // namespace

void computeConservativeForces(System& sys) {
    sys.particles.clearForces();
    const PairForceParameters& params = sys.forceParameters;
    if (sys.usesConservativeForce())
        accumulatePairForces(sys.particles, contextOf(sys), ConservativePairEvaluator(params), params.cutoff);
    sys.bodyForce.apply(sys.particles, sys.frozenOfSpecies(), sys.box);
}

void addDissipativeForces(System& sys) {
    const PairForceParameters& params = sys.forceParameters;
    if (params.weightExponent == 2.0)
        accumulatePairForces(sys.particles, contextOf(sys), DissipativePairEvaluator<true>(params), params.cutoff);
    else
        accumulatePairForces(sys.particles, contextOf(sys), DissipativePairEvaluator<false>(params), params.cutoff);
}

}  // namespace dpd
