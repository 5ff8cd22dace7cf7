#pragma once
// The DPD pair force (docs/methods.md section 1), written once: the pair loop, DPD-VV's partial
// forces, Shardlow's sweep and the virial all evaluate it through the types below.
//
//   F_ij = [ a (1 - r/rc) - gamma w_D(r) (e.v_ij) + sigma w_R(r) zeta_ij / sqrt(dt) ] e_ij
//   w_D = w_R^2,  w_R = (1 - r/rc)^(s/2),  sigma^2 = 2 gamma kT.
//
// Which terms and which weight are template arguments fixed once per run, so a scene pays only for
// what it uses: no conservative term when every a is zero, no pow() for the standard weight (s = 2).
#include "core/Species.hpp"

#include <cmath>

namespace dpd {

struct PairForceParameters {
    double cutoff = 1.0;
    double weightExponent = 2.0;  // s in w_D = (1 - r/rc)^s
    double kT = 1.0;
    double dt = 0.01;
};

// The weights at a pair distance r < rc.
template <bool kStandardWeight>
struct DpdWeight {
    struct Values {
        double w;   // 1 - r/rc (the conservative weight)
        double wR;  // random weight
        double wD;  // dissipative weight, wR^2
    };
    double invCutoff;
    double halfExponent;  // s/2, used only for the generalised weight

    explicit DpdWeight(const PairForceParameters& p) : invCutoff(1.0 / p.cutoff), halfExponent(0.5 * p.weightExponent) {}

    inline Values at(double r) const {
        const double w = 1.0 - r * invCutoff;
        const double wR = kStandardWeight ? w : std::pow(w, halfExponent);
        return {w, wR, wR * wR};
    }
};

// Calls body(weight) with the DpdWeight of the run's exponent: the one place the exponent is branched on.
template <class Body>
decltype(auto) withDpdWeight(const PairForceParameters& p, Body&& body) {
    if (p.weightExponent == 2.0) return body(DpdWeight<true>(p));
    return body(DpdWeight<false>(p));
}

// The terms an evaluator adds up.
enum DpdTerm : unsigned { kConservativeTerm = 1u, kDissipativeTerm = 2u, kRandomTerm = 4u };

template <unsigned kTerms, class Weight>
struct DpdPairTerms {
    static constexpr bool kConservative = (kTerms & kConservativeTerm) != 0;
    static constexpr bool kUsesVelocity = (kTerms & kDissipativeTerm) != 0;  // the pair loop gathers v only then
    static constexpr bool kUsesRandom = (kTerms & kRandomTerm) != 0;         // and draws zeta only then
    Weight weight;
    double invSqrtDt;

    explicit DpdPairTerms(const PairForceParameters& p) : weight(p), invSqrtDt(1.0 / std::sqrt(p.dt)) {}
    explicit DpdPairTerms(const Weight& w, const PairForceParameters& p) : weight(w), invSqrtDt(1.0 / std::sqrt(p.dt)) {}

    // Scalar force along e_ij divided by r (so F_ij = result * r_ij), for a pair at distance
    // sqrt(r2) < rc with rDotV = r_ij . v_ij and unit-variance noise zeta.
    inline double forceOverR(double r2, double rDotV, const PairCoeffs& c, double zeta) const {
        const double r = std::sqrt(r2);
        const double invR = 1.0 / r;
        const typename Weight::Values wt = weight.at(r);
        double f = 0.0;
        if constexpr (kUsesVelocity && kUsesRandom) f = -c.gamma * wt.wD * rDotV * invR + c.sigma * wt.wR * zeta * invSqrtDt;
        else if constexpr (kUsesVelocity) f = -c.gamma * wt.wD * rDotV * invR;
        else if constexpr (kUsesRandom) f = c.sigma * wt.wR * zeta * invSqrtDt;
        if constexpr (kConservative) f += c.a * wt.w;
        return f * invR;
    }
};

// The whole force (the conservative term only where some a is not zero).
template <bool kConservative, bool kStandardWeight>
using DpdPairEvaluator = DpdPairTerms<kDissipativeTerm | kRandomTerm | (kConservative ? kConservativeTerm : 0u),
                                      DpdWeight<kStandardWeight>>;

}  // namespace dpd
