// The viscosity probe (studies/ViscosityProbe.hpp) on the standard fluid (rho 3, a 25, gamma 4.5,
// kT 1) in a 5 x 5 x 10 box, Groot-Warren at dt 0.02: a check of the plumbing (force direction, start,
// bins, fit, error bars) at test cost, from two laminar starts (nu 0.15 and 0.6, half and twice the
// fluid's ~0.29).
//
// What it can decide: each fit must be parabolic within the block errors (chi^2 per degree of freedom
// < 3: with ~10 degrees of freedom per half a value above 2.5 has a probability below 1 %), its
// standard error within 0.05, and nu positive and within a factor of two of the kinetic-theory
// estimate (0.32), which rules out sign and unit slips (a halved force gives twice nu). The errors come
// from 32 blocks of 5 time units with their correlation summed (analysis/CorrelatedMean.hpp): 160 time
// units are ~18 relaxation times, SE measured 0.017-0.021 (40 time units gave 0.028-0.068 with 8
// blocks, too few to measure the correlation, which is why the sampling is four times longer).
//
// What it cannot decide, and so does not claim: that nu does not depend on the start. Each run
// equilibrates for 30 time units (3.4 relaxation times tau = (Lz/2)^2 / (pi^2 nu) = 8.7, leaving 3 % of
// the start's error), but with SE ~0.02 per run the two answers could only be told apart at ~0.11
// (4 combined SE, 40 % of nu). The long test PairPrecisionReferenceTest samples ten times as long and
// holds the two starts' nu within a tenth of each other; the full-size viscosity runs
// (tutorials/channel/poiseuille/viscosity and latticeWall/viscosity) resolve it further.
#include "ProbeFluid.hpp"
#include "analysis/PoiseuilleFit.hpp"
#include "integrators/Integrator.hpp"
#include "studies/ViscosityProbe.hpp"
#include "setup/StandardFluid.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace dpd;

TEST(ViscosityProbe, ReversePoiseuilleGivesAParabolaAndAPlausibleViscosityFromEitherStart) {
    const System fluid = test::equilibratedProbeFluid();
    EXPECT_NEAR(fluid.box.length().z(), 10.0, 1e-9);
    ViscosityProbeSettings s;
    s.g = 0.08;
    s.bins = 20;
    s.exclude = 1.0;
    s.run.equilibrationTime = 30.0;
    s.run.productionTime = 160.0;
    s.run.blocks = 32;
    ViscosityProbeResult r[2];
    const double starts[2] = {0.15, 0.6};
    for (int k = 0; k < 2; ++k) {
        s.startNu = starts[k];
        auto integrator = makeIntegrator(IntegratorSettings{});
        r[k] = probeViscosity(fluid, *integrator, s);
        ASSERT_FALSE(r[k].unstable) << r[k].problem;
        std::printf("    start nu %.2f: nu %.4f +- %.4f, chi2/dof %.2f, kT %.4f\n", starts[k], r[k].nu, r[k].nuErr,
                    r[k].chi2PerDof, r[k].kT);
        EXPECT_TRUE(r[k].chi2PerDof < 3.0) << r[k].chi2PerDof;
        EXPECT_TRUE(r[k].nuErr <= 0.05) << "too noisy to decide: " << r[k].nuErr;
        const double kinetic = kineticTheoryViscosity(1.0, 4.5, 3.0);
        EXPECT_GT(r[k].nu, 0.5 * kinetic);
        EXPECT_LT(r[k].nu, 2.0 * kinetic);
    }
}
