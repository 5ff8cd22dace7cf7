// makeFoamCase's spec and files: the mesh matches the DPD box and walls, nu and the slip come from where
// the dictionary says, the body force and sampling lines are written in OpenFOAM v1912 syntax, solid
// cells of a mask are the cells whose centres are solid (labelled as blockMesh numbers them), and what
// the continuum case cannot represent is refused naming the file and keyword.
#include "core/Error.hpp"
#include "foam/FoamCaseSpec.hpp"
#include "foam/FoamCaseWriter.hpp"
#include "../geometry/GeometryTestFiles.hpp"
#include "../support/ExactSlipCalibration.hpp"
#include "io/Dictionary.hpp"
#include "walls/SlipCalibration.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace {

namespace fs = std::filesystem;
using dpd::Dictionary;

const std::string kHeader = "FoamFile { version 2.0; format ascii; class dictionary; }\n";

std::string dpdProperties(const std::string& walls, const std::string& force = "(0.02 0 0)",
                          const std::string& extra = "") {
    return kHeader +
           "dimension 3; kT 1; seed 1;\n"
           "species { fluid { frozen no; } wall { frozen yes; } }\n"
           "pairCoeffs { fluid-fluid { a 18.75; gamma 4.5; } fluid-wall { a 18.75; gamma 4.5; } }\n"
           "integrator { type GrootWarren; lambda 0.65; }\n"
           "bodyForce { type uniform; value " + force + "; }\n" + walls + extra;
}

const std::string kChannelWalls =
    "walls {\n"
    "  lower { type plane; point (0 0 -5); normal (0 0 1); reflection bounceBack; }\n"
    "  upper { type plane; point (0 0 5); normal (0 0 -1); reflection bounceBack; }\n}\n";

class FoamCase : public ::testing::Test {
protected:
    void SetUp() override {
        dir = fs::temp_directory_path() / ("foamCaseTest" + std::to_string(::getpid()) + "_" +
                                           ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir);
        fs::create_directories(dir);
        in.caseDir = dir.string();
    }
    void TearDown() override {
        ::unsetenv("DPD_SLIP_CALIBRATIONS");
        fs::remove_all(dir);
    }

    dpd::FoamCaseSpec spec(const std::string& dictText, const std::string& propsText) {
        const Dictionary d = Dictionary::parse(kHeader + dictText, (dir / "system/makeFoamCaseDict").string());
        const Dictionary p = Dictionary::parse(propsText, (dir / "constant/dpdProperties").string());
        return dpd::makeFoamCaseSpec(d, p, in);
    }
    // Expects an InputError naming the file (by its last path part) and the keyword.
    void expectRefused(const std::string& dictText, const std::string& propsText, const std::string& file,
                       const std::string& keyword) {
        try {
            spec(dictText, propsText);
            ADD_FAILURE() << "expected an InputError about " << keyword;
        } catch (const dpd::InputError& e) {
            EXPECT_NE(std::string(e.what()).find(file), std::string::npos) << e.what();
            EXPECT_EQ(e.keyword(), keyword) << e.what();
        }
    }
    void writeFit(const std::string& time, const std::string& body) {
        geometryTest::writeText((dir / "postProcessing/fitSlipLength" / time / "fit.dat").string(), kHeader + body);
    }

    fs::path dir;
    dpd::MakeFoamCaseInput in;
};

const std::string kBox = "box { min (-5 -1.5 -6); max (5 1.5 6); }\n";

