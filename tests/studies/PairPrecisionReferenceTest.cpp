// Two claims about the measured fluid, held by fixed bounds (issue 45): the single-precision pair
// search leaves kT, the pressure and the viscosity where a double-precision pair loop puts them, and
// the viscosity does not depend on the flow the run starts from.
//
// The reference is a pair loop written here, in double precision throughout (positions, separations,
// weights), with the DPD force written out from its definition (docs/methods.md): no code of the
// production loop (forces/PairForceLoop) is used, only the cell list's bookkeeping of which particles
// share a cell and the same random numbers per pair (random/PairRandom). It drives the same
// Groot-Warren step (lambda 0.5) through the Integrator interface, so the studies' probes measure both
// fluids in the same way. The trajectories part after a few hundred steps (chaos amplifies the
// single-precision round-off), so what is compared is statistics.
//
// The fluid: the standard one (rho 3, a 25, gamma 4.5, kT 1) in a 5 x 5 x 10 box, dt 0.02. kT and the
// pressure at rest, 800 time units sampled in 20 blocks; nu from reverse-Poiseuille flow (g 0.08), as
// the viscosity probe measures it (ViscosityProbeTest), from laminar starts at nu 0.15 and 0.6 (half
// and twice the fluid's ~0.28), 1600 time units sampled in 64 blocks after 40 (4.6 relaxation times).
//
// Each comparison's standard error must first lie within its budget, then the difference within three
// budgets. The budgets are the errors of the difference measured on 2026-11-28 (one thread; the
// same on any number), raised for the scatter of a block error estimate itself (~16 % with 20 blocks,
// ~9 % with 64):
//   quantity   measured (single / double)     error of the difference  budget   bound
//   kT         1.0105 +- 0.0010 / 1.0088 +- 0.0013    0.0016            0.0025   0.0075 (0.75 %)
//   pressure   23.677 +- 0.003 / 23.673 +- 0.004      0.0050            0.007    0.021 (0.09 %)
//   nu         0.2786 +- 0.0055 / 0.2744 +- 0.0041    0.0069            0.009    0.027 (10 %)
//   nu, start 0.15 against 0.6: 0.2786 / 0.2701 +- 0.0042                0.009    0.027
// What the bounds rule out: a pair search that lost the pairs in the last 2 % of the cutoff (their
// conservative virial, rho/3 x (rho/2) 4 pi r^2 dr x a (1 - r) r, is ~0.09 of the pressure: four
// bounds), a random force not matched to its dissipation (kT), an equilibration that does not forget the start by the tenth of nu. What they
// cannot: effects of a few per cent on nu, which the tutorials' viscosity runs resolve. (kT 1.01 is
// velocity Verlet's own error at dt 0.02, the same in both.) About 2.5 minutes on one thread.
#include "ProbeFluid.hpp"
#include "integrators/Integrator.hpp"
#include "studies/TemperatureProbe.hpp"
#include "studies/ViscosityProbe.hpp"
#include "system/System.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace dpd;

