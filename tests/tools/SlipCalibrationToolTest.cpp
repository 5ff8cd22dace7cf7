// slipCalibration on a calibration made for it, b = 3 / gamma_L - 0.2 at four frictions (exactly linear
// in 1 / gamma_L, so the friction for any b in range is 3 / (b + 0.2)): the range, each asked b's
// friction, error, plane offset and the slip left, below the range the stiffest friction with its plane
// moved out; a b outside 0 .. the largest, and a missing file, refused by name.
#include "tools/SlipCalibrationTool.hpp"

#include "../support/ExactSlipCalibration.hpp"
#include "../support/InputErrorOf.hpp"
#include "io/Dictionary.hpp"
#include "walls/SlipCalibration.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace dpd {
namespace {

constexpr double kOffset = 0.3, kShift = 0.2;

struct CalibrationFile {
    fs::path path = fs::temp_directory_path() / ("slipCalibrationTool" + std::to_string(::getpid()));
    CalibrationFile() {
        std::vector<SlipCalibrationPoint> points;
        for (double g : {8.0, 0.5, 2.0, 0.25}) points.push_back({g, 3.0 / g - kShift, 0.01 * g});
        Dictionary d(path.string());
        SlipCalibration(test::standardFluidSlipKey(), points, kOffset, 0.02, "test").writeTo(d);
        writeDictionaryFile(path.string(), d);
    }
    ~CalibrationFile() { fs::remove(path); }
};

Dictionary printed(const std::string& file, std::vector<double> slips) {
    std::ostringstream out;
    printSlipCalibration({file, std::move(slips)}, out);
    return Dictionary::parse(out.str(), "printed");
}

TEST(SlipCalibrationTool, PrintsTheRangeAndTheWallOfEachAskedSlipLength) {
    const CalibrationFile file;
    const Dictionary d = printed(file.path.string(), {5.0, 1.0, 3.0 / 8.0 - kShift, 0.0});
    EXPECT_DOUBLE_EQ(d.get<double>("smallestSlip"), 3.0 / 8.0 - kShift);
    EXPECT_DOUBLE_EQ(d.get<double>("largestSlip"), 3.0 / 0.25 - kShift);
    EXPECT_DOUBLE_EQ(d.get<double>("wallOffset"), kOffset);
    const auto gammas = d.get<std::vector<double>>("gammaL");
    const auto errors = d.get<std::vector<double>>("slipLengthError");
    const auto planes = d.get<std::vector<double>>("planeOffset");
    const auto left = d.get<std::vector<double>>("slipLeft");
    ASSERT_EQ(gammas.size(), 4u);
    for (int k = 0; k < 3; ++k) {
        const double b = d.get<std::vector<double>>("slipLength")[k];
        EXPECT_NEAR(gammas[k], 3.0 / (b + kShift), 1e-8 * gammas[k]) << "b " << b;
        EXPECT_DOUBLE_EQ(planes[k], kOffset);
        EXPECT_DOUBLE_EQ(left[k], b);
    }
    // b 1 lies between gamma_L 2 (b 1.3, error 0.02) and 8 (b 0.175, error 0.08): t = 0.3 / 1.125.
    EXPECT_NEAR(errors[1], 0.02 + (0.3 / 1.125) * 0.06, 1e-9);
    // No slip lies below the range: the stiffest friction, its plane 0.175 less far behind.
    EXPECT_DOUBLE_EQ(gammas[3], 8.0);
    EXPECT_NEAR(planes[3], kOffset - (3.0 / 8.0 - kShift), 1e-9);
    EXPECT_NEAR(left[3], 3.0 / 8.0 - kShift, 1e-9);
}

TEST(SlipCalibrationTool, WithoutSlipLengthsPrintsTheRangeAlone) {
    const CalibrationFile file;
    const Dictionary d = printed(file.path.string(), {});
    EXPECT_TRUE(d.found("largestSlip"));
    EXPECT_FALSE(d.found("gammaL"));
}

TEST(SlipCalibrationTool, RefusesASlipLengthOutsideTheCalibrationByName) {
    const CalibrationFile file;
    for (double b : {12.0, -0.1}) {
        try {
            printed(file.path.string(), {1.0, b});
            ADD_FAILURE() << "b " << b << " was not refused";
        } catch (const std::invalid_argument& e) {
            EXPECT_NE(std::string(e.what()).find("-slipLength"), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("calibrated range"), std::string::npos) << e.what();
        }
    }
}

TEST(SlipCalibrationTool, RefusesAMissingFileByName) {
    const std::string missing = (fs::temp_directory_path() / "noSuchSlipCalibration").string();
    EXPECT_NE(test::inputErrorOf([&] { printed(missing, {1.0}); }).find(missing), std::string::npos);
}

}  // namespace
}  // namespace dpd
