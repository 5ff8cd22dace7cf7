#include "system/Monitors.hpp"

#include "system/System.hpp"

#include <algorithm>
#include <cmath>

namespace dpd {

namespace {

bool allFinite(const Particles& p, std::size_t i) {
    return std::isfinite(p.rx[i]) && std::isfinite(p.ry[i]) && std::isfinite(p.rz[i]) && std::isfinite(p.vx[i]) &&
           std::isfinite(p.vy[i]) && std::isfinite(p.vz[i]) && std::isfinite(p.fx[i]) && std::isfinite(p.fy[i]) &&
           std::isfinite(p.fz[i]);
}

// A decomposed run's sums over every rank (the same on each).
void sumOverRanks(const Communicator& comm, std::vector<LocalFlowSums>& sums, MonitorReport& r) {
    constexpr std::size_t kPerCell = 1 + 3 + 9 + 3 + 3 + 9;
    std::vector<double> flat;
    flat.reserve(kPerCell * sums.size());
    for (const LocalFlowSums& c : sums) {
        flat.push_back(static_cast<double>(c.n));
        flat.insert(flat.end(), c.s.data(), c.s.data() + 3);
        flat.insert(flat.end(), c.ss.data(), c.ss.data() + 9);
        flat.insert(flat.end(), c.v.data(), c.v.data() + 3);
        flat.insert(flat.end(), c.vv.data(), c.vv.data() + 3);
        flat.insert(flat.end(), c.vs.data(), c.vs.data() + 9);
    }
    comm.sum(flat.data(), flat.size());
    const double* at = flat.data();
    for (LocalFlowSums& c : sums) {
        c.n = std::lround(*at++);
        std::copy(at, at + 3, c.s.data()); at += 3;
        std::copy(at, at + 9, c.ss.data()); at += 9;
        std::copy(at, at + 3, c.v.data()); at += 3;
        std::copy(at, at + 3, c.vv.data()); at += 3;
        std::copy(at, at + 9, c.vs.data()); at += 9;
    }
    r.insideWalls = comm.sum(r.insideWalls);
    r.finite = comm.all(r.finite);
}

}  // namespace

MonitorReport monitor(const System& sys, const FlowAxes& flow) {
    const Particles& p = sys.particles;
    const LocalFlowCells cells(sys.box, flow, sys.forceParameters.cutoff,
                               static_cast<std::size_t>(sys.sumOverRanks(static_cast<long>(sys.countMobile()))));
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
    if (sys.domain()) sumOverRanks(sys.domain()->communicator(), sums, r);
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
