// A geometry wall with the tunable-slip layer, and one that asks for a slip length (docs/walls.md 3.9):
// the friction and the offset of its acting surface from the case's calibration, as a planar wall's;
// randomEquilWall keeping the fluid up to where the wall acts; clear errors for what it cannot take.
#include "../geometry/GeometryTestFiles.hpp"
#include "../support/ExactSlipCalibration.hpp"
#include "../support/InputErrorOf.hpp"
#include "case/DpdProperties.hpp"
#include "geometry/GeometryDictionary.hpp"
#include "io/Dictionary.hpp"
#include "setup/RandomEquilWall.hpp"
#include "walls/GeometryShape.hpp"
#include "walls/SlipCalibration.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <memory>

using namespace dpd;
using namespace geometryTest;

namespace {

const std::string kModel = "tunableSlip { zc 1; epsilon 1; sigma 0.5; fluidBehind { a 25; density 3; } }";

// Box x 0..8, y 0..3, z 0..8; a 16 x 16 mask of 0.5 pixels whose top and bottom three rows are solid:
// the geometry's surfaces at z = 1.5 and 6.5.
Picture channel() { return channelPicture(16, 3); }

std::string properties(const std::string& wall) {
    return "dimension 3; kT 1; seed 5;\nspecies { fluid { frozen no; } }\npairCoeffs { fluid-fluid { a 25; gamma 4.5; } }\n"
           "integrator { type GrootWarren; lambda 0.65; }\n"
           "geometry { type imageMask; file \"constant/geometry/mask.pgm\"; solidValues (0); pixelSize 0.5; }\n"
           "walls { channel { type geometry; " + wall + " } }\n";
}

// A geometry case with its calibration in constant/slipCalibration, an empty user cache, and the
// fluid's density in system/randomEquilWallDict (no blockFrozenWallDict).
class GeometrySlipLengthWall : public ScratchDirectory {
protected:
    void SetUp() override {
        ScratchDirectory::SetUp();
        writePgm(path("constant/geometry/mask.pgm"), channel());
        writeText(path("system/controlDict"), "deltaT 0.01;\n");
        writeText(path("system/randomEquilWallDict"), "box { min (0 0 0); max (8 3 8); }\nfluid { species fluid; density 3; }\n"
                                                      "equilibration { time 2; deltaT 0.01; }\n");
        fs::create_directories(dir_ / "cache");
        ::setenv("DPD_SLIP_CALIBRATIONS", (dir_ / "cache").c_str(), 1);
        const std::string file = path("constant/slipCalibration");
        Dictionary d(file);
        test::exactSlipCalibration().writeTo(d);
        writeDictionaryFile(file, d);
    }
    void TearDown() override {
        ::unsetenv("DPD_SLIP_CALIBRATIONS");
        ScratchDirectory::TearDown();
    }
    Dictionary propertiesDict(const std::string& wall) const {
        return Dictionary::parse(properties(wall), path("constant/dpdProperties"));
    }
    DpdModel read(const std::string& wall) const { return readDpdModel(propertiesDict(wall), dir_.string()); }
    std::string errorOf(const std::string& wall) const {
        return test::inputErrorOf([&] { read(wall); });
    }
    // The model's wall built on the box, as a run builds it.
    std::shared_ptr<Wall> built(const DpdModel& m) const {
        Box box;
        box.lo = Eigen::Vector3d(0, 0, 0);
        box.hi = Eigen::Vector3d(8, 3, 8);
        return m.walls[0].builtOn(ShapeBuildContext{box, dir_.string(), 1.0});
    }
};

}  // namespace

TEST_F(GeometrySlipLengthWall, TakesTheCalibratedFrictionAndActsBehindTheGeometrysSurface) {
    const DpdModel m = read("slipLength 2; " + kModel + ";");
    ASSERT_EQ(m.walls.size(), 1u);
    ASSERT_TRUE(m.walls[0].actsWithForces());
    EXPECT_NE(m.walls[0].description().find("specular"), std::string::npos) << m.walls[0].description();
    const auto* shape = dynamic_cast<const GeometryShape*>(&m.walls[0].shape());
    ASSERT_NE(shape, nullptr);
    // b = 3 / gamma_L - 0.4 = 2 (tests/support/ExactSlipCalibration.hpp): gamma_L 1.25; the calibration's
    // wall acts 0.3 in front of its plane, so the acting surface lies 0.3 behind the geometry's.
    EXPECT_EQ(shape->surfaceOffset(), 0.3);
    ASSERT_EQ(m.wallNotes.size(), 1u);
    EXPECT_NE(m.wallNotes[0].find("wall channel: slipLength 2 from " + path("constant/slipCalibration") + ": gammaL 1.25"),
              std::string::npos) << m.wallNotes[0];
    // The channel's flat surfaces lie at z = 1.5 and 6.5: the field is exact there, the wall acts at
    // 1.2 and 6.8, and a point 0.5 into the fluid is 0.8 from it.
    const std::shared_ptr<Wall> w = built(m);
    ASSERT_TRUE(w);
    EXPECT_NEAR(w->signedDistance({4, 1.5, 1.5}), 0.3, 1e-6);
    EXPECT_NEAR(w->signedDistance({4, 1.5, 1.2}), 0.0, 1e-6);
    EXPECT_NEAR(w->signedDistance({4, 1.5, 6.0}), 0.8, 1e-6);
    EXPECT_NEAR(w->shape().surfaceAt({4, 1.5, 6.0}).distance, 0.8, 1e-6);
    EXPECT_NEAR(w->shape().surfaceAt({4, 1.5, 6.0}).normal.z(), -1.0, 1e-6);
    EXPECT_TRUE(w->isInsideSolid({4, 1.5, 1.1}));
    EXPECT_FALSE(w->isInsideSolid({4, 1.5, 1.3}));
    EXPECT_NE(w->description().find("acting 0.3 behind its surface"), std::string::npos) << w->description();
}

