// A planar wall that asks for a slip length (docs/walls.md 3.8): its friction and plane from the
// case's slip calibration, said in the log, and a clear error for every ask it cannot meet.
#include "../support/ExactSlipCalibration.hpp"
#include "../support/InputErrorOf.hpp"
#include "case/DpdProperties.hpp"
#include "core/Error.hpp"
#include "io/Dictionary.hpp"
#include "walls/SlipCalibration.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

using namespace dpd;
namespace fs = std::filesystem;

namespace {

std::string wallEntry(const std::string& name, double z, double nz, const std::string& ask) {
    return name + " { type plane; point (0 0 " + std::to_string(z) + "); normal (0 0 " + std::to_string(nz) + "); " + ask +
           " }\n";
}

const std::string kModel = "tunableSlip { zc 1; epsilon 1; sigma 0.5; fluidBehind { a 25; density 3; } }";

std::string properties(const std::string& lowerAsk, double a = 25) {
    return "kT 1;\nspecies { fluid { frozen no; } }\npairCoeffs { fluid-fluid { a " + std::to_string(a) +
           "; gamma 4.5; } }\nintegrator { type GrootWarren; lambda 0.65; }\nwalls {\n" +
           wallEntry("lower", -5, 1, lowerAsk) + wallEntry("upper", 5, -1, "slipLength 2; " + kModel + ";") + "}\n";
}

// A case with its calibration in constant/slipCalibration and an empty user cache.
struct CalibratedCase {
    fs::path dir = fs::temp_directory_path() / ("dpdSlipLengthWall-" + std::to_string(::getpid()));
    CalibratedCase() {
        fs::create_directories(dir / "constant");
        fs::create_directories(dir / "system");
        fs::create_directories(dir / "cache");
        ::setenv("DPD_SLIP_CALIBRATIONS", (dir / "cache").c_str(), 1);
        std::ofstream(dir / "system" / "controlDict") << "deltaT 0.01;\n";
        std::ofstream(dir / "system" / "blockFrozenWallDict") << "fluid { species fluid; density 3; }\n";
        const std::string file = (dir / "constant" / "slipCalibration").string();
        Dictionary d(file);
        test::exactSlipCalibration().writeTo(d);
        writeDictionaryFile(file, d);
    }
    ~CalibratedCase() {
        ::unsetenv("DPD_SLIP_CALIBRATIONS");
        fs::remove_all(dir);
    }
    DpdModel read(const std::string& text) const {
        return readDpdModel(Dictionary::parse(text, "constant/dpdProperties"), dir.string());
    }
    std::string errorOf(const std::string& text) const {
        return test::inputErrorOf([&] { read(text); });
    }
};

}  // namespace

TEST(SlipLengthWall, TakesTheCalibratedFrictionAndMovesItsPlaneBehindThePoint) {
    const CalibratedCase c;
    const DpdModel m = c.read(properties("slipLength 2; " + kModel + ";"));
    ASSERT_EQ(m.planarWalls.size(), 2u);
    for (const PlanarWallSettings& w : m.planarWalls) {
        EXPECT_TRUE(w.asksSlipLength);
        EXPECT_EQ(w.slipLength, 2.0);
        // b = 3 / gamma_L - 0.4 = 2: gamma_L 1.25, between the calibrated 0.5 and 2.
        EXPECT_NEAR(w.tunableSlip.gammaL, 1.25, 1e-12);
        EXPECT_EQ(w.planeOffset, 0.3);
    }
    // The user's point stays where the flow sees the wall; the acting plane is 0.3 behind it.
    EXPECT_EQ(m.planarWalls[0].point.z(), -5.0);
    EXPECT_NEAR(m.planarWalls[0].actingPoint().z(), -5.3, 1e-12);
    EXPECT_NEAR(m.planarWalls[1].actingPoint().z(), 5.3, 1e-12);
    EXPECT_NEAR(m.walls[0].signedDistance({0, 0, -5}), 0.3, 1e-12);
    EXPECT_NEAR(m.walls[1].signedDistance({0, 0, 5}), 0.3, 1e-12);
    EXPECT_NEAR(m.planarWalls[0].signedDistance(0, 0, -5.3), 0.0, 1e-12);
    ASSERT_EQ(m.wallNotes.size(), 2u);
    EXPECT_NE(m.wallNotes[0].find("wall lower: slipLength 2 from " + (c.dir / "constant" / "slipCalibration").string() +
                                  ": gammaL 1.25"), std::string::npos) << m.wallNotes[0];
    EXPECT_NE(m.wallNotes[0].find("0.3 +- 0.02 behind"), std::string::npos) << m.wallNotes[0];
}

