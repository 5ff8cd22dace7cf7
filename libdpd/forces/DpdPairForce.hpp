#pragma once
// The DPD pair force (docs/methods.md section 1) as a small inlined evaluator.
//
//   F_ij = [ a (1 - r/rc) - gamma w_D(r) (e.v_ij) + sigma w_R(r) zeta_ij / sqrt(dt) ] e_ij
//   w_D = w_R^2,  w_R = (1 - r/rc)^(s/2),  sigma^2 = 2 gamma kT.
//
// The two template switches are fixed once per run, so a scene pays only for what it uses: no
// conservative term when every a is zero, no pow() for the standard weight (s = 2).
#include "core/Species.hpp"

#include <cmath>

namespace dpd {

struct PairForceParameters {
    double cutoff = 1.0;
    double weightExponent = 2.0;  // s in w_D = (1 - r/rc)^s
    double kT = 1.0;
    double dt = 0.01;
};

template <bool kConservative, bool kStandardWeight>
struct DpdPairEvaluator {
    double invCutoff;
    double halfExponent;  // s/2, used only for the generalised weight
    double invSqrtDt;

    explicit DpdPairEvaluator(const PairForceParameters& p)
        : invCutoff(1.0 / p.cutoff), halfExponent(0.5 * p.weightExponent), invSqrtDt(1.0 / std::sqrt(p.dt)) {}

    // Scalar force along e_ij divided by r (so F_ij = result * r_ij), for a pair at distance
    // sqrt(r2) < rc with relative velocity dv and unit-variance noise zeta.
    inline double forceOverR(double r2, double rDotV, const PairCoeffs& c, double zeta) const {
        const double r = std::sqrt(r2);
        const double invR = 1.0 / r;
        const double w = 1.0 - r * invCutoff;                        // 1 - r/rc
        const double wR = kStandardWeight ? w : std::pow(w, halfExponent);
        const double wD = wR * wR;
        double f = -c.gamma * wD * rDotV * invR + c.sigma * wR * zeta * invSqrtDt;
        if (kConservative) f += c.a * w;
        return f * invR;
    }
};

}  // namespace dpd
