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
    const std::vector<double>& r = flowAxis == 0 ? sys.particles.rx : (flowAxis == 1 ? sys.particles.ry : sys.particles.rz);
    const double u = (r[i] - sys.box.lo[flowAxis]) / sys.box.length()[flowAxis];
    return std::min(nSlabs - 1, std::max(0, static_cast<int>(u * nSlabs)));
}

bool allFinite(const Particles& p, std::size_t i) {
    return std::isfinite(p.rx[i]) && std::isfinite(p.ry[i]) && std::isfinite(p.rz[i]) && std::isfinite(p.vx[i]) &&
           std::isfinite(p.vy[i]) && std::isfinite(p.vz[i]) && std::isfinite(p.fx[i]) && std::isfinite(p.fy[i]) &&
           std::isfinite(p.fz[i]);
}

}  // namespace

MonitorReport monitor(const System& sys, int flowAxis) {
    const Particles& p = sys.particles;
    const int nSlabs = slabCount(sys, flowAxis);
    std::vector<Eigen::Vector3d> sum(nSlabs, Eigen::Vector3d::Zero());
    std::vector<Eigen::Vector3d> sumSq(nSlabs, Eigen::Vector3d::Zero());
    std::vector<long> count(nSlabs, 0);
    MonitorReport r;
    // Serial on purpose: a few flops per particle every report interval, and the sums stay
    // independent of the thread count.
    for (std::size_t i = 0; i < p.size(); ++i) {
        if (sys.isFrozen(i)) continue;
        if (!allFinite(p, i)) { r.finite = false; continue; }
        const int s = slabOf(sys, flowAxis, nSlabs, i);
        const Eigen::Vector3d v(p.vx[i], p.vy[i], p.vz[i]);
        sum[s] += v;
        sumSq[s] += v.cwiseProduct(v);
        ++count[s];
        if (sys.walls.isInsideSolid(p.rx[i], p.ry[i], p.rz[i])) ++r.insideWalls;
    }
    double twiceKinetic = 0.0;
    long degreesOfFreedom = 0;
    for (int s = 0; s < nSlabs; ++s) {
        r.momentum += sum[s];
        r.mobile += count[s];
        if (count[s] < 2) continue;
        // sum (v - <v>)^2 = sum v^2 - (sum v)^2 / n, per component
        const Eigen::Vector3d fluct = sumSq[s] - sum[s].cwiseProduct(sum[s]) / static_cast<double>(count[s]);
        twiceKinetic += sys.box.dimension == 3 ? fluct.sum() : fluct.x() + fluct.z();
        degreesOfFreedom += sys.box.dimension * (count[s] - 1);
    }
    r.kT = degreesOfFreedom > 0 ? twiceKinetic / degreesOfFreedom : 0.0;
    if (r.mobile > 0) r.meanVelocity = r.momentum / static_cast<double>(r.mobile);
    return r;
}

}  // namespace dpd
