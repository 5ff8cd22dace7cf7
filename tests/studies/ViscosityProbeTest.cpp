// The viscosity probe (studies/ViscosityProbe.hpp) on the standard fluid (rho 3, a 25, gamma 4.5,
// kT 1) in a 5 x 5 x 10 box, Groot-Warren at dt 0.02.
//
// Its answer must not depend on the laminar start: one run started at nu 0.15 and one at 0.6 (half and
// twice the fluid's viscosity, ~0.29) must agree within 4 combined standard errors. Each equilibrates
// for 30 time units, 3.4 times the relaxation time tau = (Lz/2)^2 / (pi^2 nu) = 8.7 of the start's
// error, leaving 3 % of it. Resolution: the fit errors are ~0.02-0.03 each (measured: 0.028 and 0.017,
// nu 0.31 and 0.25), so 4 combined SE is ~0.13, 45 % of nu. The two starts' profiles differ by 145 % of
// the signal at first (0.29 / 0.15 - 0.29 / 0.6); sampled with no equilibration for 10 time units they
// gave nu 0.20 +- 0.01 and 0.37 +- 0.10 (the drifting profile inflates the fit's error through its
// chi^2), which this tolerance does not resolve either. So this is a coarse check of the plumbing
// (force direction, start, bins, fit, error bars) at test cost, not a test of the relaxation or a
// precision value of nu. Caveat: blocks of 5 time units are shorter than the profile's slowest
// fluctuation (~8.7), so the block errors understate the true scatter (by up to sqrt(2 tau / block) ~ 1.9);
// the result is deterministic for the seed, but a new seed can fail this test by chance more often than
// 4 SE suggests.
// Both fits must be parabolic within the block errors (chi^2 per degree of freedom < 3: with ~10
// degrees of freedom per half a value above 2.5 has a probability below 1 %) and give a positive nu
// within a factor of two of the kinetic-theory estimate (0.32), which rules out sign and unit slips.
#include "analysis/PoiseuilleFit.hpp"
#include "integrators/Integrator.hpp"
#include "studies/ViscosityProbe.hpp"
#include "setup/StandardFluid.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace dpd;

TEST(ViscosityProbe, ReversePoiseuilleViscosityDoesNotDependOnTheStart) {
    StandardFluidSettings f;
    f.particles = 750;
    f.aspect = Eigen::Vector3d(1, 1, 2);
    f.dt = 0.01;
    f.seed = 5;
    System fluid = makeStandardFluid(f);
    EXPECT_NEAR(fluid.box.length().z(), 10.0, 1e-9);
    auto gw = makeIntegrator(IntegratorSettings{});
    for (int k = 0; k < 1000; ++k) gw->step(fluid);
    fluid.forceParameters.dt = 0.02;
    ViscosityProbeSettings s;
    s.g = 0.08;
    s.bins = 20;
    s.exclude = 1.0;
    s.run.equilibrationTime = 30.0;
    s.run.productionTime = 40.0;
    s.run.blocks = 8;
    ViscosityProbeResult r[2];
    const double starts[2] = {0.15, 0.6};
    for (int k = 0; k < 2; ++k) {
        s.startNu = starts[k];
        auto integrator = makeIntegrator(IntegratorSettings{});
        r[k] = probeViscosity(fluid, *integrator, s);
        ASSERT_FALSE(r[k].unstable) << r[k].problem;
        std::printf("    start nu %.2f: nu %.4f +- %.4f, chi2/dof %.2f, kT %.4f\n", starts[k], r[k].nu, r[k].nuErr,
                    r[k].chi2PerDof, r[k].kT);
        EXPECT_LT(r[k].chi2PerDof, 3.0);
        const double kinetic = kineticTheoryViscosity(1.0, 4.5, 3.0);
        EXPECT_GT(r[k].nu, 0.5 * kinetic);
        EXPECT_LT(r[k].nu, 2.0 * kinetic);
    }
    EXPECT_LT(std::abs(r[0].nu - r[1].nu), 4.0 * std::hypot(r[0].nuErr, r[1].nuErr));
}
