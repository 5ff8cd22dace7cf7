// fitSlipLength on tiny cases whose profile tables hold exact analytic profiles: the viscosity and the
// slip lengths written to fit.dat must be the ones the profiles were made with; bad input gives an
// error naming the file and keyword, and writes nothing.
#include "tools/FitSlipLengthTool.hpp"

#include "../support/InputErrorOf.hpp"
#include "core/Error.hpp"
#include "io/Dictionary.hpp"
#include "sampling/BinAccumulatorFile.hpp"
#include "sampling/BinProfile.hpp"
#include "sampling/ProfileTable.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>

namespace fs = std::filesystem;

namespace dpd {
namespace {

constexpr double kNu = 0.3, kG = 0.02, kBeta = 0.5, kWall = 5.0;
constexpr int kBins = 40;

const char* kHeader = "FoamFile { version 2.0; format ascii; class dictionary; object x; }\n";

std::string channelProperties(const std::string& bodyForce, bool walls = true) {
    std::string s = std::string(kHeader) +
                    "kT 1;\n"
                    "species { fluid { frozen no; } wall { frozen yes; } }\n"
                    "pairCoeffs { fluid-fluid { a 18.75; gamma 4.5; } fluid-wall { a 18.75; gamma 4.5; } }\n"
                    "bodyForce { " + bodyForce + " }\n";
    if (walls)
        s += "walls\n{\n"
             "    upper { type plane; point (0 0 5); normal (0 0 -1); }\n"
             "    lower { type plane; point (0 0 -5); normal (0 0 1); }\n"
             "}\n";
    return s;
}

// A table along z over [-5, 5) with kBins bins, velocity ux = u(z), uniform density 4.
BinProfile makeProfile(const std::function<double(double)>& u, double uErr) {
    BinProfile p;
    const double w = 2.0 * kWall / kBins;
    for (int b = 0; b < kBins; ++b) {
        const double z = -kWall + (b + 0.5) * w;
        p.centre.push_back(z);
        p.density.push_back(4.0);
        p.densityErr.push_back(0.01);
        p.ux.push_back(u(z));
        p.uxErr.push_back(uErr);
        p.uy.push_back(0.0);
        p.uyErr.push_back(uErr);
        p.uz.push_back(0.0);
        p.uzErr.push_back(uErr);
        p.kT.push_back(1.0);
        p.kTErr.push_back(0.001);
        p.count.push_back(1e5);
    }
    return p;
}

// Plane Poiseuille between z = -5 and 5 with slip length kBeta at both (resting) walls:
// u = g/(2 nu) (h^2 - z^2) + beta g h / nu, so that u(wall) = beta du/dn.
double poiseuille(double z) {
    return kG / (2.0 * kNu) * (kWall * kWall - z * z) + kBeta * kG * kWall / kNu;
}

// Periodic reverse Poiseuille on [-5, 5): +g on the lower half, -g on the upper half.
double reversePoiseuille(double z) {
    const double L = 2.0 * kWall, s = z + kWall;
    if (s < 0.5 * L) return kG / (2.0 * kNu) * s * (0.5 * L - s) + 0.1;
    return -kG / (2.0 * kNu) * (s - 0.5 * L) * (L - s) + 0.1;
}

class FitSlipLengthToolTest : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = fs::temp_directory_path() /
               ("dpdFitSlipLength-" + std::string(info->name()) + "-" + std::to_string(::getpid()));
        fs::remove_all(dir_);
        fs::create_directories(dir_ / "constant");
        fs::create_directories(dir_ / "system");
        fs::create_directories(dir_ / "10");
    }
    void TearDown() override { fs::remove_all(dir_); }

    void write(const std::string& rel, const std::string& text) const { std::ofstream(dir_ / rel) << text; }
    void writeDict(const std::string& body) const { write("system/fitSlipLengthDict", kHeader + body); }
    void writeTable(const BinProfile& p, const std::string& name = "channelProfile") const {
        writeProfileTable((dir_ / "postProcessing/profileBins/10" / (name + ".dat")).string(), "z", p);
    }
    std::vector<FitSlipLengthResult> run(std::string* printed = nullptr) const {
        FitSlipLengthOptions o;
        o.caseDir = dir_.string();
        o.latestTime = true;
        std::ostringstream out;
        auto r = runFitSlipLength(o, out);
        if (printed) *printed = out.str();
        return r;
    }
    Dictionary fitDat() const { return Dictionary::readFile((dir_ / "postProcessing/fitSlipLength/10/fit.dat").string()); }
    bool wroteNothing() const { return !fs::exists(dir_ / "postProcessing/fitSlipLength"); }
    // The InputError of a run (message), "" when it succeeds.
    std::string inputError() const {
        return test::inputErrorOf([&] { run(); });
    }

