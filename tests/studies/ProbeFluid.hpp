#pragma once
// The fluid the studies' tests probe: the standard fluid (rho 3, a 25, gamma 4.5, kT 1), 750 particles
// in a 5 x 5 x 10 box, equilibrated for 1000 Groot-Warren steps at dt 0.01, then set to dt 0.02.
#include "integrators/Integrator.hpp"
#include "setup/StandardFluid.hpp"
#include "system/System.hpp"

namespace dpd::test {

inline System equilibratedProbeFluid() {
    StandardFluidSettings f;
    f.particles = 750;
    f.aspect = Eigen::Vector3d(1, 1, 2);
    f.dt = 0.01;
    f.seed = 5;
    System fluid = makeStandardFluid(f);
    auto gw = makeIntegrator(IntegratorSettings{});
    for (int k = 0; k < 1000; ++k) gw->step(fluid);
    fluid.forceParameters.dt = 0.02;
    return fluid;
}

}  // namespace dpd::test
