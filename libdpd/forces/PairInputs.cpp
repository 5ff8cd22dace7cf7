#include "forces/PairInputs.hpp"

#include "forces/FitTo.hpp"

#include <algorithm>
#include <array>
#include <type_traits>

namespace dpd {

std::size_t PairInputs::capacityBytes() const {
    return sizeof(float) * (x.capacity() + y.capacity() + z.capacity()) + sizeof(PairKinematics) * kinematics.capacity();
}

void fillPairInputs(const Particles& p, const CellList& cells, bool velocities, bool ids, PairInputs& in) {
    const std::size_t n = p.size();
    fitTo(in.x, n + kPairInputPadding); fitTo(in.y, n + kPairInputPadding); fitTo(in.z, n + kPairInputPadding);
    if (velocities || ids) fitTo(in.kinematics, n);
    const Eigen::Vector3d& h = cells.cellSize();
    const Eigen::Vector3d& lo = cells.box().lo;
    in.cellX = static_cast<float>(h.x()); in.cellY = static_cast<float>(h.y()); in.cellZ = static_cast<float>(h.z());
    // Each particle's cell found again from its position, as the sort found it (the same arithmetic on
    // the same wrapped positions): one flat loop the compiler vectorises, not one per cell.
    const double* __restrict rx = p.rx.data();
    const double* __restrict ry = p.ry.data();
    const double* __restrict rz = p.rz.data();
    float* __restrict x = in.x.data();
    float* __restrict y = in.y.data();
    float* __restrict z = in.z.data();
#pragma omp parallel for schedule(static)
    for (std::size_t k = 0; k < n; ++k) {
        x[k] = static_cast<float>(rx[k] - (lo.x() + cells.axisCell(rx[k], 0) * h.x()));
        y[k] = static_cast<float>(ry[k] - (lo.y() + cells.axisCell(ry[k], 1) * h.y()));
        z[k] = static_cast<float>(rz[k] - (lo.z() + cells.axisCell(rz[k], 2) * h.z()));
    }
    if (!velocities && !ids) return;
    // Velocities and ids in one pass, each entry written whole (the part not asked for kept).
    PairKinematics* __restrict kin = in.kinematics.data();
#pragma omp parallel for schedule(static)
    for (std::size_t k = 0; k < n; ++k) {
        PairKinematics e = kin[k];
        if (velocities) {
            e.vx = static_cast<float>(p.vx[k]);
            e.vy = static_cast<float>(p.vy[k]);
            e.vz = static_cast<float>(p.vz[k]);
        }
        if (ids) e.id = static_cast<std::uint32_t>(p.id[k]);
        kin[k] = e;
    }
}

void fillPredictedVelocities(const Particles& p, double shift, const std::vector<std::uint8_t>* frozenOfSpecies,
                             const std::uint32_t* forceOrder, bool ids, PairInputs& in) {
    const std::size_t n = p.size();
    fitTo(in.kinematics, n);
    const double* __restrict fx = p.fx.data();
    const double* __restrict fy = p.fy.data();
    const double* __restrict fz = p.fz.data();
    const double* __restrict vx = p.vx.data();
    const double* __restrict vy = p.vy.data();
    const double* __restrict vz = p.vz.data();
    const std::uint64_t* __restrict id = p.id.data();
    PairKinematics* __restrict kin = in.kinematics.data();
    // Per species: v + 0 f is v exactly (forces are finite), so a frozen particle's velocity passes as it is.
    std::array<double, 256> shiftOf;
    shiftOf.fill(shift);
    if (frozenOfSpecies)
        for (std::size_t s = 0; s < frozenOfSpecies->size(); ++s)
            if ((*frozenOfSpecies)[s]) shiftOf[s] = 0.0;
    const bool anyFrozen = std::any_of(shiftOf.begin(), shiftOf.end(), [](double c) { return c == 0.0; });
    const std::uint8_t* __restrict species = p.species.data();
    const std::uint32_t* __restrict order = forceOrder;
    const auto fill = [&](auto perSpecies, auto withIds, auto forcesInOrder) {
#pragma omp parallel for schedule(static)
        for (std::size_t k = 0; k < n; ++k) {
            const double c = decltype(perSpecies)::value ? shiftOf[species[k]] : shift;
            const std::size_t f = decltype(forcesInOrder)::value ? k : order[k];
            PairKinematics e;
            e.vx = static_cast<float>(vx[k] + c * fx[f]);
            e.vy = static_cast<float>(vy[k] + c * fy[f]);
            e.vz = static_cast<float>(vz[k] + c * fz[f]);
            e.id = decltype(withIds)::value ? static_cast<std::uint32_t>(id[k]) : kin[k].id;
            kin[k] = e;
        }
    };
    const auto withForces = [&](auto perSpecies, auto withIds) {
        if (forceOrder) fill(perSpecies, withIds, std::false_type{});
        else fill(perSpecies, withIds, std::true_type{});
    };
    if (anyFrozen) {
        if (ids) withForces(std::true_type{}, std::true_type{});
        else withForces(std::true_type{}, std::false_type{});
    } else {
        if (ids) withForces(std::false_type{}, std::true_type{});
        else withForces(std::false_type{}, std::false_type{});
    }
}

PairInputs& sharedPairInputs() {
    static PairInputs inputs;
    return inputs;
}

}  // namespace dpd