    fs::path dir_;
};

void expectRel(double actual, double expected, double rel = 1e-8) {
    EXPECT_NEAR(actual, expected, rel * std::abs(expected)) << "expected " << expected;
}

TEST_F(FitSlipLengthToolTest, PoiseuilleRecoversViscosityAndSlipLength) {
    write("constant/dpdProperties", channelProperties("type uniform; value (0.02 0 0);"));
    writeDict("mode poiseuille;\nprofile channelProfile;\ncomponent x;\nexclude 0;\n");
    writeTable(makeProfile(poiseuille, 0.01));
    std::string printed;
    run(&printed);
    const Dictionary d = fitDat();
    EXPECT_EQ(d.get<std::string>("mode"), "poiseuille");
    expectRel(d.get<double>("nu"), kNu);
    const auto slip = d.get<std::vector<double>>("slipLength");
    ASSERT_EQ(slip.size(), 2u);
    expectRel(slip[0], kBeta);
    expectRel(slip[1], kBeta);
    const auto slipVelocity = d.get<std::vector<double>>("slipVelocity");
    expectRel(slipVelocity[0], kBeta * kG * kWall / kNu);
    expectRel(slipVelocity[1], kBeta * kG * kWall / kNu);
    const auto shear = d.get<std::vector<double>>("shearRate");
    expectRel(shear[0], kG * kWall / kNu);
    expectRel(shear[1], kG * kWall / kNu);
    for (const char* key : {"nuError", "slipLengthError", "slipVelocityError", "chi2PerDof"}) EXPECT_TRUE(d.found(key)) << key;
    // Exact data: the errors, scaled by the (vanishing) scatter, are essentially zero.
    EXPECT_LT(d.get<double>("nuError"), 1e-8);
    expectRel(d.get<double>("nuKineticTheory"), kineticTheoryViscosity(1.0, 4.5, 4.0), 1e-12);
    EXPECT_NE(printed.find("estimate"), std::string::npos) << printed;
    EXPECT_NE(printed.find("slip length"), std::string::npos) << printed;
}

TEST_F(FitSlipLengthToolTest, PoiseuilleDefaultsToTheBodyForceDirectionAndUnitWeights) {
    write("constant/dpdProperties", channelProperties("type uniform; value (0.02 0 0);"));
    writeDict("mode poiseuille;\nprofile channelProfile;\n");
    writeTable(makeProfile(poiseuille, 0.0));  // no error bars (a snapshot profile)
    const auto r = run();
    ASSERT_EQ(r.size(), 1u);
    EXPECT_EQ(r[0].component, 0);
    expectRel(r[0].poiseuille.nu, kNu);
    expectRel(r[0].poiseuille.lower.slipLength, kBeta);
}

TEST_F(FitSlipLengthToolTest, EmptyBinsAreLeftOut) {
    write("constant/dpdProperties", channelProperties("type uniform; value (0.02 0 0);"));
    writeDict("mode poiseuille;\nprofile channelProfile;\n");
    BinProfile p = makeProfile(poiseuille, 0.01);
    p.count[0] = 0.0;  // no particles: no velocity, no error
    p.ux[0] = 0.0;
    p.uxErr[0] = 0.0;
    writeTable(p);
    const auto r = run();
    EXPECT_EQ(r[0].binsWithoutVelocity, 1);
    EXPECT_EQ(r[0].pointsUsed, kBins - 1);
    expectRel(r[0].poiseuille.nu, kNu);
}

TEST_F(FitSlipLengthToolTest, ReversePoiseuilleRecoversViscosity) {
    write("constant/dpdProperties",
          channelProperties("type reversePoiseuille; value (0.02 0 0); gradientAxis z;", false));
    writeDict("mode reversePoiseuille;\nprofile channelProfile;\n");
    writeTable(makeProfile(reversePoiseuille, 0.01));
    run();
    const Dictionary d = fitDat();
    EXPECT_EQ(d.get<std::string>("mode"), "reversePoiseuille");
    expectRel(d.get<double>("nu"), kNu);
    expectRel(d.get<double>("nuFirstHalf"), kNu);
    expectRel(d.get<double>("nuSecondHalf"), kNu);
    for (const char* key : {"nuError", "chi2PerDof", "nuKineticTheory"}) EXPECT_TRUE(d.found(key)) << key;
    expectRel(d.get<double>("boxLength"), 2.0 * kWall, 1e-12);
}

