// The Couette fit (analysis/CouetteFit.*) and fitSlipLength's couette mode: synthetic profiles made
// from the exact Couette solution with Navier slip at both walls. Without noise the fit must give back
// shear rate, slip velocities, slip lengths and (from a stress column) the viscosity to rounding; with
// noise the quoted errors must cover the truth about 68 % of the time.
#include "analysis/CouetteFit.hpp"
#include "tools/FitSlipLengthTool.hpp"

#include "core/Error.hpp"
#include "sampling/ProfileTable.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>

namespace fs = std::filesystem;

namespace dpd {
namespace {

// Walls at y = -h and +h sliding at -U and +U, slip length beta at both. Navier at the upper wall:
// u(h) - U = -beta u'  with u = gdot y  gives  gdot = U / (h + beta) (the same at the lower wall).
struct Couette {
    double h = 5.0, U = 1.0, beta = 0.7;
    double shearRate() const { return U / (h + beta); }
    double operator()(double y) const { return shearRate() * y; }
};

Profile1D sample(const Couette& c, int nBins, double sigma, std::mt19937_64* rng = nullptr) {
    Profile1D p;
    std::normal_distribution<double> normal(0.0, 1.0);
    for (int i = 0; i < nBins; ++i) {
        const double y = -c.h + (i + 0.5) * 2.0 * c.h / nBins;
        const double err = sigma * (1.0 + 0.5 * std::sin(0.9 * i));  // unequal errors: weights matter
        p.y.push_back(y);
        p.u.push_back(c(y) + (rng ? err * normal(*rng) : 0.0));
        p.uErr.push_back(err);
    }
    return p;
}

void expectRel(double actual, double expected, double rel = 1e-10) {
    EXPECT_NEAR(actual, expected, rel * std::abs(expected)) << "expected " << expected;
}

}  // namespace

TEST(CouetteFit, RecoversShearRateSlipAndViscosityExactly) {
    const Couette c;
    // The near-wall bins bend in a real run: garbage there must not matter once excluded.
    Profile1D p = sample(c, 40, 0.01);
    p.u.front() = 7.0;
    p.u.back() = -3.0;
    const CouetteFitResult r = fitCouette(p, -c.h, c.h, -4.0, 4.0, -c.U, c.U);
    expectRel(r.shearRate, c.shearRate());
    expectRel(r.lower.slipLength, c.beta);
    expectRel(r.upper.slipLength, c.beta);
    // Slip velocity u_fit(wall) - U_wall: +U beta/(h + beta) at the lower wall, the opposite above.
    expectRel(r.lower.slipVelocity, c.U * c.beta / (c.h + c.beta));
    expectRel(r.upper.slipVelocity, -c.U * c.beta / (c.h + c.beta));
    expectRel(r.lower.shearRate, c.shearRate());
    expectRel(r.upper.shearRate, -c.shearRate());
    EXPECT_EQ(r.dof, 32 - 2);
    // A uniform stress sigma = eta gdot gives back eta and nu = eta / rho.
    const double eta = 0.85, rho = 4.0;
    std::vector<double> sigma(p.y.size(), eta * c.shearRate()), sigmaErr(p.y.size(), 1e-3);
    const StressViscosity v = viscosityFromStress(p.y, sigma, sigmaErr, r, rho);
    expectRel(v.eta, eta);
    expectRel(v.nu, eta / rho);
    EXPECT_EQ(v.points, 32);
    // The stress error over 32 independent bins of error 1e-3.
    expectRel(v.stressErr, 1e-3 / std::sqrt(32.0));
}

// Coverage: 400 noisy profiles; the fraction whose quoted 1-sigma error covers the truth is binomial
// with standard deviation sqrt(0.683 x 0.317 / 400) = 0.023 around 0.683 (Student-t with 38 dof: 0.677);
// the window [0.62, 0.74] fails a right error bar with probability below 2 % and catches one 20 % off.
TEST(CouetteFit, ErrorEstimatesAreStatisticallyRight) {
    const Couette c;
    std::mt19937_64 rng(424242);
    int shearHits = 0, betaHits = 0, slipHits = 0;
    const int repetitions = 400;
    for (int rep = 0; rep < repetitions; ++rep) {
        const CouetteFitResult r = fitCouette(sample(c, 40, 0.02, &rng), -c.h, c.h, -c.h, c.h, -c.U, c.U);
        shearHits += std::abs(r.shearRate - c.shearRate()) < r.shearRateErr;
        betaHits += std::abs(r.upper.slipLength - c.beta) < r.upper.slipLengthErr;
        slipHits += std::abs(r.lower.slipVelocity - c.U * c.beta / (c.h + c.beta)) < r.lower.slipVelocityErr;
    }
    for (int hits : {shearHits, betaHits, slipHits}) {
        EXPECT_GT(double(hits) / repetitions, 0.62);
        EXPECT_LT(double(hits) / repetitions, 0.74);
    }
}

TEST(CouetteFit, RejectsBadRanges) {
    const Couette c;
    const Profile1D p = sample(c, 40, 0.01);
    EXPECT_THROW(fitCouette(p, -c.h, c.h, 1.0, 1.1, -c.U, c.U), std::invalid_argument);  // too few points
    EXPECT_THROW(fitCouette(p, -c.h, c.h, -6.0, 4.0, -c.U, c.U), std::invalid_argument);  // beyond a wall
    EXPECT_THROW(fitCouette(p, c.h, -c.h, -4.0, 4.0, -c.U, c.U), std::invalid_argument);  // walls swapped
}

// The tool: a case whose walls slide at -1 and +1, a profile table with the exact Couette profile and a
// stress column; fit.dat carries the Poiseuille-mode keywords plus shearRate.
class CouetteToolTest : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("dpdCouetteTool-" + std::to_string(::getpid()));
        fs::remove_all(dir_);
        fs::create_directories(dir_ / "constant");
        fs::create_directories(dir_ / "system");
        fs::create_directories(dir_ / "10");
        std::ofstream(dir_ / "constant/dpdProperties")
            << "FoamFile { version 2.0; format ascii; class dictionary; object dpdProperties; }\n"
               "kT 1;\nspecies { fluid { frozen no; } wall { frozen yes; } }\n"
               "pairCoeffs { fluid-fluid { a 18.75; gamma 4.5; } fluid-wall { a 18.75; gamma 4.5; } }\n"
               "walls {\n"
               "  lower { type plane; point (0 0 -5); normal (0 0 1); velocity (-1 0 0); reflection bounceForward; }\n"
               "  upper { type plane; point (0 0 5); normal (0 0 -1); velocity (1 0 0); reflection bounceForward; }\n"
               "}\n";
    }
    void TearDown() override { fs::remove_all(dir_); }
    void writeDict(const std::string& body) const {
        std::ofstream(dir_ / "system/fitSlipLengthDict")
            << "FoamFile { version 2.0; format ascii; class dictionary; object fitSlipLengthDict; }\n" << body;
    }
    std::vector<FitSlipLengthResult> run() const {
        FitSlipLengthOptions o;
        o.caseDir = dir_.string();
        o.latestTime = true;
        std::ostringstream out;
        return runFitSlipLength(o, out);
    }
    fs::path dir_;
};

