// The slip-length calibration (walls/SlipCalibration.hpp): the friction for an asked b, the calibrated
// range, the key that says which fluid and wall model a calibration holds for, and its file.
#include "../support/ExactSlipCalibration.hpp"
#include "../support/InputErrorOf.hpp"
#include "core/Error.hpp"
#include "io/Dictionary.hpp"
#include "walls/SlipCalibration.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

using namespace dpd;
namespace fs = std::filesystem;

namespace {

SlipCalibrationKey standardFluidKey() { return test::standardFluidSlipKey(); }

SlipCalibration exactCalibration(SlipCalibrationKey key = standardFluidKey()) { return test::exactSlipCalibration(key); }

struct TempDir {
    fs::path path = fs::temp_directory_path() / ("dpdSlipCalibration-" + std::to_string(::getpid()));
    TempDir() { fs::create_directories(path); }
    ~TempDir() { fs::remove_all(path); }
};

}  // namespace

TEST(SlipCalibration, GivesTheFrictionOfASlipLengthThatIsLinearInItsInverse) {
    const SlipCalibration c = exactCalibration();
    EXPECT_DOUBLE_EQ(c.largestSlip(), 11.6);
    EXPECT_DOUBLE_EQ(c.smallestSlip(), 3.0 / 8.0 - 0.4);
    for (double g : {0.25, 0.3, 0.5, 1.0, 3.7, 8.0}) {
        const CalibratedFriction f = c.frictionFor(3.0 / g - 0.4);
        EXPECT_NEAR(f.gammaL, g, 1e-12 * g) << "b = " << 3.0 / g - 0.4;
    }
    // Halfway in b between gamma_L 0.5 and 2 (b 5.6 and 1.1): the error halfway between 0.005 and 0.02.
    EXPECT_NEAR(c.frictionFor(3.35).slipLengthError, 0.0125, 1e-12);
}

TEST(SlipCalibration, RefusesASlipLengthOutsideItsRangeNamingTheRange) {
    const SlipCalibration c = exactCalibration();
    try {
        c.frictionFor(12.0);
        FAIL() << "b beyond the calibration accepted";
    } catch (const std::out_of_range& e) {
        EXPECT_NE(std::string(e.what()).find("outside the calibrated range -0.025 to 11.6"), std::string::npos) << e.what();
    }
    EXPECT_THROW(c.frictionFor(-0.1), std::out_of_range);
    EXPECT_THROW(c.frictionFor(std::nan("")), std::out_of_range);
}

TEST(SlipCalibration, RefusesASlipThatDoesNotFallWithTheFriction) {
    const std::vector<SlipCalibrationPoint> rising{{1.0, 2.0, 0.1}, {2.0, 2.5, 0.1}};
    EXPECT_THROW(SlipCalibration(standardFluidKey(), rising, 0.3, 0.02, "test"), std::invalid_argument);
    const std::vector<SlipCalibrationPoint> one{{1.0, 2.0, 0.1}};
    EXPECT_THROW(SlipCalibration(standardFluidKey(), one, 0.3, 0.02, "test"), std::invalid_argument);
}

TEST(SlipCalibration, ItsKeyNamesTheFirstEntryThatDiffers) {
    const SlipCalibrationKey k = standardFluidKey();
    EXPECT_EQ(k.firstDifference(k), "");
    SlipCalibrationKey idealGas = k;
    idealGas.a = 0;
    EXPECT_EQ(k.firstDifference(idealGas), "fluid/a 25 against 0");
    SlipCalibrationKey otherStep = k;
    otherStep.integrator = "GrootWarren lambda 0.5";
    EXPECT_EQ(k.firstDifference(otherStep), "step/integrator 'GrootWarren lambda 0.65' against 'GrootWarren lambda 0.5'");
    SlipCalibrationKey tangential = k;
    tangential.tangentialOnly = true;
    EXPECT_EQ(k.firstDifference(tangential), "wall/friction full against tangential");
}

TEST(SlipCalibration, ReadsBackWhatItWrites) {
    TempDir dir;
    const std::string file = (dir.path / "slipCalibration").string();
    Dictionary d(file);
    exactCalibration().writeTo(d);
    writeDictionaryFile(file, d);
    const SlipCalibration back = SlipCalibration::read(Dictionary::readFile(file));
    EXPECT_EQ(back.key().firstDifference(standardFluidKey()), "");
    ASSERT_EQ(back.points().size(), 4u);
    EXPECT_EQ(back.points()[1].gammaL, 0.5);
    EXPECT_EQ(back.points()[1].slipLength, 5.6);
    EXPECT_EQ(back.wallOffset(), 0.3);
    EXPECT_EQ(back.source(), file);
}

TEST(SlipCalibration, AFileWithListsOfDifferentLengthsIsAnInputErrorAtTheList) {
    TempDir dir;
    const std::string file = (dir.path / "slipCalibration").string();
    Dictionary d(file);
    exactCalibration().writeTo(d);
    d.set("slipLengthError", "(0.1 0.2)");
    writeDictionaryFile(file, d);
    const std::string message = test::inputErrorOf([&] { SlipCalibration::read(Dictionary::readFile(file)); });
    EXPECT_NE(message.find("slipLengthError"), std::string::npos) << message;
    EXPECT_NE(message.find("one error per gammaL"), std::string::npos) << message;
}