TEST_F(FitSlipLengthToolTest, DefaultSelectionSkipsTimesWithoutTheTable) {
    write("constant/dpdProperties", channelProperties("type uniform; value (0.02 0 0);"));
    writeDict("mode poiseuille;\nprofile channelProfile;\n");
    writeTable(makeProfile(poiseuille, 0.01));
    fs::create_directories(dir_ / "5");  // written before profileBins was run on it
    FitSlipLengthOptions o;
    o.caseDir = dir_.string();
    std::ostringstream out;
    const auto r = runFitSlipLength(o, out);
    ASSERT_EQ(r.size(), 1u);
    EXPECT_EQ(r[0].time, "10");
    EXPECT_NE(out.str().find("Time = 5: no profile table"), std::string::npos) << out.str();
    EXPECT_FALSE(fs::exists(dir_ / "postProcessing/fitSlipLength/5"));
    o.time = "5";
    EXPECT_THROW(runFitSlipLength(o, out), InputError);
}

TEST_F(FitSlipLengthToolTest, MissingKeywordNamesTheDictionary) {
    write("constant/dpdProperties", channelProperties("type uniform; value (0.02 0 0);"));
    writeDict("mode poiseuille;\n");
    writeTable(makeProfile(poiseuille, 0.01));
    const std::string msg = inputError();
    EXPECT_NE(msg.find("fitSlipLengthDict"), std::string::npos) << msg;
    EXPECT_NE(msg.find("'profile'"), std::string::npos) << msg;
    EXPECT_TRUE(wroteNothing());
}

TEST_F(FitSlipLengthToolTest, MissingDictionaryIsAnError) {
    write("constant/dpdProperties", channelProperties("type uniform; value (0.02 0 0);"));
    EXPECT_NE(inputError().find("fitSlipLengthDict"), std::string::npos) << inputError();
}

TEST_F(FitSlipLengthToolTest, UnknownModeNamesFileLineAndKeyword) {
    write("constant/dpdProperties", channelProperties("type uniform; value (0.02 0 0);"));
    writeDict("profile channelProfile;\nmode stokes;\n");
    writeTable(makeProfile(poiseuille, 0.01));
    const std::string msg = inputError();
    EXPECT_NE(msg.find("fitSlipLengthDict:3"), std::string::npos) << msg;
    EXPECT_NE(msg.find("'mode'"), std::string::npos) << msg;
    EXPECT_TRUE(wroteNothing());
}

TEST_F(FitSlipLengthToolTest, MissingProfileTableIsNamed) {
    write("constant/dpdProperties", channelProperties("type uniform; value (0.02 0 0);"));
    writeDict("mode poiseuille;\nprofile otherProfile;\n");
    writeTable(makeProfile(poiseuille, 0.01));
    const std::string msg = inputError();
    EXPECT_NE(msg.find("otherProfile.dat"), std::string::npos) << msg;
    EXPECT_TRUE(wroteNothing());
}

TEST_F(FitSlipLengthToolTest, TooFewPointsIsAnError) {
    write("constant/dpdProperties", channelProperties("type uniform; value (0.02 0 0);"));
    writeDict("mode poiseuille;\nprofile channelProfile;\nexclude 4.7;\n");
    writeTable(makeProfile(poiseuille, 0.01));
    const std::string msg = inputError();
    EXPECT_NE(msg.find("'exclude'"), std::string::npos) << msg;
    EXPECT_NE(msg.find("at least 4"), std::string::npos) << msg;
    EXPECT_TRUE(wroteNothing());
}

TEST_F(FitSlipLengthToolTest, PoiseuilleNeedsTwoWallsAlongTheAxis) {
    write("constant/dpdProperties", channelProperties("type uniform; value (0.02 0 0);", false));
    writeDict("mode poiseuille;\nprofile channelProfile;\n");
    writeTable(makeProfile(poiseuille, 0.01));
    const std::string msg = inputError();
    EXPECT_NE(msg.find("dpdProperties"), std::string::npos) << msg;
    EXPECT_NE(msg.find("exactly two"), std::string::npos) << msg;
    EXPECT_TRUE(wroteNothing());
}

