// chainScaling on cases made here: the chain length from insertChainsDict and the means from the
// header of the latest chainStatistics table give nu = exponent / 2; missing or broken inputs are named.
#include "tools/ChainScalingTool.hpp"

#include "core/Error.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

namespace fs = std::filesystem;

namespace dpd {
namespace {

class ChainScalingToolTest : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("dpdChainScaling-" + std::to_string(::getpid()));
        fs::remove_all(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    // A case of chains of `length` beads whose table at time `time` says <R_g^2> = rg2 +- err.
    std::string makeCase(int length, double rg2, double err, const std::string& time = "100") const {
        const fs::path c = dir_ / ("N" + std::to_string(length));
        fs::create_directories(c / "system");
        std::ofstream(c / "system/insertChainsDict") << "FoamFile { version 2.0; format ascii; class dictionary; object x; }\n"
                                                     << "chains 3;\nlength " << length << ";\n";
        const fs::path table = c / "postProcessing/chains" / time;
        fs::create_directories(table);
        std::ofstream(table / "chainStatistics.dat") << "# chainStatistics: means\n# mean Rg2     " << rg2 << " +- " << err
                                                     << "\n# mean Ree2    " << 6.2 * rg2 << " +- " << 6.2 * err << "\n";
        return c.string();
    }

    fs::path dir_;
};

TEST_F(ChainScalingToolTest, TheFloryExponentIsHalfThePowerLawsExponent) {
    std::vector<std::string> cases;
    for (int n : {40, 10, 20}) cases.push_back(makeCase(n, 0.2 * std::pow(n, 2 * 0.588), 0.01 * 0.2 * std::pow(n, 1.176)));
    makeCase(20, 99.0, 1.0, "50");  // an earlier time of the same case: not read
    const ChainScalingResult r = chainScaling(cases, "chains");
    ASSERT_EQ(r.cases.size(), 3u);
    EXPECT_EQ(r.cases.front().length, 10);  // sorted by length
    EXPECT_NEAR(r.nu(), 0.588, 1e-6);
    EXPECT_NEAR(r.cases[1].ree2, 6.2 * r.cases[1].rg2, 1e-6 * r.cases[1].ree2);
    const Dictionary d = chainScalingDictionary(r);
    EXPECT_NEAR(d.get<double>("nu"), 0.588, 1e-6);
    EXPECT_EQ(d.get<std::vector<double>>("length"), (std::vector<double>{10, 20, 40}));
}

TEST_F(ChainScalingToolTest, MissingAndBrokenInputsAreNamed) {
    const std::string a = makeCase(10, 1.0, 0.01), b = makeCase(20, 2.2, 0.02);
    EXPECT_THROW(chainScaling({a, b}, "chains"), std::invalid_argument);  // two lengths
    try {
        chainScaling({a, b, (dir_ / "N30").string()}, "chains");
        FAIL() << "a case without its dictionary was read";
    } catch (const std::exception& e) {
        EXPECT_NE(std::string(e.what()).find("insertChainsDict"), std::string::npos) << e.what();
    }
    const std::string c = makeCase(30, 3.5, 0.03);
    std::ofstream(fs::path(c) / "postProcessing/chains/100/chainStatistics.dat") << "# mean Ree2 1 +- 0.1\n";
    try {
        chainScaling({a, b, c}, "chains");
        FAIL() << "a table without the mean of R_g^2 was read";
    } catch (const IoError& e) {
        EXPECT_NE(std::string(e.what()).find("no '# mean Rg2' line"), std::string::npos) << e.what();
    }
    EXPECT_THROW(chainScaling({a, b, c}, "otherChains"), IoError);
    makeCase(30, 3.5, 0.0);
    EXPECT_THROW(chainScaling({a, b, c}, "chains"), std::invalid_argument);  // a zero error
}

}  // namespace
}  // namespace dpd
