#include "system/LocalFlowFit.hpp"

#include "system/System.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace dpd {

FlowAxes FlowAxes::along(int axis) {
    FlowAxes a;
    if (axis >= 0) a.varies[axis] = true;
    return a;
}

FlowAxes flowAxesOf(const System& sys) {
    FlowAxes a;
    for (std::size_t w = 0; w < sys.walls.size(); ++w) sys.walls[w].markFlowAxes(sys.box, a.varies);
    if (!sys.bodyForce->uniform()) a.varies[sys.bodyForce->gradientAxis()] = true;
    return a;
}

LocalFlowCells::LocalFlowCells(const Box& box, const FlowAxes& axes, double cutoff, std::size_t mobile)
    : box_(box), axes_(axes) {
    const Eigen::Vector3d L = box.length();
    const int k = axes.count();
    if (k == 0) return;
    double across = 1.0;  // the cells' measure along the active axes that do not vary
    for (int a = 0; a < 3; ++a)
        if (!axes.varies[a] && box.isActiveAxis(a)) across *= L[a];
    const double density = mobile > 0 ? static_cast<double>(mobile) / box.volume() : 0.0;
    double edge = cutoff;
    if (k > 1 && density > 0.0)
        edge = std::max(cutoff, std::pow(kParticlesPerCell / (density * across), 1.0 / k));
    for (int a = 0; a < 3; ++a) {
        if (!axes.varies[a]) continue;
        n_[a] = std::max(1, static_cast<int>(std::floor(L[a] / edge)));
        width_[a] = L[a] / n_[a];
        count_ *= static_cast<std::size_t>(n_[a]);
    }
}

int LocalFlowCells::indexAlong(int axis, double coordinate) const {
    if (!axes_.varies[axis]) return 0;
    const double u = (coordinate - box_.lo[axis]) / width_[axis];
    return std::min(n_[axis] - 1, std::max(0, static_cast<int>(std::floor(u))));
}

std::size_t LocalFlowCells::cellOf(const Eigen::Vector3d& r) const {
    const int i = indexAlong(0, r.x()), j = indexAlong(1, r.y()), k = indexAlong(2, r.z());
    return (static_cast<std::size_t>(k) * n_[1] + j) * n_[0] + i;
}

Eigen::Vector3d LocalFlowCells::offsetInCell(const Eigen::Vector3d& r, std::size_t cell) const {
    const std::array<std::size_t, 3> index{cell % n_[0], (cell / n_[0]) % n_[1], cell / (std::size_t(n_[0]) * n_[1])};
    Eigen::Vector3d offset{0, 0, 0};
    for (int a = 0; a < 3; ++a)
        if (axes_.varies[a]) offset[a] = r[a] - box_.lo[a] - (static_cast<double>(index[a]) + 0.5) * width_[a];
    return offset;
}

void LocalFlowSums::add(const Eigen::Vector3d& offset, const Eigen::Vector3d& velocity) {
    ++n;
    s += offset;
    ss += offset * offset.transpose();
    v += velocity;
    vv += velocity.cwiseProduct(velocity);
    vs += velocity * offset.transpose();
}

LocalFlowSums::Residual LocalFlowSums::residual() const {
    Residual r;
    const double dn = static_cast<double>(n);
    r.squares = vv - v.cwiseProduct(v) / dn;  // about the mean
    const Eigen::Matrix3d spread = ss - s * s.transpose() / dn;
    const Eigen::Matrix3d covariance = vs - v * (s.transpose() / dn);  // (component, axis)
    // The plane's slopes over the directions the offsets span; a direction with (almost) no spread
    // carries no slope and costs no degree of freedom.
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(spread);
    for (int d = 0; d < 3; ++d) {
        const double lambda = eigen.eigenvalues()[d];
        if (!(lambda > 1e-12 * dn)) continue;
        const Eigen::Vector3d projected = covariance * eigen.eigenvectors().col(d);
        r.squares -= projected.cwiseProduct(projected) / lambda;
        ++r.parameters;
    }
    return r;
}

}  // namespace dpd
