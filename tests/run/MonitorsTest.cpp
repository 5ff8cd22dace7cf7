// The run monitor's temperature (run/Monitors.*) is measured about the local flow: a shear flow
// must not read as heat. With slab means alone, a linear profile of shear rate c across slabs of
// width w adds (c w)^2 / 12 to one velocity component, i.e. (c w)^2 / 36 to kT in 3-D.
#include "run/Monitors.hpp"
#include "run/StandardFluid.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace dpd;

namespace {

// The standard fluid's thermal velocities plus u_x = shear * z (z from the box centre).
System shearedFluid(double shear) {
    StandardFluidSettings s;
    s.particles = 3000;
    System sys = makeStandardFluid(s);
    const double zc = 0.5 * (sys.box.lo.z() + sys.box.hi.z());
    for (std::size_t i = 0; i < sys.particles.size(); ++i) sys.particles.vx[i] += shear * (sys.particles.rz[i] - zc);
    return sys;
}

}  // namespace

TEST(Monitors, ShearInsideASlabIsNotCountedAsHeat) {
    const double shear = 1.5;
    const double atRest = monitor(shearedFluid(0.0), 2).kT;
    const double sheared = monitor(shearedFluid(shear), 2).kT;
    // The fit removes the linear profile exactly, up to round-off: the two readings differ only by
    // the change of the fitted lines' degrees of freedom, which is none here (same particles).
    EXPECT_NEAR(sheared, atRest, 1e-9);
    // What a slab mean would have added, for scale: (1.5 x ~1)^2 / 36 = 0.06 kT.
    EXPECT_GT(shear * shear / 36.0, 1e3 * std::abs(sheared - atRest));
}

TEST(Monitors, WithoutAFlowAxisTheGlobalMeanIsRemoved) {
    System sys = shearedFluid(0.0);
    const double before = monitor(sys, -1).kT;
    for (std::size_t i = 0; i < sys.particles.size(); ++i) sys.particles.vy[i] += 0.7;
    const MonitorReport r = monitor(sys, -1);
    EXPECT_NEAR(r.kT, before, 1e-12);
    EXPECT_NEAR(r.meanVelocity.y(), 0.7, 1e-12);
    // The standard fluid starts at exactly kT = 1 about its (zero) mean.
    EXPECT_NEAR(before, 1.0, 1e-12);
}