// Sets an environment variable for the scope (unset: nullptr), restoring it after.
struct ScopedEnvironment {
    std::string name;
    std::optional<std::string> before;
    ScopedEnvironment(std::string n, const char* value) : name(std::move(n)) {
        if (const char* v = std::getenv(name.c_str())) before = v;
        if (value) ::setenv(name.c_str(), value, 1);
        else ::unsetenv(name.c_str());
    }
    ~ScopedEnvironment() {
        if (before) ::setenv(name.c_str(), before->c_str(), 1);
        else ::unsetenv(name.c_str());
    }
};

TEST(SlipCalibration, IsFoundInTheCaseOrTheCacheByItsKey) {
    const ScopedEnvironment noProject("DPD_PROJECT_DIR", nullptr);  // its shipped calibrations come last (below)
    TempDir dir;
    fs::create_directories(dir.path / "case" / "constant");
    fs::create_directories(dir.path / "cache");
    SlipCalibrationKey idealGas = standardFluidKey();
    idealGas.a = 0;
    const std::pair<fs::path, SlipCalibrationKey> files[] = {{dir.path / "case" / "constant" / "slipCalibration", idealGas},
                                                             {dir.path / "cache" / "standardFluid", standardFluidKey()}};
    for (const auto& [path, key] : files) {
        Dictionary d(path.string());
        exactCalibration(key).writeTo(d);
        writeDictionaryFile(path.string(), d);
    }
    ::setenv("DPD_SLIP_CALIBRATIONS", (dir.path / "cache").c_str(), 1);
    const std::vector<std::string> searched = slipCalibrationFiles((dir.path / "case").string());
    ::unsetenv("DPD_SLIP_CALIBRATIONS");
    ASSERT_EQ(searched.size(), 2u);
    EXPECT_EQ(searched[0], files[0].first.string()) << "the case's own first";
    EXPECT_EQ(findSlipCalibration(searched, idealGas).source(), files[0].first.string());
    EXPECT_EQ(findSlipCalibration(searched, standardFluidKey()).source(), files[1].first.string());
    SlipCalibrationKey hotter = standardFluidKey();
    hotter.kT = 1.5;
    try {
        findSlipCalibration(searched, hotter);
        FAIL() << "a fluid without calibration accepted";
    } catch (const std::runtime_error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find(files[0].first.string() + ": fluid/a 25 against 0"), std::string::npos) << what;
        EXPECT_NE(what.find(files[1].first.string() + ": fluid/kT 1.5 against 1"), std::string::npos) << what;
    }
}

// The project's shipped calibrations ($DPD_PROJECT_DIR/etc/slipCalibrations) come after the case's and the
// user's, in name order, their README left out.
TEST(SlipCalibration, TheProjectsShippedCalibrationsComeLast) {
    TempDir dir;
    const fs::path shipped = dir.path / "project" / "etc" / "slipCalibrations";
    fs::create_directories(shipped);
    fs::create_directories(dir.path / "cache");
    for (const char* name : {"standardFluid", "README", "idealGas"}) std::ofstream(shipped / name) << "\n";
    std::ofstream(dir.path / "cache" / "mine") << "\n";
    const ScopedEnvironment project("DPD_PROJECT_DIR", (dir.path / "project").c_str());
    const ScopedEnvironment cache("DPD_SLIP_CALIBRATIONS", (dir.path / "cache").c_str());
    const std::vector<std::string> searched = slipCalibrationFiles((dir.path / "case").string());
    const std::vector<std::string> expected{(dir.path / "case" / "constant" / "slipCalibration").string(),
                                            (dir.path / "cache" / "mine").string(), (shipped / "idealGas").string(),
                                            (shipped / "standardFluid").string()};
    EXPECT_EQ(searched, expected);
}

TEST(SlipCalibration, GivesSlipsBelowItsRangeByMovingTheStiffestWallOut) {
    // The stiffest wall slips 0.2 from where it acts, 0.7 in front of its plane.
    const std::vector<SlipCalibrationPoint> points{{0.5, 5.6, 0.05}, {2.0, 1.1, 0.02}, {16.0, 0.2, 0.1}};
    const SlipCalibration c(standardFluidKey(), points, 0.7, 0.05, "test");
    const CalibratedFriction inside = c.wallFor(1.1);
    EXPECT_EQ(inside.gammaL, 2.0);
    EXPECT_EQ(inside.planeOffset, 0.7);
    EXPECT_EQ(inside.slipLengthError, 0.02);
    // No slip: the stiffest friction, its plane 0.2 less far behind, so that the flow's zero lies at
    // the user's point.
    const CalibratedFriction noSlip = c.wallFor(0.0);
    EXPECT_EQ(noSlip.gammaL, 16.0);
    EXPECT_NEAR(noSlip.planeOffset, 0.5, 1e-15);
    EXPECT_EQ(noSlip.slipLengthError, 0.1);
    EXPECT_NEAR(c.wallFor(0.15).planeOffset, 0.65, 1e-15);
    EXPECT_EQ(c.wallFor(0.2).planeOffset, 0.7) << "continuous at the range's end";
    try {
        c.wallFor(5.7);
        FAIL() << "b beyond the calibration accepted";
    } catch (const std::out_of_range& e) {
        EXPECT_NE(std::string(e.what()).find("outside the calibrated range 0 to 5.6"), std::string::npos) << e.what();
    }
    EXPECT_THROW(c.wallFor(-0.01), std::out_of_range);
    EXPECT_THROW(c.wallFor(std::nan("")), std::out_of_range);
}