TEST_F(FitSlipLengthToolTest, ForceWithoutTheComponentIsAnError) {
    write("constant/dpdProperties", channelProperties("type uniform; value (0.02 0 0);"));
    writeDict("mode poiseuille;\nprofile channelProfile;\ncomponent y;\n");
    writeTable(makeProfile(poiseuille, 0.01));
    const std::string msg = inputError();
    EXPECT_NE(msg.find("'component'"), std::string::npos) << msg;
    EXPECT_TRUE(wroteNothing());
}

TEST_F(FitSlipLengthToolTest, ReverseModeNeedsAReversePoiseuilleForce) {
    write("constant/dpdProperties", channelProperties("type uniform; value (0.02 0 0);"));
    writeDict("mode reversePoiseuille;\nprofile channelProfile;\n");
    writeTable(makeProfile(reversePoiseuille, 0.01));
    const std::string msg = inputError();
    EXPECT_NE(msg.find("'mode'"), std::string::npos) << msg;
    EXPECT_NE(msg.find("reversePoiseuille"), std::string::npos) << msg;
    EXPECT_TRUE(wroteNothing());
}

// Walls of a geometry block (randomEquilWall) are not planar walls of dpdProperties: wallPositions
// places them. The same exact profile seen from walls at +-4.5 has the slip length u(4.5) / |u'(4.5)|,
// so the fit must use the given positions, not the profile's ends.
TEST_F(FitSlipLengthToolTest, WallPositionsPlaceTheWallsOfAGeometry) {
    write("constant/dpdProperties", channelProperties("type uniform; value (0.02 0 0);", false));
    writeDict("mode poiseuille;\nprofile channelProfile;\nwallPositions (-4.5 4.5);\n");
    writeTable(makeProfile(poiseuille, 0.01));
    run();
    const Dictionary d = fitDat();
    expectRel(d.get<double>("nu"), kNu);
    const double wall = 4.5, shear = kG * wall / kNu;
    const auto slip = d.get<std::vector<double>>("slipLength");
    expectRel(slip[0], poiseuille(-wall) / shear);
    expectRel(slip[1], poiseuille(wall) / shear);
    const auto position = d.get<std::vector<double>>("wallPosition");
    EXPECT_DOUBLE_EQ(position[0], -wall);
    EXPECT_DOUBLE_EQ(position[1], wall);
}

// wallPositions beside planar walls along the same axis is ambiguous; the pair must increase.
TEST_F(FitSlipLengthToolTest, WallPositionsAreRefusedWhereTheyDoNotFit) {
    const auto refusal = [&](bool planarWalls, const std::string& positions) {
        write("constant/dpdProperties", channelProperties("type uniform; value (0.02 0 0);", planarWalls));
        writeDict("mode poiseuille;\nprofile channelProfile;\nwallPositions " + positions + ";\n");
        writeTable(makeProfile(poiseuille, 0.01));
        const std::string msg = inputError();
        EXPECT_TRUE(wroteNothing());
        EXPECT_NE(msg.find("fitSlipLengthDict:4"), std::string::npos) << msg;
        EXPECT_NE(msg.find("'wallPositions'"), std::string::npos) << msg;
        return msg;
    };
    EXPECT_NE(refusal(true, "(-4.5 4.5)").find("planar walls"), std::string::npos);
    EXPECT_NE(refusal(false, "(4.5 -4.5)").find("upper > lower"), std::string::npos);
}

}  // namespace
}  // namespace dpd

