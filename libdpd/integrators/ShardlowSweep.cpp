#include "integrators/ShardlowSweep.hpp"

#include "integrators/PairSweep.hpp"
#include "system/System.hpp"

#include <cmath>

namespace dpd {

// The pair's process. With positions fixed, e = r_ij / r is constant and the dissipative and random
// forces of pair (i, j) are F_i = -F_j = (-gamma w_D u + sigma w_R xi(t)) e, u = e . (v_i - v_j), xi
// white noise. They leave the pair's centre-of-mass velocity and the components of v_i - v_j normal
// to e alone, and change u by
//   du = (1/m_i + 1/m_j) (-gamma w_D u dt + sigma w_R dW) = -kappa u dt + (sigma w_R / mu) dW,
// with the reduced mass mu = 1 / (1/m_i + 1/m_j) and kappa = gamma w_D / mu. That is an Ornstein-
// Uhlenbeck process, solved exactly over dt by
//   u(dt) = u e^(-kappa dt) + sqrt(D (1 - e^(-2 kappa dt))) N(0, 1),
//   D = (sigma w_R / mu)^2 / (2 kappa) = sigma^2 / (2 gamma mu) = kT / mu   (w_D = w_R^2, sigma^2 = 2 gamma kT),
// whatever r is. The change du goes to the particles in proportion to their inverse masses, so the
// pair's momentum is kept: dv_i = (mu / m_i) du e, dv_j = -(mu / m_j) du e.
//
// A frozen particle never moves: it is a particle of infinite mass, 1/m = 0. For a frozen-fluid pair
// the reduced mass is then the fluid particle's mass, mu = m_i, and the whole change du goes to the
// fluid particle (dv_i = du e) while the frozen one keeps its (wall) velocity. All masses are 1 here.
namespace {

template <class Weight>
void sweepWithWeight(System& sys, const Weight& weight, double dt, std::uint32_t sweep) {
    Particles& p = sys.particles;
    const PairTable& table = sys.pairs;
    const auto& frozen = sys.frozenOfSpecies();
    const double kT = sys.forceParameters.kT;
    const std::uint64_t step = static_cast<std::uint64_t>(sys.step);
    const PairRandom& random = sys.random();
    const std::uint32_t stream = kStreamShardlowSweep + 0x10u * sweep;  // distinct from all RandomStream values
    double* vx = p.vx.data();
    double* vy = p.vy.data();
    double* vz = p.vz.data();
    const auto update = [&](std::uint32_t i, std::uint32_t j, double dx, double dy, double dz, double zeta) {
        const PairCoeffs& c = table(p.species[i], p.species[j]);
        if (c.gamma == 0.0) return;
        const double invMassI = frozen[p.species[i]] ? 0.0 : 1.0;
        const double invMassJ = frozen[p.species[j]] ? 0.0 : 1.0;
        const double invMu = invMassI + invMassJ;
        const double r = std::sqrt(dx * dx + dy * dy + dz * dz);
        const double wD = weight.at(r).wD;
        // decay - 1 = e^(-kappa dt) - 1, and 1 - decay^2 = -(decay - 1)(decay + 1), accurate for small kappa dt.
        const double decayMinusOne = std::expm1(-c.gamma * wD * invMu * dt);
        const double spread = std::sqrt(-kT * invMu * decayMinusOne * (2.0 + decayMinusOne));
        const double ex = dx / r, ey = dy / r, ez = dz / r;
        const double u = ex * (vx[i] - vx[j]) + ey * (vy[i] - vy[j]) + ez * (vz[i] - vz[j]);
        const double du = u * decayMinusOne + spread * zeta;
        const double dvi = du * invMassI / invMu, dvj = du * invMassJ / invMu;
        vx[i] += dvi * ex; vy[i] += dvi * ey; vz[i] += dvi * ez;
        vx[j] -= dvj * ex; vy[j] -= dvj * ey; vz[j] -= dvj * ez;
    };
    // Per row of cells: the pairs' Gaussians first (they depend on nothing the sweep changes), then
    // the pairs one after the other.
    sweepPairRows(p, sys.cells(), table, sys.forceParameters.cutoff, [&](detail::PairBatch& b) {
        const std::size_t n = b.size;
        for (std::size_t k = 0; k < n; ++k) b.zeta[k] = random.pairGaussian(step, p.id[b.i[k]], p.id[b.j[k]], stream);
        for (std::size_t k = 0; k < n; ++k) update(b.i[k], b.j[k], b.dx[k], b.dy[k], b.dz[k], b.zeta[k]);
    });
}

}  // namespace

void shardlowSweep(System& sys, double dt, std::uint32_t sweep) {
    withDpdWeight(sys.forceParameters, [&](const auto& weight) { sweepWithWeight(sys, weight, dt, sweep); });
}

}  // namespace dpd
