#pragma once
// The bond pass: for each bond, follow its vector to the particles' new positions and add the spring
// force of the evaluator (one small struct per potential, e.g. FeneEvaluator) to both particles.
#include "core/Box.hpp"
#include "forces/ChainBonds.hpp"

#include <algorithm>
#include <cmath>

namespace dpd {

// The new bond vector component: the positions' difference shifted by the whole box lengths that keep
// it nearest the previous vector. A bond changes by far less than half a box length in a step, so this
// follows it through the periodic boundary even when it is longer than half the box.
inline double followedComponent(double previous, double difference, double length) {
    return difference - length * std::nearbyint((difference - previous) / length);
}

// PartOnly: a rank of a decomposed run, which takes only the bonds of its own particles
// (ChainBonds::here); a bond whose other particle it does not hold is broken, of unknown length.
template <bool PartOnly, class Evaluator>
BondPassResult bondPass(ChainBonds& chains, Particles& p, const Box& box, const Evaluator& eval, double maxLength2) {
    Bonds& b = chains.bonds();
    const Eigen::Vector3d length = box.length();
    const bool threeD = box.dimension == 3;  // in 2-D every particle has the same y
    double longest2 = 0.0;
    long broken = -1;
    bool brokenUnseen = false;  // the first broken bond's other particle is not held here
    const long nChains = static_cast<long>(chains.chainCount());
#pragma omp parallel for schedule(static) reduction(max : longest2)
    for (long c = 0; c < nChains; ++c)
        for (std::size_t k = chains.chainBegin(c); k < chains.chainEnd(c); ++k) {
            const std::uint32_t i = chains.indexOf(b.first[k]), j = chains.indexOf(b.second[k]);
            if constexpr (PartOnly) {
                const ChainBonds::Here here = chains.here(k, i, j, p);
                if (here == ChainBonds::Here::Skip) continue;
                if (here == ChainBonds::Here::Beyond) {
#pragma omp critical(dpdBrokenBond)
                    if (broken < 0 || static_cast<long>(k) < broken) {
                        broken = static_cast<long>(k);
                        brokenUnseen = true;
                    }
                    continue;
                }
            }
            const double bx = followedComponent(b.bx[k], p.rx[j] - p.rx[i], length.x());
            const double by = threeD ? followedComponent(b.by[k], p.ry[j] - p.ry[i], length.y()) : 0.0;
            const double bz = followedComponent(b.bz[k], p.rz[j] - p.rz[i], length.z());
            b.bx[k] = bx;
            b.by[k] = by;
            b.bz[k] = bz;
            const double r2 = bx * bx + by * by + bz * bz;
            if (!(r2 < maxLength2)) {  // NaN too
#pragma omp critical(dpdBrokenBond)
                if (broken < 0 || static_cast<long>(k) < broken) {
                    broken = static_cast<long>(k);
                    brokenUnseen = false;
                }
                continue;
            }
            longest2 = std::max(longest2, r2);
            const double f = eval.forceOverR(r2);
            p.fx[j] += f * bx; p.fy[j] += f * by; p.fz[j] += f * bz;
            p.fx[i] -= f * bx; p.fy[i] -= f * by; p.fz[i] -= f * bz;
        }
    BondPassResult result;
    result.longest2 = longest2;
    result.broken = broken;
    if (broken >= 0) result.brokenLength = brokenUnseen ? kUnseenBondLength : b.vector(static_cast<std::size_t>(broken)).norm();
    return result;
}

template <class Evaluator>
BondPassResult accumulateBondForces(ChainBonds& chains, Particles& p, const Box& box, const Evaluator& eval,
                                    double maxLength2) {
    return chains.holdsPartOnly() ? bondPass<true>(chains, p, box, eval, maxLength2)
                                  : bondPass<false>(chains, p, box, eval, maxLength2);
}

}  // namespace dpd