namespace {

// F_ij = [a w + (-gamma w^2 (e.v) + sigma w zeta / sqrt(dt))] e, w = 1 - r / r_c, for every pair
// within the cutoff, found through the cell list's cells in double precision. Adds to the forces.
void addReferencePairForces(System& sys, const std::vector<double>& vx, const std::vector<double>& vy,
                            const std::vector<double>& vz) {
    Particles& p = sys.particles;
    const CellList& cells = sys.cells();
    const auto& n = cells.cellsPerAxis();
    const double rc = sys.forceParameters.cutoff;
    const double rootDt = std::sqrt(sys.dt());
    const auto step = static_cast<std::uint64_t>(sys.step);
    const Eigen::Vector3d length = sys.box.length();  // periodic on every axis
    const auto pairForce = [&](std::uint32_t i, std::uint32_t j) {
        Eigen::Vector3d d(p.rx[i] - p.rx[j], p.ry[i] - p.ry[j], p.rz[i] - p.rz[j]);
        for (int a = 0; a < 3; ++a) d[a] -= length[a] * std::round(d[a] / length[a]);
        const double r = d.norm();
        if (r >= rc || r == 0.0) return;
        const Eigen::Vector3d e = d / r;
        const double w = 1.0 - r / rc;
        const double ev = e.dot(Eigen::Vector3d(vx[i] - vx[j], vy[i] - vy[j], vz[i] - vz[j]));
        const PairCoeffs& c = sys.pairs(p.species[i], p.species[j]);
        const double zeta = sys.random().pairUniform(step, p.id[i], p.id[j]);
        const Eigen::Vector3d f = (c.a * w - c.gamma * w * w * ev + c.sigma * w * zeta / rootDt) * e;
        p.fx[i] += f.x(); p.fy[i] += f.y(); p.fz[i] += f.z();
        p.fx[j] -= f.x(); p.fy[j] -= f.y(); p.fz[j] -= f.z();
    };
    for (int cx = 0; cx < n[0]; ++cx)
        for (int cy = 0; cy < n[1]; ++cy)
            for (int cz = 0; cz < n[2]; ++cz) {
                const int home = cells.cellIndex(cx, cy, cz);
                for (int dx = -1; dx <= 1; ++dx)
                    for (int dy = -1; dy <= 1; ++dy)
                        for (int dz = -1; dz <= 1; ++dz) {
                            const int other = cells.cellIndex((cx + dx + n[0]) % n[0], (cy + dy + n[1]) % n[1],
                                                              (cz + dz + n[2]) % n[2]);
                            if (other < home) continue;  // each pair of cells once (3 or more cells per axis)
                            for (std::uint32_t i = cells.cellStart(home); i < cells.cellStart(home + 1); ++i)
                                for (std::uint32_t j = other == home ? i + 1 : cells.cellStart(other);
                                     j < cells.cellStart(other + 1); ++j)
                                    pairForce(i, j);
                        }
            }
}

// Groot-Warren's step at lambda 0.5 (velocity Verlet) with the reference pair loop and the body force.
class ReferenceVelocityVerlet : public Integrator {
public:
    std::string name() const override { return "reference velocity Verlet (double-precision pairs)"; }
    Capabilities capabilities() const override { return {}; }
    WallCounters step(System& sys) override {
        Particles& p = sys.particles;
        const double dt = sys.dt();
        for (std::size_t i = 0; i < p.size(); ++i) {
            p.vx[i] += 0.5 * dt * p.fx[i]; p.vy[i] += 0.5 * dt * p.fy[i]; p.vz[i] += 0.5 * dt * p.fz[i];
            p.rx[i] += dt * p.vx[i]; p.ry[i] += dt * p.vy[i]; p.rz[i] += dt * p.vz[i];
        }
        sys.advanceClock();
        sys.sortByCell();  // wraps, and moves the velocities and forces with the particles
        std::vector<double> vx(p.vx.begin(), p.vx.end()), vy(p.vy.begin(), p.vy.end()), vz(p.vz.begin(), p.vz.end());
        p.clearForces();
        addReferencePairForces(sys, vx, vy, vz);
        sys.bodyForce->apply(p, sys.frozenOfSpecies(), sys.box);
        for (std::size_t i = 0; i < p.size(); ++i) {
            p.vx[i] += 0.5 * dt * p.fx[i]; p.vy[i] += 0.5 * dt * p.fy[i]; p.vz[i] += 0.5 * dt * p.fz[i];
        }
        return {};
    }
};

std::unique_ptr<Integrator> productionVelocityVerlet() { return makeIntegrator(IntegratorSettings::parse("type GrootWarren; lambda 0.5;")); }

// The probes' fluid (ProbeFluid.hpp), its forces those of dt 0.02 (the random term's scale).
System restingFluid() {
    System fluid = test::equilibratedProbeFluid();
    fluid.computeForces();
    return fluid;
}

// a - b with its standard error first within the budget, then within three budgets of zero.
void expectSame(const char* what, double a, double errA, double b, double errB, double budget) {
    const double error = std::hypot(errA, errB);
    std::printf("    %-10s %.5f +- %.5f against %.5f +- %.5f: difference %+.5f +- %.5f (budget %.4g)\n", what, a, errA,
                b, errB, a - b, error, budget);
    ASSERT_TRUE(std::isfinite(a) && std::isfinite(b) && std::isfinite(error)) << what;
    EXPECT_LE(error, budget) << what << ": too noisy to decide";
    EXPECT_LE(std::abs(a - b), 3.0 * budget) << what;
}

TemperatureProbeResult atRest(const System& fluid, Integrator& integrator) {
    System sys = fluid;
    TemperatureProbeSettings s;
    s.equilibrationTime = 10.0;
    s.productionTime = 800.0;
    s.blocks = 20;
    s.samplePressure = true;
    return probeTemperature(sys, integrator, s);
}

ViscosityProbeResult inFlow(const System& fluid, Integrator& integrator, double startNu) {
    ViscosityProbeSettings s;
    s.g = 0.08;
    s.bins = 20;
    s.exclude = 1.0;
    s.startNu = startNu;
    s.run.equilibrationTime = 40.0;
    s.run.productionTime = 1600.0;
    s.run.blocks = 64;
    ViscosityProbeResult r = probeViscosity(fluid, integrator, s);
    EXPECT_FALSE(r.unstable) << r.problem;
    return r;
}

}  // namespace

TEST(LongPairPrecision, SinglePrecisionPairsGiveTheDoubleReferencesKTAndPressure) {
    const System fluid = restingFluid();
    auto production = productionVelocityVerlet();
    ReferenceVelocityVerlet reference;
    const TemperatureProbeResult single = atRest(fluid, *production);
    const TemperatureProbeResult exact = atRest(fluid, reference);
    ASSERT_FALSE(single.unstable || exact.unstable) << single.problem << exact.problem;
    expectSame("kT", single.kT, single.standardError, exact.kT, exact.standardError, 0.0025);
    expectSame("pressure", single.pressure, single.pressureStandardError, exact.pressure, exact.pressureStandardError,
               0.007);
}

TEST(LongPairPrecision, TheViscosityIsTheDoubleReferencesAndForgetsItsStart) {
    const System fluid = restingFluid();
    auto production = productionVelocityVerlet();
    ReferenceVelocityVerlet reference;
    const ViscosityProbeResult fromLow = inFlow(fluid, *production, 0.15);
    const ViscosityProbeResult fromHigh = inFlow(fluid, *production, 0.6);
    const ViscosityProbeResult exact = inFlow(fluid, reference, 0.15);
    expectSame("nu (start)", fromLow.nu, fromLow.nuErr, fromHigh.nu, fromHigh.nuErr, 0.009);
    expectSame("nu (double)", fromLow.nu, fromLow.nuErr, exact.nu, exact.nuErr, 0.009);
}