TEST_F(FoamCase, PlanarChannelSpansTheFluidBetweenTheWallsInTwoDimensions) {
    const dpd::FoamCaseSpec s = spec(kBox + "nu 4.5; cellSize 0.25;", dpdProperties(kChannelWalls));
    EXPECT_EQ(s.wallAxis, 2);
    EXPECT_EQ(s.dimension, 2);  // nothing varies along y
    EXPECT_DOUBLE_EQ(s.lo.z(), -5.0);
    EXPECT_DOUBLE_EQ(s.hi.z(), 5.0);
    EXPECT_DOUBLE_EQ(s.lo.x(), -5.0);
    EXPECT_DOUBLE_EQ(s.hi.y(), 1.5);
    // 40 cells across d = 10; one along the periodic axes where the flow does not vary.
    EXPECT_EQ(s.cells, (std::array<int, 3>{1, 1, 40}));
    EXPECT_TRUE(s.isPeriodic(0));
    EXPECT_FALSE(s.isPeriodic(1));
    EXPECT_FALSE(s.isPeriodic(2));
    EXPECT_DOUBLE_EQ(s.nu, 4.5);
    ASSERT_EQ(s.lines.size(), 1u);  // the default line across the channel, through cell centres and faces
    EXPECT_EQ(s.lines[0].nPoints, 161);
    EXPECT_DOUBLE_EQ(s.lines[0].start.z(), -5.0);
    EXPECT_DOUBLE_EQ(s.lines[0].end.z(), 5.0);

    const std::string mesh = dpd::foamBlockMeshDict(s);
    EXPECT_NE(mesh.find("hex (0 1 2 3 4 5 6 7) (1 1 40)"), std::string::npos) << mesh;
    EXPECT_NE(mesh.find("neighbourPatch periodicXHigh;"), std::string::npos) << mesh;
    EXPECT_NE(mesh.find("type empty;"), std::string::npos) << mesh;
    EXPECT_NE(mesh.find("(-5 -1.5 -5)"), std::string::npos) << mesh;
    EXPECT_NE(mesh.find("(5 1.5 5)"), std::string::npos) << mesh;
    const std::string u = dpd::foamVelocityField(s);
    EXPECT_NE(u.find("type            noSlip;"), std::string::npos) << u;
    EXPECT_NE(u.find("\"periodicX.*\""), std::string::npos) << u;
    EXPECT_NE(dpd::foamFvOptions(s).find("U           ((0.02 0 0) 0);"), std::string::npos) << dpd::foamFvOptions(s);
    const std::string control = dpd::foamControlDict(s);
    EXPECT_NE(control.find("type            sets;"), std::string::npos) << control;
    EXPECT_NE(control.find("nPoints 161;"), std::string::npos) << control;
}

TEST_F(FoamCase, WrittenCaseHasEveryFileAnOpenFoamUserExpects) {
    const dpd::FoamCaseSpec s = spec(kBox + "nu 4.5;", dpdProperties(kChannelWalls));
    dpd::writeFoamCase(s, (dir / "simpleFoam").string());
    for (const char* f : {"0/U", "0/p", "constant/transportProperties", "constant/turbulenceProperties",
                          "constant/dpdCase", "system/controlDict", "system/fvSchemes", "system/fvSolution",
                          "system/blockMeshDict", "system/fvOptions", "Allrun", "Allclean"})
        EXPECT_TRUE(fs::is_regular_file(dir / "simpleFoam" / f)) << f;
    EXPECT_FALSE(fs::exists(dir / "simpleFoam/system/topoSetDict"));  // no solid to cut
    // The record reads back as a dictionary (compareFVM reads it).
    const Dictionary rec = Dictionary::readFile((dir / "simpleFoam/constant/dpdCase").string());
    EXPECT_EQ(rec.get<std::string>("wallAxis"), "z");
    EXPECT_DOUBLE_EQ(rec.subDict("upperWall").get<double>("position"), 5.0);
    EXPECT_DOUBLE_EQ(rec.get<double>("nu"), 4.5);
    EXPECT_EQ(rec.get<Eigen::Vector3d>("dpdBoxMin"), Eigen::Vector3d(-5, -1.5, -6));
    const Dictionary transport = Dictionary::readFile((dir / "simpleFoam/constant/transportProperties").string());
    EXPECT_DOUBLE_EQ(transport.get<double>("nu"), 4.5);
    EXPECT_EQ(Dictionary::readFile((dir / "simpleFoam/constant/turbulenceProperties").string())
                  .get<std::string>("simulationType"), "laminar");
}