TEST_F(CouetteToolTest, FitDatHasSlipShearRateAndViscosity) {
    const Couette c;
    const Profile1D p = sample(c, 40, 0.01);
    BinProfile b;
    for (std::size_t i = 0; i < p.y.size(); ++i) {
        b.centre.push_back(p.y[i]);
        b.density.push_back(4.0); b.densityErr.push_back(0.01);
        b.ux.push_back(p.u[i]); b.uxErr.push_back(p.uErr[i]);
        b.uy.push_back(0.0); b.uyErr.push_back(0.01);
        b.uz.push_back(0.0); b.uzErr.push_back(0.01);
        b.kT.push_back(1.0); b.kTErr.push_back(0.01);
        b.count.push_back(1e4);
    }
    const double eta = 0.9;
    b.stress.assign(b.centre.size(), StressPoint{});
    for (auto& s : b.stress) { s.shear = eta * c.shearRate(); s.shearErr = 1e-3; }
    b.hasStress = true;
    b.stressName = "sigmaxz";
    writeProfileTable((dir_ / "postProcessing/profileBins/10/couette.dat").string(), "z", b);
    writeDict("mode couette; profile couette; fitRange (-4 4);\n");
    const auto results = run();
    ASSERT_EQ(results.size(), 1u);
    const Dictionary fit = Dictionary::readFile((dir_ / "postProcessing/fitSlipLength/10/fit.dat").string());
    EXPECT_EQ(fit.get<std::string>("mode"), "couette");
    EXPECT_EQ(fit.get<std::string>("component"), "x");  // the axis the walls slide along
    expectRel(fit.get<double>("shearRate"), c.shearRate(), 1e-9);
    const auto slip = fit.get<std::vector<double>>("slipLength");
    ASSERT_EQ(slip.size(), 2u);
    expectRel(slip[0], c.beta, 1e-9);
    expectRel(slip[1], c.beta, 1e-9);
    expectRel(fit.get<double>("eta"), eta, 1e-9);
    expectRel(fit.get<double>("nu"), eta / 4.0, 1e-9);
    for (const char* key : {"slipLengthError", "slipVelocity", "slipVelocityError", "wallPosition", "wallVelocity",
                            "shearRateError", "chi2PerDof"})
        EXPECT_TRUE(fit.found(key)) << key;
}

TEST_F(CouetteToolTest, BadSettingsNameTheKeyword) {
    writeDict("mode couette; profile couette; fitRange (4 -4);\n");
    try {
        run();
        FAIL() << "expected an InputError";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("fitRange"), std::string::npos) << e.what();
    }
    writeDict("mode poiseuille; profile couette; fitRange (-4 4);\n");
    EXPECT_THROW(run(), InputError);
}

}  // namespace dpd