namespace dpd {
namespace {

// A sampling file of 16 blocks in which the whole profile moves up and down from block to block (an
// irregular shift of about 0.05) with little noise per bin: the table made from it, and the file itself at time 10.
BinAccumulator shiftingBlocks(int nBins, double noise = 1e-3) {
    BinLayout layout;
    layout.axis = 2;
    layout.nBins = nBins;
    layout.lo = -kWall;
    layout.hi = kWall;
    std::vector<std::vector<BinSums>> blocks;
    for (int k = 0; k < 16; ++k) {
        const double shift = 0.05 * std::sin(1.3 + 2.9 * k * k);
        std::vector<BinSums> bins(nBins);
        for (int b = 0; b < nBins; ++b) {
            const double n = 1000.0, u = poiseuille(layout.centre(b)) + shift + noise * std::sin(3.0 * b + k);
            bins[b].s[0] = n;
            bins[b].s[1] = n * u;
            bins[b].s[4] = n * (u * u + 1.0);
            bins[b].s[5] = bins[b].s[6] = n;
        }
        blocks.push_back(bins);
    }
    return BinAccumulator::fromBlocks(layout, {1, 0}, 100, blocks, std::vector<long>(16, 100));
}

TEST_F(FitSlipLengthToolTest, ErrorsComeFromTheBlocksOfTheSamplingFile) {
    write("constant/dpdProperties", channelProperties("type uniform; value (0.02 0 0);"));
    writeDict("mode poiseuille;\nprofile channelProfile;\n");
    const BinAccumulator acc = shiftingBlocks(kBins);
    writeTable(computeProfile(acc, 1.0, 3));
    const auto independent = run();
    EXPECT_EQ(fitDat().get<std::string>("errors"), "independentBins");
    fs::create_directories(dir_ / "10/sampling");
    writeBins((dir_ / "10/sampling/channelProfile.h5").string(), acc, 3, 1.0, 10.0);
    std::string printed;
    const auto blocks = run(&printed);
    const Dictionary d = fitDat();
    EXPECT_EQ(d.get<std::string>("errors"), "blocks");
    EXPECT_EQ(d.get<int>("errorBlocks"), 16);
    EXPECT_NE(printed.find("16 blocks"), std::string::npos) << printed;
    // The same fitted values; the slip velocity's error is the spread of the shift (~0.035 / sqrt(16)),
    // not the bins' noise averaged as if independent.
    EXPECT_EQ(blocks[0].poiseuille.lower.slipVelocity, independent[0].poiseuille.lower.slipVelocity);
    EXPECT_GT(blocks[0].poiseuille.lower.slipVelocityErr, 0.005);
    EXPECT_GT(blocks[0].poiseuille.lower.slipVelocityErr, 5.0 * independent[0].poiseuille.lower.slipVelocityErr);
}

TEST_F(FitSlipLengthToolTest, ASamplingFileWithOtherBinsIsNotUsed) {
    write("constant/dpdProperties", channelProperties("type uniform; value (0.02 0 0);"));
    writeDict("mode poiseuille;\nprofile channelProfile;\n");
    writeTable(computeProfile(shiftingBlocks(kBins), 1.0, 3));
    fs::create_directories(dir_ / "10/sampling");
    writeBins((dir_ / "10/sampling/channelProfile.h5").string(), shiftingBlocks(kBins / 2), 3, 1.0, 10.0);
    std::string printed;
    run(&printed);
    EXPECT_EQ(fitDat().get<std::string>("errors"), "independentBins");
    EXPECT_NE(printed.find("are not the table's"), std::string::npos) << printed;
}

// A case whose sampling blocks are shiftingBlocks' without noise, each block 5 time units (100 samples
// every 5 steps of 0.01), fitted with the superBlocks entry given.
class SuperBlockTest : public FitSlipLengthToolTest {
protected:
    void setUpCase(const std::string& superBlocks, const std::string& mode = "poiseuille",
                   const std::string& bodyForce = "type uniform; value (0.02 0 0);") {
        write("constant/dpdProperties", channelProperties(bodyForce));
        write("system/controlDict", std::string(kHeader) +
                                        "deltaT 0.01;\nfunctions { channelProfile { type binnedProfile; sampleInterval 5; } }\n");
        writeDict("mode " + mode + ";\nprofile channelProfile;\n" + superBlocks);
        const BinAccumulator acc = shiftingBlocks(kBins, 0.0);
        writeTable(computeProfile(acc, 1.0, 3));
        fs::create_directories(dir_ / "10/sampling");
        writeBins((dir_ / "10/sampling/channelProfile.h5").string(), acc, 3, 1.0, 10.0);
    }
};

// The profile moves as a whole from block to block, so each fit's slip velocity is the profile's plus the
// mean shift of the blocks it holds, and nu does not move: the jackknife's slip-velocity error is then
// the standard error of the super-blocks' mean shifts, exactly, and nu's is zero.
TEST_F(SuperBlockTest, TheJackknifeOfAWholeProfileShiftIsTheStandardErrorOfTheSuperBlocksShifts) {
    setUpCase("superBlocks { length 15; minimum 5; }\n");
    std::string printed;
    const auto r = run(&printed);
    const Dictionary d = fitDat();
    EXPECT_EQ(d.get<std::string>("errors"), "jackknife");
    EXPECT_EQ(d.get<int>("superBlocks"), 5);
    EXPECT_EQ(d.get<int>("blocksPerSuperBlock"), 3);
    EXPECT_DOUBLE_EQ(d.get<double>("superBlockLength"), 15.0);
    // Super-block j holds blocks 1 + 3j .. 3 + 3j (block 0, the earliest, is left out).
    std::vector<double> means;
    for (int j = 0; j < 5; ++j) {
        double sum = 0.0;
        for (int k = 1 + 3 * j; k < 4 + 3 * j; ++k) sum += 0.05 * std::sin(1.3 + 2.9 * k * k);
        means.push_back(sum / 3.0);
    }
    double mean = 0.0, squares = 0.0;
    for (double x : means) mean += x / 5.0;
    for (double x : means) squares += (x - mean) * (x - mean);
    const double standardError = std::sqrt(squares / 4.0 / 5.0);
    ASSERT_GT(standardError, 0.005);
    expectRel(r[0].poiseuille.lower.slipVelocityErr, standardError, 1e-9);
    expectRel(r[0].poiseuille.upper.slipVelocityErr, standardError, 1e-9);
    expectRel(d.get<std::vector<double>>("slipVelocityError")[0], standardError, 1e-6);
    EXPECT_LT(r[0].poiseuille.nuErr, 1e-9 * kNu);
    // The slip length moves with the slip velocity at a fixed shear rate.
    expectRel(r[0].poiseuille.lower.slipLengthErr, standardError / r[0].poiseuille.lower.shearRate, 1e-6);
    EXPECT_NE(printed.find("jackknife over 5 super-blocks of 15"), std::string::npos) << printed;
}

TEST_F(SuperBlockTest, DecayTimesSetTheLengthFromTheChannelsSlowestMode) {
    // tau1 = d^2 / (pi^2 nu) = 100 / (pi^2 0.3) = 33.8; 0.3 tau1 = 10.1: two blocks of 5.
    setUpCase("superBlocks { decayTimes 0.3; }\n");
    run();
    const Dictionary d = fitDat();
    EXPECT_EQ(d.get<std::string>("errors"), "jackknife");
    EXPECT_EQ(d.get<int>("blocksPerSuperBlock"), 2);
    EXPECT_EQ(d.get<int>("superBlocks"), 8);
}

TEST_F(SuperBlockTest, TooFewSuperBlocksKeepTheBlocksErrorsAndSayWhy) {
    setUpCase("superBlocks { length 15; minimum 6; }\n");
    std::string printed;
    run(&printed);
    const Dictionary d = fitDat();
    EXPECT_EQ(d.get<std::string>("errors"), "blocks");
    EXPECT_FALSE(d.found("superBlocks"));
    EXPECT_NE(d.get<std::string>("superBlocksNote").find("5 super-blocks of 15, fewer than 6"), std::string::npos)
        << d.get<std::string>("superBlocksNote");
    EXPECT_NE(printed.find("no jackknife"), std::string::npos) << printed;
}

TEST_F(SuperBlockTest, BadEntriesNameTheKeyword) {
    setUpCase("superBlocks { length 15; decayTimes 2; }\n");
    EXPECT_NE(inputError().find("give one of length"), std::string::npos) << inputError();
    setUpCase("superBlocks { length 15; minimum 1; }\n");
    EXPECT_NE(inputError().find("minimum"), std::string::npos) << inputError();
    setUpCase("superBlocks { lenght 15; }\n");
    EXPECT_NE(inputError().find("lenght"), std::string::npos) << inputError();
    write("system/controlDict", std::string(kHeader) + "deltaT 0.01;\n");
    setUpCase("superBlocks { length 15; }\n");
    write("system/controlDict", std::string(kHeader) + "deltaT 0.01;\n");
    const std::string noFunction = inputError();
    EXPECT_NE(noFunction.find("superBlocks"), std::string::npos) << noFunction;
    EXPECT_NE(noFunction.find("no function object 'channelProfile'"), std::string::npos) << noFunction;
    EXPECT_TRUE(wroteNothing());
}

TEST_F(SuperBlockTest, AModeWithoutAJackknifeRefusesSuperBlocks) {
    setUpCase("superBlocks { length 15; }\ncomponent x;\n", "couette", "type uniform; value (0 0 0);");
    const std::string refusal = inputError();
    EXPECT_NE(refusal.find("superBlocks"), std::string::npos) << refusal;
    EXPECT_NE(refusal.find("mode couette has no jackknife"), std::string::npos) << refusal;
}

}  // namespace
}  // namespace dpd