TEST_F(FoamCase, ViscosityAndSlipComeFromTheLatestFit) {
    writeFit("100", "nu 9; slipLength (9 9);");
    writeFit("300", "nu 4.25; slipLength (0.2 0.4);");
    const dpd::FoamCaseSpec s = spec(kBox + "slipLength fitted;", dpdProperties(kChannelWalls));
    EXPECT_DOUBLE_EQ(s.nu, 4.25);
    EXPECT_NE(s.nuSource.find("300"), std::string::npos) << s.nuSource;
    EXPECT_DOUBLE_EQ(s.lower.slipLength, 0.2);
    EXPECT_DOUBLE_EQ(s.upper.slipLength, 0.4);
    // partialSlip: u_w = (1 - f) U_P and u_w = beta (U_P - u_w) / (h/2)  =>  f = (h/2) / (beta + h/2).
    const double h = 0.25;
    EXPECT_DOUBLE_EQ(dpd::partialSlipValueFraction(0.2, h), 0.125 / 0.325);
    EXPECT_NE(dpd::foamVelocityField(s).find("type            partialSlip;"), std::string::npos);
    // The command line wins over the fit.
    in.nuGiven = true;
    in.nu = 3.5;
    EXPECT_DOUBLE_EQ(spec(kBox, dpdProperties(kChannelWalls)).nu, 3.5);
}

TEST_F(FoamCase, SolidCellsAreThoseWhoseCentresLieInTheMask) {
    // A 4 x 4 picture over x, z in [0, 4]: a 2 x 2 solid square (grey 0) in the middle; row 0 at the top.
    geometryTest::writePgm((dir / "constant/geometry/mask.pgm").string(),
                           {{255, 255, 255, 255}, {255, 0, 0, 255}, {255, 0, 0, 255}, {255, 255, 255, 255}});
    const std::string geometry =
        "geometry { type imageMask; file \"constant/geometry/mask.pgm\"; solidValues (0); pixelSize 1;"
        " smooth no; extrudeAxis y; }\n";
    const dpd::FoamCaseSpec s = spec("box { min (0 0 0); max (4 1 4); } nu 1; cellSize 0.5;",
                                     dpdProperties("", "(0.02 0 0)", geometry));
    EXPECT_EQ(s.cells, (std::array<int, 3>{8, 1, 8}));
    // The solid square x, z in [1, 3]: cells i, k = 2..5, labelled i + nx (j + ny k).
    std::vector<std::size_t> expected;
    for (int k = 2; k <= 5; ++k)
        for (int i = 2; i <= 5; ++i) expected.push_back(static_cast<std::size_t>(i + 8 * k));
    EXPECT_EQ(s.solidCells, expected);
    const std::string topo = dpd::foamTopoSetDict(s);
    EXPECT_NE(topo.find("source  labelToCell;"), std::string::npos) << topo;
    EXPECT_NE(topo.find("action  invert;"), std::string::npos) << topo;
    EXPECT_NE(dpd::foamBlockMeshDict(s).find("solidWalls"), std::string::npos);
    EXPECT_TRUE(s.isPeriodic(0) && s.isPeriodic(2));
}