TEST_F(GeometrySlipLengthWall, AGivenFrictionLeavesTheSurfaceWhereTheGeometryPutsIt) {
    const DpdModel m = read("tunableSlip { gammaL 2; zc 1; epsilon 1; sigma 0.5; };");
    ASSERT_TRUE(m.walls[0].actsWithForces());
    EXPECT_TRUE(m.wallNotes.empty());
    const DpdModel plain = read("reflection bounceBack;");
    EXPECT_FALSE(plain.walls[0].actsWithForces());
    const std::shared_ptr<Wall> a = built(m), b = built(plain);
    for (const double z : {1.3, 1.5, 2.1, 4.0, 6.4, 6.7})
        EXPECT_EQ(a->signedDistance({3.3, 0.7, z}), b->signedDistance({3.3, 0.7, z})) << z;
}

TEST_F(GeometrySlipLengthWall, RefusesWhatItCannotTakeAtTheKeyword) {
    std::string e = errorOf("slipLength 2;");
    EXPECT_NE(e.find("keyword 'slipLength'"), std::string::npos) << e;
    EXPECT_NE(e.find("needs the wall's model"), std::string::npos) << e;
    e = errorOf("slipLength 2; tunableSlip { zc 1; epsilon 1; sigma 0.5; fluidBehind { a 25; density 3; } stripes { axis x; "
                "period 4; gasFraction 0.5; gammaGas 0.1; } };");
    EXPECT_NE(e.find("keyword 'stripes'"), std::string::npos) << e;
    EXPECT_NE(e.find("type plane"), std::string::npos) << e;
    e = errorOf("slipLength 12; " + kModel + ";");
    EXPECT_NE(e.find("outside the calibrated range 0 to 11.6"), std::string::npos) << e;
    e = errorOf("slipLength 2; tunableSlip { gammaL 1; zc 1; epsilon 1; sigma 0.5; fluidBehind { a 25; density 3; } };");
    EXPECT_NE(e.find("give one of the two"), std::string::npos) << e;
    e = errorOf("slipLength 2; tunableSlip { zc 1; epsilon 1; sigma 0.5; };");
    EXPECT_NE(e.find("wall/fluidBehind/a 0 against 25"), std::string::npos) << e;
}

// Without a wall species the solid is left empty (the layer's force stands in for it), and the fluid
// fills the channel from sigma (0.5) in front of where the wall acts, 0.3 behind the geometry's surface
// (as blockFrozenWall starts it in front of a tunable-slip plane): no fluid particle starts nearer the
// run's wall, and the fluid's count is the density times the volume from z = 1.7 to 6.3 within Poisson
// scatter (4 standard deviations).
TEST_F(GeometrySlipLengthWall, RandomEquilWallFillsFromWhereTheWallActs) {
    const Dictionary props = propertiesDict("slipLength 2; " + kModel + ";");
    const DpdModel m = readDpdModel(props, dir_.string());
    const Dictionary dict = Dictionary::readFile(path("system/randomEquilWallDict"));
    RandomEquilWallReport r;
    const Snapshot s = buildRandomEquilWall(dict, props, m, dir_.string(), r);
    EXPECT_EQ(r.frozen, 0u);
    EXPECT_EQ(r.surfaceOffset, 0.3);
    EXPECT_EQ(r.fluidStartsBeyond, 0.5);
    EXPECT_EQ(s.particles.size(), r.fluid);
    const std::shared_ptr<Wall> w = built(m);
    double nearest = 8.0;
    for (std::size_t i = 0; i < s.particles.size(); ++i)
        nearest = std::min(nearest, w->signedDistance({s.particles.rx[i], s.particles.ry[i], s.particles.rz[i]}));
    EXPECT_GE(nearest, 0.5 - 1e-6);
    EXPECT_LT(nearest, 0.6);  // the fluid reaches there: between the geometry's surface and the acting one
    const double mean = 3.0 * 8.0 * 3.0 * (6.3 - 1.7);
    EXPECT_NEAR(static_cast<double>(r.fluid), mean, 4.0 * std::sqrt(mean));
}
