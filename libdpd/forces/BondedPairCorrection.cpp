#include "forces/BondedPairCorrection.hpp"

#include <cmath>

namespace dpd {

namespace {

double minimumImage(double d, double length) { return d - length * std::nearbyint(d / length); }

// The factors of the three terms to take back.
struct TakenBack {
    double conservative, dissipative, random;
};

TakenBack takenBack(const BondedPairs& rule) {
    if (rule.mode == BondedPairs::Mode::none) return {1.0, 1.0, 1.0};
    if (rule.mode == BondedPairs::Mode::weighted) return {0.0, 1.0 - rule.weight, 1.0 - std::sqrt(rule.weight)};
    return {0.0, 0.0, 0.0};
}

template <class Weight>
void correct(const ChainBonds& chains, const TakenBack& back, const BondedPairScene& scene, const Weight& weight,
             const Box& box, Particles& p) {
    const DpdPairTerms<kConservativeTerm, Weight> conservative(weight, scene.parameters);
    const DpdPairTerms<kDissipativeTerm, Weight> dissipative(weight, scene.parameters);
    const DpdPairTerms<kRandomTerm, Weight> random(weight, scene.parameters);
    const double cutoff2 = scene.parameters.cutoff * scene.parameters.cutoff;
    const Eigen::Vector3d length = box.length();
    const bool threeD = box.dimension == 3;
    const Bonds& b = chains.bonds();
    const bool partOnly = chains.holdsPartOnly();
    const long nChains = static_cast<long>(chains.chainCount());
#pragma omp parallel for schedule(static)
    for (long c = 0; c < nChains; ++c)
        for (std::size_t k = chains.chainBegin(c); k < chains.chainEnd(c); ++k) {
            const std::uint32_t i = chains.indexOf(b.first[k]), j = chains.indexOf(b.second[k]);
            // A rank of a decomposed run takes its own particles' bonds; one whose other particle it
            // does not hold is longer than the cutoff (and the bond pass stops the run).
            if (partOnly && chains.here(k, i, j, p) != ChainBonds::Here::Evaluate) continue;
            const double dx = minimumImage(p.rx[i] - p.rx[j], length.x());
            const double dy = threeD ? minimumImage(p.ry[i] - p.ry[j], length.y()) : 0.0;
            const double dz = minimumImage(p.rz[i] - p.rz[j], length.z());
            const double r2 = dx * dx + dy * dy + dz * dz;
            if (!(r2 < cutoff2)) continue;
            const PairCoeffs& coeffs = scene.pairs(p.species[i], p.species[j]);
            const double rDotV = dx * (p.vx[i] - p.vx[j]) + dy * (p.vy[i] - p.vy[j]) + dz * (p.vz[i] - p.vz[j]);
            const double zeta = scene.random.pairUniform(scene.step, p.id[i], p.id[j]);
            double s = back.dissipative * dissipative.forceOverR(r2, rDotV, coeffs, zeta) +
                       back.random * random.forceOverR(r2, rDotV, coeffs, zeta);
            if (back.conservative != 0.0) s += back.conservative * conservative.forceOverR(r2, rDotV, coeffs, zeta);
            p.fx[i] -= s * dx; p.fy[i] -= s * dy; p.fz[i] -= s * dz;
            p.fx[j] += s * dx; p.fy[j] += s * dy; p.fz[j] += s * dz;
        }
}

}  // namespace

void correctBondedPairs(const ChainBonds& bonds, const BondedPairs& rule, const BondedPairScene& scene,
                        const Box& box, Particles& p) {
    if (bonds.empty() || rule.keepsAll()) return;
    const TakenBack back = takenBack(rule);
    withDpdWeight(scene.parameters, [&](auto weight) { correct(bonds, back, scene, weight, box, p); });
}

}  // namespace dpd