// The dpdProperties of a case whose geometry wall asks for slip b, with the calibration it reads
// written into the case.
std::string slippingGeometryCase(const fs::path& dir, const std::string& geometry, double b) {
    geometryTest::writeText((dir / "system/controlDict").string(), "deltaT 0.01;\n");
    geometryTest::writeText((dir / "system/randomEquilWallDict").string(), "fluid { species fluid; density 3; }\n");
    fs::create_directories(dir / "cache");  // an empty user cache: the case's calibration alone
    ::setenv("DPD_SLIP_CALIBRATIONS", (dir / "cache").c_str(), 1);
    Dictionary calibration((dir / "constant/slipCalibration").string());
    dpd::test::exactSlipCalibration().writeTo(calibration);
    dpd::writeDictionaryFile((dir / "constant/slipCalibration").string(), calibration);
    return kHeader + "dimension 3; kT 1; seed 1;\nspecies { fluid { frozen no; } }\npairCoeffs { fluid-fluid { a 25; gamma 4.5; } }\n"
                     "integrator { type GrootWarren; lambda 0.65; }\nbodyForce { type uniform; value (0 0.02 0); }\n" +
           geometry + "walls { channel { type geometry; slipLength " + std::to_string(b) +
           "; tunableSlip { zc 1; epsilon 1; sigma 0.5; fluidBehind { a 25; density 3; } } } }\n";
}

// A geometry wall asking for a slip length (docs/walls.md 3.9): its twin's solidWalls take the same b
// as partialSlip, each face valueFraction (h/2) / (b + h/2) with its own h; along a flat wall every
// face slips by b.
TEST_F(FoamCase, AGeometryWallsSlipLengthGoesToTheStaircase) {
    geometryTest::writePgm((dir / "constant/geometry/mask.pgm").string(),
                           {{0, 0, 0, 0}, {255, 255, 255, 255}, {255, 255, 255, 255}, {0, 0, 0, 0}});
    const std::string props = slippingGeometryCase(
        dir, "geometry { type imageMask; file \"constant/geometry/mask.pgm\"; solidValues (0); pixelSize 1; extrudeAxis y; }\n", 1.0);
    const dpd::FoamCaseSpec s = spec("box { min (0 0 0); max (4 1 4); } nu 1; cellSize 0.5;", props);
    EXPECT_EQ(s.solidWallSlip, 1.0);
    EXPECT_FALSE(s.solidCells.empty());
    // Two layers of 8 x 2 cells (x, y) face the solid: 32 faces normal to z, each slipping by b.
    ASSERT_EQ(s.staircaseFaces.size(), 32u);
    for (const dpd::StaircaseFace& f : s.staircaseFaces) {
        EXPECT_EQ(f.axis, 2);
        EXPECT_DOUBLE_EQ(f.slipLength, 1.0);
        EXPECT_TRUE(f.halfCells[2] == 4 || f.halfCells[2] == 12) << f.halfCells[2];  // z = 1 and 3
    }
    const std::string u = dpd::foamVelocityField(s);
    const std::size_t walls = u.find("solidWalls");
    ASSERT_NE(walls, std::string::npos) << u;
    EXPECT_NE(u.find("type            partialSlip;", walls), std::string::npos) << u;
    // h = 0.5: (0.25) / (1 + 0.25) = 0.2 on every face.
    EXPECT_NE(u.find("valueFraction   uniform 0.2;", walls), std::string::npos) << u;
    EXPECT_NE(dpd::foamStaircaseSlip(s).find("\n1 1 4 0.2 1\n"), std::string::npos) << dpd::foamStaircaseSlip(s);
    // Cells of 0.5 along x and 1 along z: the faces normal to z take h = 1, (0.5) / (1 + 0.5).
    const dpd::FoamCaseSpec tall = spec("box { min (0 0 0); max (4 1 4); } nu 1; cells (8 1 4);", props);
    ASSERT_FALSE(tall.staircaseFaces.empty());
    EXPECT_NE(dpd::foamVelocityField(tall).find("valueFraction   uniform " + std::to_string(1.0 / 3.0).substr(0, 6)),
              std::string::npos) << dpd::foamVelocityField(tall);
}

