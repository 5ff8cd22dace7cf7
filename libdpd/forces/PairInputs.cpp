#include "forces/PairInputs.hpp"

#include <algorithm>
#include <array>

namespace dpd {

std::size_t PairInputs::capacityBytes() const {
    return sizeof(float) * (x.capacity() + y.capacity() + z.capacity()) + sizeof(PairKinematics) * kinematics.capacity();
}

namespace {
// n entries, and no more than twice that held: the inputs are shared by every system of the process
// (the benchmark runs a million particles, then 32,000), and each should hold what it needs.
template <class T>
void fitTo(std::vector<T>& v, std::size_t n) {
    if (v.capacity() > 2 * n) std::vector<T>().swap(v);
    v.resize(n);
}
}  // namespace

void fillPairInputs(const Particles& p, const CellList& cells, bool velocities, bool ids, PairInputs& in) {
    const std::size_t n = p.size();
    fitTo(in.x, n); fitTo(in.y, n); fitTo(in.z, n);
    if (velocities || ids) fitTo(in.kinematics, n);
    const auto& nc = cells.cellsPerAxis();
    const Eigen::Vector3d& h = cells.cellSize();
    const Eigen::Vector3d& lo = cells.box().lo;
    in.cellX = static_cast<float>(h.x()); in.cellY = static_cast<float>(h.y()); in.cellZ = static_cast<float>(h.z());
#pragma omp parallel for schedule(static)
    for (int ix = 0; ix < nc[0]; ++ix)
        for (int iy = 0; iy < nc[1]; ++iy) {
            const double cornerX = lo.x() + ix * h.x(), cornerY = lo.y() + iy * h.y();
            for (int iz = 0; iz < nc[2]; ++iz) {
                const int c = cells.cellIndex(ix, iy, iz);
                const double cornerZ = lo.z() + iz * h.z();
                for (std::uint32_t k = cells.cellStart(c); k < cells.cellStart(c + 1); ++k) {
                    in.x[k] = static_cast<float>(p.rx[k] - cornerX);
                    in.y[k] = static_cast<float>(p.ry[k] - cornerY);
                    in.z[k] = static_cast<float>(p.rz[k] - cornerZ);
                }
            }
        }
    PairKinematics* __restrict kin = in.kinematics.data();
    if (velocities) {
#pragma omp parallel for schedule(static)
        for (std::size_t k = 0; k < n; ++k) {
            kin[k].vx = static_cast<float>(p.vx[k]);
            kin[k].vy = static_cast<float>(p.vy[k]);
            kin[k].vz = static_cast<float>(p.vz[k]);
        }
    }
    if (ids) {
#pragma omp parallel for schedule(static)
        for (std::size_t k = 0; k < n; ++k) kin[k].id = static_cast<std::uint32_t>(p.id[k]);
    }
}

void fillPredictedVelocities(Particles& p, double shift, const std::vector<std::uint8_t>* frozenOfSpecies,
                             PairInputs& in) {
    const std::size_t n = p.size();
    fitTo(in.kinematics, n);
    double* __restrict fx = p.fx.data();
    double* __restrict fy = p.fy.data();
    double* __restrict fz = p.fz.data();
    const double* __restrict vx = p.vx.data();
    const double* __restrict vy = p.vy.data();
    const double* __restrict vz = p.vz.data();
    PairKinematics* __restrict kin = in.kinematics.data();
    const bool anyFrozen = frozenOfSpecies &&
                           std::any_of(frozenOfSpecies->begin(), frozenOfSpecies->end(), [](std::uint8_t f) { return f != 0; });
    if (!anyFrozen) {
#pragma omp parallel for schedule(static)
        for (std::size_t k = 0; k < n; ++k) {
            kin[k].vx = static_cast<float>(vx[k] + shift * fx[k]);
            kin[k].vy = static_cast<float>(vy[k] + shift * fy[k]);
            kin[k].vz = static_cast<float>(vz[k] + shift * fz[k]);
            fx[k] = 0.0; fy[k] = 0.0; fz[k] = 0.0;
        }
        return;
    }
    // Per species: v + 0 f is v exactly (forces are finite), so a frozen particle's velocity passes as it is.
    std::array<double, 256> shiftOf;
    shiftOf.fill(shift);
    for (std::size_t s = 0; s < frozenOfSpecies->size(); ++s)
        if ((*frozenOfSpecies)[s]) shiftOf[s] = 0.0;
    const std::uint8_t* __restrict species = p.species.data();
#pragma omp parallel for schedule(static)
    for (std::size_t k = 0; k < n; ++k) {
        const double c = shiftOf[species[k]];
        kin[k].vx = static_cast<float>(vx[k] + c * fx[k]);
        kin[k].vy = static_cast<float>(vy[k] + c * fy[k]);
        kin[k].vz = static_cast<float>(vz[k] + c * fz[k]);
        fx[k] = 0.0; fy[k] = 0.0; fz[k] = 0.0;
    }
}

PairInputs& sharedPairInputs() {
    static PairInputs inputs;
    return inputs;
}

}  // namespace dpd