TEST(SlipLengthWall, AWallWithItsFrictionGivenIsReadAsBefore) {
    const CalibratedCase c;
    const DpdModel m = c.read(properties("tunableSlip { gammaL 2; zc 1; epsilon 1; sigma 0.5; fluidBehind { a 25; density 3; } };"));
    EXPECT_FALSE(m.planarWalls[0].asksSlipLength);
    EXPECT_EQ(m.planarWalls[0].tunableSlip.gammaL, 2.0);
    EXPECT_EQ(m.planarWalls[0].planeOffset, 0.0);
    EXPECT_EQ(m.walls[0].signedDistance({0, 0, -5}), 0.0);
    EXPECT_EQ(m.wallNotes.size(), 1u) << "the upper wall's ask alone";
}

TEST(SlipLengthWall, RefusesANegativeSlipLengthAtItsKeyword) {
    const std::string e = CalibratedCase().errorOf(properties("slipLength -1; " + kModel + ";"));
    EXPECT_NE(e.find("slipLength"), std::string::npos) << e;
    EXPECT_NE(e.find("negative"), std::string::npos) << e;
}

TEST(SlipLengthWall, RefusesASlipLengthBeyondTheCalibrationNamingTheRangeAndTheCommand) {
    const std::string e = CalibratedCase().errorOf(properties("slipLength 12; " + kModel + ";"));
    EXPECT_NE(e.find("keyword 'slipLength'"), std::string::npos) << e;
    EXPECT_NE(e.find("(in walls/lower)"), std::string::npos) << e;
    EXPECT_NE(e.find("outside the calibrated range 0 to 11.6"), std::string::npos) << e;
    EXPECT_NE(e.find("hydrodynamicWall -calibration"), std::string::npos) << e;
}

TEST(SlipLengthWall, RefusesAFluidWithoutCalibrationNamingWhatDiffers) {
    const std::string e = CalibratedCase().errorOf(properties("slipLength 2; " + kModel + ";", 18.75));
    EXPECT_NE(e.find("keyword 'slipLength'"), std::string::npos) << e;
    EXPECT_NE(e.find("fluid/a 18.75 against 25"), std::string::npos) << e;
    EXPECT_NE(e.find("hydrodynamicWall -calibration"), std::string::npos) << e;
}

TEST(SlipLengthWall, RefusesAWallModelWithoutCalibration) {
    const std::string e = CalibratedCase().errorOf(properties("slipLength 2; tunableSlip { zc 1; epsilon 1; sigma 0.5; };"));
    EXPECT_NE(e.find("wall/fluidBehind/a 0 against 25"), std::string::npos) << e;
}

TEST(SlipLengthWall, RefusesTheFrictionGivenTogetherWithTheSlipLength) {
    const std::string e = CalibratedCase().errorOf(
        properties("slipLength 2; tunableSlip { gammaL 1; zc 1; epsilon 1; sigma 0.5; fluidBehind { a 25; density 3; } };"));
    EXPECT_NE(e.find("gammaL"), std::string::npos) << e;
    EXPECT_NE(e.find("give one of the two"), std::string::npos) << e;
}

TEST(SlipLengthWall, NeedsTheWallModel) {
    const std::string e = CalibratedCase().errorOf(properties("slipLength 2;"));
    EXPECT_NE(e.find("keyword 'slipLength'"), std::string::npos) << e;
    EXPECT_NE(e.find("needs the wall's model"), std::string::npos) << e;
}

TEST(SlipLengthWall, RefusesStripes) {
    const std::string e = CalibratedCase().errorOf(properties(
        "slipLength 2; tunableSlip { zc 1; epsilon 1; sigma 0.5; fluidBehind { a 25; density 3; } stripes { axis x; "
        "period 10; gasFraction 0.5; gammaGas 0.1; } };"));
    EXPECT_NE(e.find("stripes"), std::string::npos) << e;
}

TEST(SlipLengthWall, IsRefusedWithoutItsCase) {
    const std::string e = test::inputErrorOf(
        [&] { readDpdModel(Dictionary::parse(properties("slipLength 2; " + kModel + ";"), "constant/dpdProperties")); });
    EXPECT_NE(e.find("keyword 'slipLength'"), std::string::npos) << e;
    EXPECT_NE(e.find("read it with its case"), std::string::npos) << e;
}

TEST(SlipLengthWall, NeedsTheBuildersDensity) {
    const CalibratedCase c;
    fs::remove(c.dir / "system" / "blockFrozenWallDict");
    try {
        c.read(properties("slipLength 2; " + kModel + ";"));
        FAIL() << "a slip length read without the fluid's density";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("blockFrozenWallDict"), std::string::npos) << e.what();
    }
}