// Along a curved wall each staircase face slips by b |n|_1, n the wall's normal at the face: a pipe of
// radius 4 drawn in gmsh as a polygon of edges 0.05 long, whose normals are the circle's to 0.05 / 4.
TEST_F(FoamCase, ACurvedWallsStaircaseFacesSlipByTheirLengthPerUnitOfWall) {
    geometryTest::writeText((dir / "constant/geometry/pipe.geo").string(),
                            "R = 4; lc = 0.05;\nPoint(1) = {0, 0, 0, lc};\n"
                            "Point(2) = {R, 0, 0, lc}; Point(3) = {0, R, 0, lc}; Point(4) = {-R, 0, 0, lc}; Point(5) = {0, -R, 0, lc};\n"
                            "Circle(1) = {2, 1, 3}; Circle(2) = {3, 1, 4}; Circle(3) = {4, 1, 5}; Circle(4) = {5, 1, 2};\n"
                            "Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1}; Physical Surface(\"fluid\") = {1};\n");
    const std::string props = slippingGeometryCase(
        dir, "geometry { type gmsh; file \"constant/geometry/pipe.geo\"; extrudeAxis y; }\n", 2.0);
    const dpd::FoamCaseSpec s = spec("box { min (-5 -1.5 -5); max (5 1.5 5); } nu 1; dimension 3; cells (40 1 40);", props);
    ASSERT_GT(s.staircaseFaces.size(), 100u);
    double largest = 0.0;
    for (const dpd::StaircaseFace& f : s.staircaseFaces) {
        const double x = -5.0 + 0.125 * static_cast<double>(f.halfCells[0]);
        const double z = -5.0 + 0.125 * static_cast<double>(f.halfCells[2]);
        const double r = std::hypot(x, z);
        EXPECT_NEAR(r, 4.0, 0.25 * std::sqrt(2.0)) << "a face away from the wall at (" << x << ", " << z << ")";
        EXPECT_NEAR(f.slipLength, 2.0 * (std::abs(x) + std::abs(z)) / r, 2.0 * 1.5 * 0.05 / 4.0) << x << " " << z;
        largest = std::max(largest, f.slipLength);
    }
    EXPECT_GT(largest, 2.0 * 1.4);  // faces near 45 degrees carry b sqrt(2)
}

TEST_F(FoamCase, WhatTheContinuumCaseCannotHoldIsRefused) {
    const std::string oneWall = "walls { lower { type plane; point (0 0 -5); normal (0 0 1); } }\n";
    expectRefused(kBox + "nu 1;", dpdProperties(oneWall), "dpdProperties", "walls");
    const std::string oblique =
        "walls { lower { type plane; point (0 0 -5); normal (0 0.6 0.8); }"
        " upper { type plane; point (0 0 5); normal (0 0 -1); } }\n";
    expectRefused(kBox + "nu 1;", dpdProperties(oblique), "dpdProperties", "walls");
    const std::string reverse = dpdProperties("", "(0.02 0 0)").replace(
        dpdProperties("", "(0.02 0 0)").find("type uniform"), 12, "type reversePoiseuille; gradientAxis z");
    expectRefused(kBox + "nu 1;", reverse, "dpdProperties", "bodyForce");
    expectRefused(kBox + "nu 1; dimension 2;", dpdProperties(kChannelWalls, "(0.02 0.01 0)"), "makeFoamCaseDict", "dimension");
    expectRefused("nu 1;", dpdProperties(kChannelWalls), "makeFoamCaseDict", "box");      // no box, no snapshot
    expectRefused(kBox, dpdProperties(kChannelWalls), "makeFoamCaseDict", "nu");          // no nu, no fit
    expectRefused(kBox + "nu 1; slipLength -0.1;", dpdProperties(kChannelWalls), "makeFoamCaseDict", "slipLength");
    expectRefused(kBox + "nu 1; cellsize 0.5;", dpdProperties(kChannelWalls), "makeFoamCaseDict", "cellsize");
    expectRefused(kBox + "nu 1; lines { a { start (0 0 -9); end (0 0 5); } }", dpdProperties(kChannelWalls),
                  "makeFoamCaseDict", "start");
}

}  // namespace
