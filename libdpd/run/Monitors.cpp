#include "run/Monitors.hpp"

#include "run/System.hpp"

#include <algorithm>
#include <cmath>

namespace dpd {

namespace {

int slabCount(const System& sys, int flowAxis) {
    if (flowAxis < 0) return 1;
    const double L = sys.box.length()[flowAxis];
    return std::max(1, static_cast<int>(std::floor(L / sys.forceParameters.cutoff)));
}

int slabOf(const System& sys, int flowAxis, int nSlabs, std::size_t i) {
    if (flowAxis < 0) return 0;
    const ParticleArray<double>& r = sys.particles.position(flowAxis);
    const double u = (r[i] - sys.box.lo[flowAxis]) / sys.box.length()[flowAxis];
    return std::min(nSlabs - 1, std::max(0, static_cast<int>(u * nSlabs)));
}

bool allFinite(const Particles& p, std::size_t i) {
    return std::isfinite(p.rx[i]) && std::isfinite(p.ry[i]) && std::isfinite(p.rz[i]) && std::isfinite(p.vx[i]) &&
           std::isfinite(p.vy[i]) && std::isfinite(p.vz[i]) && std::isfinite(p.fx[i]) && std::isfinite(p.fy[i]) &&
           std::isfinite(p.fz[i]);
}

}  // namespace

namespace {

// Sums of one slab for a least-squares line v = a + b s per velocity component, s measured from the
// slab's centre so that the sums do not cancel.
struct SlabSums {
    long n = 0;
    double s = 0.0, ss = 0.0;
    Eigen::Vector3d v{0, 0, 0}, vv{0, 0, 0}, vs{0, 0, 0};

    void add(double coordinate, const Eigen::Vector3d& velocity) {
        ++n;
        s += coordinate;
        ss += coordinate * coordinate;
        v += velocity;
        vv += velocity.cwiseProduct(velocity);
        vs += velocity * coordinate;
    }
    // Sum of squared residuals about the fitted line, per component; about the mean when the slab
    // holds too few distinct coordinates for a slope.
    Eigen::Vector3d residual() const {
        const double dn = static_cast<double>(n);
        const Eigen::Vector3d aboutMean = vv - v.cwiseProduct(v) / dn;
        const double sxx = ss - s * s / dn;
        if (!(sxx > 1e-12 * dn)) return aboutMean;
        const Eigen::Vector3d sxy = vs - v * (s / dn);
        return aboutMean - sxy.cwiseProduct(sxy) / sxx;
    }
};

}  // namespace

MonitorReport monitor(const System& sys, int flowAxis) {
    const Particles& p = sys.particles;
    const int nSlabs = slabCount(sys, flowAxis);
    const double slabWidth = flowAxis < 0 ? 0.0 : sys.box.length()[flowAxis] / nSlabs;
    std::vector<SlabSums> slabs(nSlabs);
    MonitorReport r;
    // Serial on purpose: a few flops per particle every report interval, and the sums stay
    // independent of the thread count.
    for (std::size_t i = 0; i < p.size(); ++i) {
        if (sys.isFrozen(i)) continue;
        if (!allFinite(p, i)) { r.finite = false; continue; }
        const int s = slabOf(sys, flowAxis, nSlabs, i);
        const double fromCentre =
            flowAxis < 0 ? 0.0 : p.position(flowAxis)[i] - sys.box.lo[flowAxis] - (s + 0.5) * slabWidth;
        slabs[s].add(fromCentre, Eigen::Vector3d(p.vx[i], p.vy[i], p.vz[i]));
        if (sys.isInsideSolid(p.rx[i], p.ry[i], p.rz[i])) ++r.insideWalls;
    }
    double twiceKinetic = 0.0;
    long degreesOfFreedom = 0;
    const long fitted = flowAxis < 0 ? 1 : 2;  // parameters per component taken by the local flow
    for (const SlabSums& slab : slabs) {
        r.momentum += slab.v;
        r.mobile += slab.n;
        if (slab.n <= fitted) continue;
        const Eigen::Vector3d fluct = slab.residual();  // about the mean when flowAxis < 0 (all s = 0)
        twiceKinetic += sys.box.dimension == 3 ? fluct.sum() : fluct.x() + fluct.z();
        degreesOfFreedom += sys.box.dimension * (slab.n - fitted);
    }
    r.kT = degreesOfFreedom > 0 ? twiceKinetic / degreesOfFreedom : 0.0;
    if (r.mobile > 0) r.meanVelocity = r.momentum / static_cast<double>(r.mobile);
    return r;
}

}  // namespace dpd
