// slipTensor on tiny cases whose profile tables hold exact Poiseuille profiles with a different slip
// length along and across the stripes: b_par, b_perp, theta, the fluxes and the transverse flux ratio
// written to fit.dat must be the ones the profiles were made with; an undriven component is not
// fitted; bad input names the file and keyword.
#include "tools/SlipTensorTool.hpp"

#include "../support/InputErrorOf.hpp"
#include "core/Error.hpp"
#include "io/Dictionary.hpp"
#include "sampling/BinProfile.hpp"
#include "sampling/ProfileTable.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace fs = std::filesystem;

namespace dpd {
namespace {

constexpr double kNu = 0.28, kH = 5.0, kBins = 40, kBPar = 0.9, kBPerp = 0.45, kG = 0.004;
const char* kHeader = "FoamFile { version 2.0; format ascii; class dictionary; object x; }\n";

std::string properties(double gx, double gy, bool stripes = true) {
    const std::string tunable = std::string("tunableSlip { gammaL 4; zc 1; epsilon 1; sigma 0.5; ") +
                                (stripes ? "stripes { axis x; period 10; gasFraction 0.5; gammaGas 0.1; offset 0; } " : "") +
                                "}";
    std::ostringstream s;
    s.precision(17);
    s << kHeader << "kT 1;\nspecies { fluid { frozen no; } }\npairCoeffs { fluid-fluid { a 25; gamma 4.5; } }\n"
      << "bodyForce { type uniform; value (" << gx << " " << gy << " 0); }\n"
      << "walls\n{\n"
      << "    lower { type plane; point (0 0 -5); normal (0 0 1); reflection specular; " << tunable << " }\n"
      << "    upper { type plane; point (0 0 5); normal (0 0 -1); reflection specular; " << tunable << " }\n}\n";
    return s.str();
}

// Poiseuille between z = -+kH with slip length b at both walls, driven by g.
double poiseuille(double z, double g, double b) { return g / (2.0 * kNu) * (kH * kH - z * z) + b * g * kH / kNu; }

// The midpoint sum of that profile over the bins: the integral plus (dz^2 / 24) (2 kH) g / nu, exact for a parabola.
double binnedFlux(double g, double b) {
    const double dz = 2.0 * kH / kBins;
    const double integral = g / (2.0 * kNu) * (4.0 * kH * kH * kH / 3.0) + 2.0 * kH * b * g * kH / kNu;
    return integral + dz * dz / 24.0 * 2.0 * kH * g / kNu;
}

BinProfile profile(double gx, double gy) {
    BinProfile p;
    const double w = 2.0 * kH / kBins;
    for (int k = 0; k < kBins; ++k) {
        const double z = -kH + (k + 0.5) * w;
        p.centre.push_back(z);
        p.density.push_back(3.0);
        p.densityErr.push_back(0.01);
        p.ux.push_back(poiseuille(z, gx, kBPerp));  // across the stripes (their axis x)
        p.uxErr.push_back(0.01);
        p.uy.push_back(poiseuille(z, gy, kBPar));   // along them
        p.uyErr.push_back(0.01);
        p.uz.push_back(0.0);
        p.uzErr.push_back(0.01);
        p.kT.push_back(1.0);
        p.kTErr.push_back(0.001);
        p.count.push_back(1e5);
    }
    return p;
}

class SlipTensorToolTest : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = fs::temp_directory_path() / ("dpdSlipTensor-" + std::string(info->name()) + "-" + std::to_string(::getpid()));
        fs::remove_all(dir_);
        fs::create_directories(dir_ / "constant");
        fs::create_directories(dir_ / "system");
        fs::create_directories(dir_ / "10");
        write("system/fitSlipLengthDict", std::string(kHeader) + "mode poiseuille;\nprofile channelProfile;\nexclude 0;\n");
    }
    void TearDown() override { fs::remove_all(dir_); }

