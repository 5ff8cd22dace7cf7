#include "forces/PairForceSums.hpp"

namespace dpd {

ForceSum* PairForceSums::prepare(std::size_t n) {
    // No more than twice what is needed held (the benchmark runs 10^6 particles, then 32,000).
    if (sums_.capacity() > 2 * n) std::vector<ForceSum>().swap(sums_);
    sums_.resize(n);  // new entries are zero, and the old ones were left zero
    return sums_.data();
}

void PairForceSums::handTo(Particles& p, bool replace) {
    const long n = static_cast<long>(p.size());
    ForceSum* __restrict s = sums_.data();
    double* __restrict fx = p.fx.data();
    double* __restrict fy = p.fy.data();
    double* __restrict fz = p.fz.data();
    if (replace) {
#pragma omp parallel for schedule(static)
        for (long k = 0; k < n; ++k) {
            fx[k] = s[k].x; fy[k] = s[k].y; fz[k] = s[k].z;
            s[k] = ForceSum{};
        }
    } else {
#pragma omp parallel for schedule(static)
        for (long k = 0; k < n; ++k) {
            fx[k] += s[k].x; fy[k] += s[k].y; fz[k] += s[k].z;
            s[k] = ForceSum{};
        }
    }
}

PairForceSums& sharedPairForceSums() {
    static PairForceSums sums;
    return sums;
}

}  // namespace dpd
