// compareFVM's arithmetic on synthetic profiles whose errors are known, and its readers of OpenFOAM
// output (ascii fields, raw sampled lines) with the errors they give for bad files.
#include "core/Error.hpp"
#include "foam/FieldComparison.hpp"
#include "foam/FoamFieldFiles.hpp"
#include "../geometry/GeometryTestFiles.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <random>

namespace {

namespace fs = std::filesystem;

std::vector<double> parabola(const std::vector<double>& z) {
    std::vector<double> u;
    for (double x : z) u.push_back(0.01 * (x + 5) * (5 - x));
    return u;
}

std::vector<double> centres(int n, double lo, double hi) {
    std::vector<double> z;
    for (int i = 0; i < n; ++i) z.push_back(lo + (i + 0.5) * (hi - lo) / n);
    return z;
}

TEST(FieldComparison, ScaledProfileHasTheScaleAsL2LinfAndMeanRatio) {
    const std::vector<double> fvm = parabola(centres(40, -5, 5));
    std::vector<double> dpd;
    for (double u : fvm) dpd.push_back(1.03 * u);
    const dpd::ComparisonMetrics m = dpd::compareValues(dpd, {}, fvm);
    EXPECT_EQ(m.points, 40);
    EXPECT_NEAR(m.L2, 0.03, 1e-14);
    EXPECT_NEAR(m.Linf, 0.03, 1e-14);
    EXPECT_NEAR(m.meanVelocityRatio, 1.03, 1e-14);
    EXPECT_EQ(m.noiseL2, 0.0);
}

TEST(FieldComparison, ConstantOffsetGivesTheRmsOverTheProfile) {
    const std::vector<double> fvm = parabola(centres(20, -5, 5));
    std::vector<double> dpd, err(fvm.size(), 0.01);
    double sum2 = 0.0, mx = 0.0;
    for (double u : fvm) {
        dpd.push_back(u + 0.002);
        sum2 += u * u;
        mx = std::max(mx, u);
    }
    const dpd::ComparisonMetrics m = dpd::compareValues(dpd, err, fvm);
    EXPECT_NEAR(m.L2, 0.002 * std::sqrt(20.0 / sum2), 1e-14);
    EXPECT_NEAR(m.Linf, 0.002 / mx, 1e-14);
    EXPECT_NEAR(m.noiseL2, 0.01 * std::sqrt(20.0 / sum2), 1e-14);
}

// When the DPD values scatter about the FVM with the standard errors they quote, L2 ~ noiseL2: over 400
// bins L2^2 / noiseL2^2 is a chi^2/400 with relative standard deviation sqrt(2/400) = 7 %; 5 sigma: 35 %.
TEST(FieldComparison, NoiseOfTheQuotedSizeGivesL2NearNoiseL2) {
    const std::vector<double> fvm = parabola(centres(400, -5, 5));
    std::mt19937_64 rng(11);
    std::normal_distribution<double> noise(0.0, 0.01);
    std::vector<double> dpd, err(fvm.size(), 0.01);
    for (double u : fvm) dpd.push_back(u + noise(rng));
    const dpd::ComparisonMetrics m = dpd::compareValues(dpd, err, fvm);
    EXPECT_NEAR(m.L2 * m.L2 / (m.noiseL2 * m.noiseL2), 1.0, 5 * std::sqrt(2.0 / 400));
}

TEST(FieldComparison, PointsOutsideTheContinuumAreLeftOut) {
    const double nan = std::nan("");
    const dpd::ComparisonMetrics m = dpd::compareValues({5, 1, 2, 7}, {}, {nan, 1, 2, nan});
    EXPECT_EQ(m.points, 2);
    EXPECT_EQ(m.L2, 0.0);
    EXPECT_THROW(dpd::compareValues({1, 2}, {}, {1}), std::invalid_argument);
    EXPECT_THROW(dpd::compareValues({1}, {}, {nan}), std::invalid_argument);
    EXPECT_THROW(dpd::compareValues({1}, {}, {0}), std::invalid_argument);
}

TEST(FieldComparison, LinearInterpolationIsExactForLinesAndUndefinedOutside) {
    const std::vector<double> x{0, 1, 3};
    const std::vector<double> v{1, 3, 7};  // 1 + 2x
    EXPECT_DOUBLE_EQ(dpd::interpolateLinear(x, v, 2.5), 6.0);
    EXPECT_DOUBLE_EQ(dpd::interpolateLinear(x, v, 3.0), 7.0);
    EXPECT_DOUBLE_EQ(dpd::interpolateLinear(x, v, 0.0), 1.0);
    EXPECT_TRUE(std::isnan(dpd::interpolateLinear(x, v, -0.1)));
    EXPECT_TRUE(std::isnan(dpd::interpolateLinear(x, v, 3.1)));
}

TEST(FieldComparison, LayersAverageTheFluidCellsAcrossTheAxis) {
    // 4 x 3 cells in x-z; u = 2 z + x: the mean over x of each z-layer is 2 z + mean(x).
    std::vector<Eigen::Vector3d> c, U;
    for (int k = 0; k < 3; ++k)
        for (int i = 0; i < 4; ++i) {
            c.emplace_back(i + 0.5, 0.0, 0.25 + 0.5 * k + 1e-15 * i);  // round-off within a layer
            U.emplace_back(2 * (0.25 + 0.5 * k) + (i + 0.5), 0.0, 0.0);
        }
    const dpd::LayerProfile p = dpd::layerAverage(c, U, 2, 0, 0.125);
    ASSERT_EQ(p.x.size(), 3u);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(p.u[k], 2 * (0.25 + 0.5 * k) + 2.0, 1e-12);
    // Continued linearly to the walls at 0 and 1.5.
    const dpd::LayerProfile e = dpd::extendToBounds(p, 0.0, 1.5);
    ASSERT_EQ(e.x.size(), 5u);
    EXPECT_NEAR(e.u.front(), 2.0, 1e-12);
    EXPECT_NEAR(e.u.back(), 5.0, 1e-12);
}

class FoamFiles : public ::testing::Test {
protected:
    void SetUp() override {
        dir = fs::temp_directory_path() / ("foamFilesTest" + std::to_string(::getpid()));
        fs::create_directories(dir);
    }
    void TearDown() override { fs::remove_all(dir); }
    std::string write(const std::string& name, const std::string& text) {
        geometryTest::writeText((dir / name).string(), text);
        return (dir / name).string();
    }
    fs::path dir;
};

const std::string kFieldHead = "FoamFile\n{\n    version 2.0;\n    format      ascii;\n    class volVectorField;\n}\n"
                               "dimensions [0 1 -1 0 0 0 0];\n";

TEST_F(FoamFiles, AsciiVectorFieldsReadUniformAndNonuniform) {
    const auto v = dpd::readFoamVectorField(write("U", kFieldHead +
        "internalField   nonuniform List<vector>\n3\n(\n(0.025 0 0)\n(1e-3 -2 3.5)\n(0 0 0)\n)\n;\n"
        "boundaryField { lower { type noSlip; } }\n"));
    ASSERT_EQ(v.size(), 3u);
    EXPECT_EQ(v[1], Eigen::Vector3d(1e-3, -2, 3.5));
    const auto u = dpd::readFoamVectorField(write("U0", kFieldHead + "internalField uniform (1 2 3);\nboundaryField {}\n"), 4);
    ASSERT_EQ(u.size(), 4u);
    EXPECT_EQ(u[3], Eigen::Vector3d(1, 2, 3));
}

TEST_F(FoamFiles, BadFieldFilesNameTheFile) {
    const auto expectIoError = [](const std::string& path, const std::string& what) {
        try {
            dpd::readFoamVectorField(path);
            ADD_FAILURE() << "expected an IoError for " << path;
        } catch (const dpd::IoError& e) {
            EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
        }
    };
    expectIoError((dir / "missing").string(), "cannot open");
    expectIoError(write("p", kFieldHead + "internalField nonuniform List<scalar> 2(1 2);\n"), "List<vector>");
    expectIoError(write("short", kFieldHead + "internalField nonuniform List<vector> 3((1 2 3) (4 5 6));\n"), "expected a vector");
    expectIoError(write("bin", "FoamFile { format      binary; }\ninternalField nonuniform List<vector> 1(...)\n"), "binary");
    expectIoError(write("none", kFieldHead), "no internalField");
}

TEST_F(FoamFiles, RawSampledLinesReadAndBadRowsNameTheLine) {
    const auto l = dpd::readFoamSampledLine(write("line_U.xy", "0 0 -5 0 0 0\n0 0 0 0.25 0 0\n0 0 5 0 0 0\n"));
    ASSERT_EQ(l.points.size(), 3u);
    EXPECT_EQ(l.values[1], Eigen::Vector3d(0.25, 0, 0));
    try {
        dpd::readFoamSampledLine(write("bad_U.xy", "0 0 -5 0 0 0\n-5 0\n"));
        ADD_FAILURE() << "expected an IoError";
    } catch (const dpd::IoError& e) {
        EXPECT_NE(std::string(e.what()).find("bad_U.xy:2"), std::string::npos) << e.what();
    }
}

}  // namespace