    void write(const std::string& rel, const std::string& text) const { std::ofstream(dir_ / rel) << text; }
    void setUp(double thetaDegrees, bool stripes = true) const {
        const double gx = kG * std::sin(thetaDegrees * M_PI / 180.0), gy = kG * std::cos(thetaDegrees * M_PI / 180.0);
        write("constant/dpdProperties", properties(gx, gy, stripes));
        writeProfileTable((dir_ / "postProcessing/profileBins/10/channelProfile.dat").string(), "z", profile(gx, gy));
    }
    Dictionary run() const {
        FitSlipLengthOptions o;
        o.caseDir = dir_.string();
        o.latestTime = true;
        std::ostringstream out;
        runSlipTensor(o, out);
        return Dictionary::readFile((dir_ / "postProcessing/slipTensor/10/fit.dat").string());
    }
    std::string inputError() const {
        return test::inputErrorOf([&] { run(); });
    }
    fs::path dir_;
};

TEST_F(SlipTensorToolTest, RecoversBothSlipLengthsAndTheTransverseFlux) {
    const double theta = 30.0;
    setUp(theta);
    const Dictionary d = run();
    EXPECT_EQ(d.get<std::string>("axisParallel"), "y");
    EXPECT_EQ(d.get<std::string>("axisPerpendicular"), "x");
    EXPECT_NEAR(d.get<double>("theta"), theta, 1e-9);
    for (const double b : d.get<std::vector<double>>("slipParallel")) EXPECT_NEAR(b, kBPar, 1e-8);
    for (const double b : d.get<std::vector<double>>("slipPerpendicular")) EXPECT_NEAR(b, kBPerp, 1e-8);
    const double c = std::cos(theta * M_PI / 180.0), s = std::sin(theta * M_PI / 180.0);
    EXPECT_NEAR(d.get<double>("slipEffective"), kBPar * c * c + kBPerp * s * s, 1e-8);
    EXPECT_NEAR(d.get<double>("nuParallel"), kNu, 1e-8);
    EXPECT_NEAR(d.get<double>("nuPerpendicular"), kNu, 1e-8);
    const double qPar = binnedFlux(kG * c, kBPar), qPerp = binnedFlux(kG * s, kBPerp);
    EXPECT_NEAR(d.get<double>("fluxParallel"), qPar, 1e-10 * qPar);
    EXPECT_NEAR(d.get<double>("fluxPerpendicular"), qPerp, 1e-10 * qPar);
    // More slip along the stripes turns the flow towards them: a positive ratio.
    const double expected = (qPar * s - qPerp * c) / (qPar * c + qPerp * s);
    EXPECT_GT(expected, 0.0);
    EXPECT_NEAR(d.get<double>("transverseFluxRatio"), expected, 1e-10);
    EXPECT_GT(d.get<double>("transverseFluxRatioError"), 0.0);
}

TEST_F(SlipTensorToolTest, AnUndrivenComponentIsNotFitted) {
    setUp(0.0);
    const Dictionary d = run();
    for (const double b : d.get<std::vector<double>>("slipParallel")) EXPECT_NEAR(b, kBPar, 1e-8);
    EXPECT_EQ(d.get<std::string>("slipPerpendicularMean"), "none");
    EXPECT_NEAR(d.get<double>("slipEffective"), kBPar, 1e-8);
    EXPECT_NEAR(d.get<double>("fluxPerpendicular"), 0.0, 1e-12);
    EXPECT_NEAR(d.get<double>("transverseFluxRatio"), 0.0, 1e-12);
}

TEST_F(SlipTensorToolTest, BadInputNamesFileAndKeyword) {
    setUp(45.0, false);
    std::string e = inputError();
    EXPECT_NE(e.find("dpdProperties"), std::string::npos) << e;
    EXPECT_NE(e.find("no stripes"), std::string::npos) << e;
    setUp(45.0);
    write("system/fitSlipLengthDict", std::string(kHeader) + "mode couette;\nprofile channelProfile;\n");
    e = inputError();
    EXPECT_NE(e.find("fitSlipLengthDict"), std::string::npos) << e;
    EXPECT_NE(e.find("mode"), std::string::npos) << e;
    write("system/fitSlipLengthDict", std::string(kHeader) + "mode poiseuille;\nprofile channelProfile;\ncomponent x;\n");
    e = inputError();
    EXPECT_NE(e.find("component"), std::string::npos) << e;
    EXPECT_FALSE(fs::exists(dir_ / "postProcessing/slipTensor"));
}

}  // namespace
}  // namespace dpd
