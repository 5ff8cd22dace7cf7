#include "forces/PairForceSums.hpp"

#include "forces/FitTo.hpp"

namespace dpd {

ForceSum* PairForceSums::prepare(std::size_t n) {
    fitTo(sums_, n);  // new entries are zero, and the old ones were left zero
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
