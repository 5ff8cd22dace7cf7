#include "system/Monitors.hpp"

#include "system/System.hpp"

#include <cmath>

namespace dpd {

namespace {

bool allFinite(const Particles& p, std::size_t i) {
    return std::isfinite(p.rx[i]) && std::isfinite(p.ry[i]) && std::isfinite(p.rz[i]) && std::isfinite(p.vx[i]) &&
           std::isfinite(p.vy[i]) && std::isfinite(p.vz[i]) && std::isfinite(p.fx[i]) && std::isfinite(p.fy[i]) &&
           std::isfinite(p.fz[i]);
}

}  // namespace

MonitorReport monitor(const System& sys, const FlowAxes& flow) {
    const Particles& p = sys.particles;
    const LocalFlowCells cells(sys.box, flow, sys.forceParameters.cutoff, sys.countMobile());
    std::vector<LocalFlowSums> sums(cells.count());
    MonitorReport r;
    // Serial on purpose: a few flops per particle every report interval, and the sums stay
    // independent of the thread count.
    for (std::size_t i = 0; i < p.size(); ++i) {
        if (sys.isFrozen(i)) continue;
        if (!allFinite(p, i)) { r.finite = false; continue; }
        const Eigen::Vector3d position(p.rx[i], p.ry[i], p.rz[i]);
        const std::size_t c = cells.cellOf(position);
        sums[c].add(cells.offsetInCell(position, c), Eigen::Vector3d(p.vx[i], p.vy[i], p.vz[i]));
        if (sys.isInsideSolid(p.rx[i], p.ry[i], p.rz[i])) ++r.insideWalls;
    }
    double twiceKinetic = 0.0;
    long degreesOfFreedom = 0;
    for (const LocalFlowSums& cell : sums) {
        r.momentum += cell.v;
        r.mobile += cell.n;
        if (cell.n == 0) continue;
        const LocalFlowSums::Residual fluct = cell.residual();
        if (cell.n <= fluct.parameters) continue;
        twiceKinetic += sys.box.dimension == 3 ? fluct.squares.sum() : fluct.squares.x() + fluct.squares.z();
        degreesOfFreedom += sys.box.dimension * (cell.n - fluct.parameters);
    }
    r.kT = degreesOfFreedom > 0 ? twiceKinetic / degreesOfFreedom : 0.0;
    if (r.mobile > 0) r.meanVelocity = r.momentum / static_cast<double>(r.mobile);
    return r;
}

MonitorReport monitor(const System& sys, int flowAxis) { return monitor(sys, FlowAxes::along(flowAxis)); }

}  // namespace dpd
