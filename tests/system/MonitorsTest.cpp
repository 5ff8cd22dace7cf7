// The run monitor's temperature (system/Monitors.*) is measured about the local flow: a shear flow
// must not read as heat, across planar walls or through a geometry of any shape. With slab means
// alone, a linear profile of shear rate c across slabs of width w adds (c w)^2 / 12 to one velocity
// component, i.e. (c w)^2 / 36 to kT in 3-D.
#include "../geometry/GeometryTestFiles.hpp"

#include "geometry/GeometryDictionary.hpp"
#include "io/Dictionary.hpp"
#include "system/Monitors.hpp"
#include "../support/WallRuleNamed.hpp"
#include "walls/GeometryShape.hpp"
#include "setup/StandardFluid.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iomanip>
#include <memory>
#include <sstream>

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

namespace {

// The standard fluid in a box 3 thick along y, its thermal velocities at exactly kT = 1 about a
// zero mean (box 50.4 x 3.15 x 25.2), walled by the solid of an image mask: a channel |z - zc| < halfWidth along x, the
// picture `pixels` wide (x) and tall (z), with a narrowing in the middle third of x when `throat`.
struct MaskedChannel : public geometryTest::ScratchDirectory {
    System sys = makeStandardFluid(fluidSettings());
    double zc = 0.5 * (sys.box.lo.z() + sys.box.hi.z());
    double halfWidth = 0.4 * sys.box.length().z();

    static StandardFluidSettings fluidSettings() {
        StandardFluidSettings s;
        s.particles = 12000;
        s.aspect = Eigen::Vector3d(4.0, 0.25, 2.0);  // 50.4 x 3.15 x 25.2
        return s;
    }
    // A picture `rows` pixels tall (z) and twice as wide (x), as the box (square pixels).
    void addMaskWall(int rows) {
        const double pixel = sys.box.length().z() / rows;
        geometryTest::Picture pic(rows, std::vector<int>(2 * rows, 255));
        for (int row = 0; row < rows; ++row) {
            const double z = sys.box.hi.z() - (row + 0.5) * pixel;  // rows from the top
            if (std::abs(z - zc) >= halfWidth) pic[row].assign(2 * rows, 0);
        }
        geometryTest::writePgm(path("channel.pgm"), pic);
        std::ostringstream text;
        text << std::setprecision(17) << "type imageMask; file \"" << path("channel.pgm")
             << "\"; solidValues (0); pixelSize " << pixel << ";";
        const Dictionary d = Dictionary::parse(text.str(), "geometryDict");
        sys.walls.add(std::make_shared<Wall>("geometry", std::make_shared<GeometryShape>(readSolidRegion(d, "", sys.box, 1.0).distance),
                                             test::ruleNamed("bounceBack")));
    }
    // The published Poiseuille scene's centre-line speed (u_max 14.6 in d = 40) on the channel's
    // parabola, modulated along x by a factor 1 +- 0.5 (a flow through a contraction varies along
    // both axes): the global mean would count 0.089 u_max^2 / 3 = 6.3 of it as heat.
    double flowAt(double x, double z) const {
        const double s = (z - zc) / halfWidth;
        const double along = 1.0 + 0.5 * std::cos(2.0 * M_PI * (x - sys.box.lo.x()) / sys.box.length().x());
        return std::abs(s) < 1.0 ? kUMax * (1.0 - s * s) * along : 0.0;
    }
    static constexpr double kUMax = 14.6;
};

}  // namespace

TEST(Monitors, APlaneAcrossTwoAxesIsRemovedToRoundOff) {
    StandardFluidSettings s;
    s.particles = 6000;
    const System rest = makeStandardFluid(s);
    System flowing = rest;
    // u_x and u_z linear in x and z inside every cell (the fit's cells do not straddle the box's faces).
    for (std::size_t i = 0; i < flowing.particles.size(); ++i) {
        flowing.particles.vx[i] += 1.3 * rest.particles.rx[i] - 0.8 * rest.particles.rz[i];
        flowing.particles.vz[i] += 0.6 * rest.particles.rx[i];
    }
    FlowAxes xz;
    xz.varies = {true, false, true};
    EXPECT_NEAR(monitor(flowing, xz).kT, monitor(rest, xz).kT, 1e-9);
    // Across one axis the x-gradient stays in: the slab fit sees it as heat.
    EXPECT_GT(monitor(flowing, 2).kT, monitor(rest, 2).kT + 1.0);
}

TEST_F(MaskedChannel, TheFlowAxesOfAGeometryWallAreTheAxesItVariesAlong) {
    EXPECT_EQ(flowAxesOf(sys).count(), 0);  // a periodic box: the global mean
    addMaskWall(24);
    const FlowAxes a = flowAxesOf(sys);
    EXPECT_TRUE(a.varies[0]);
    EXPECT_FALSE(a.varies[1]);  // the mask is extruded along y
    EXPECT_TRUE(a.varies[2]);
}

TEST_F(MaskedChannel, ALaminarFlowThroughAGeometryIsNotHeat) {
    addMaskWall(24);
    const double atRest = monitor(sys, flowAxesOf(sys)).kT;
    for (std::size_t i = 0; i < sys.particles.size(); ++i)
        sys.particles.vx[i] += flowAt(sys.particles.rx[i], sys.particles.rz[i]);
    const double flowing = monitor(sys, flowAxesOf(sys)).kT;
    // What the planes leave of the flow is its curvature within a cell: for a parabola of second
    // derivative c sampled uniformly over a width w, (c/2)^2 w^4 / 180 per particle, divided by the
    // 3 velocity components. The cells here are under 2 wide (32 particles at rho 3 over a depth of
    // 3.15 need 1.84 squared, rounded up to fit the box); c = 2 u_max (1.5) / halfWidth^2 along z, and the modulation along x adds
    // u_max (0.5) (2 pi / Lx)^2, far less. The cells that cut the wall hold a kink of the profile
    // (0 in the solid); the fluid's part of them is fitted all the same, and the bound below (ten
    // times the curvature share) leaves room for them. The global mean would read ~6 kT more.
    const double width = 2.0;
    const double curvature = 2.0 * kUMax * 1.5 / (halfWidth * halfWidth);
    const double curvatureShare = std::pow(0.5 * curvature, 2) * std::pow(width, 4) / 180.0 / 3.0;
    EXPECT_LT(std::abs(flowing - atRest), 10.0 * curvatureShare);
    EXPECT_LT(10.0 * curvatureShare, 0.05);  // the bound says something: under 5 % of kT
    // The same flow about the global mean is mostly "heat" (what stopped the published scene).
    EXPECT_GT(monitor(sys, FlowAxes::none()).kT, atRest + 2.0);
}
