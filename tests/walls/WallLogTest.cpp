// The solver's log reports what the walls did (tools/Runner.cpp): each wall's rule and velocity and the
// frozen particles it carries in the header; per report interval the particles each wall returned and
// those found behind its plane. A bounce layer far too thin for the step lets particles through: the
// log must show it, not hide it. Mixed pair coefficients are noted in the header.
#include "io/Snapshot.hpp"
#include "setup/InitialConditions.hpp"
#include "tools/Runner.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

namespace fs = std::filesystem;
using namespace dpd;

namespace {

const char* kHeader = "FoamFile { version 2.0; format ascii; class dictionary; object x; }\n";

// A 4 x 4 x 6 box of DPD fluid between walls at z = 1 and 5 (no frozen particles), 0.2 time units.
fs::path makeCase(const std::string& reflection) {
    const fs::path dir = fs::temp_directory_path() / ("dpdWallLog-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir / "constant");
    fs::create_directories(dir / "system");
    std::ofstream(dir / "constant/dpdProperties")
        << kHeader << "kT 1;\nseed 3;\n"
        << "stability { maxKTRatio 10; }\n"  // random initial positions overlap and heat the fluid at first
        << "species { fluid { frozen no; } wall { frozen yes; } }\n"
           "pairCoeffs { fluid-fluid { a 25; gamma 4.5; } wall-wall { a 9; gamma 4.5; } }\n"
           "walls {\n"
           "  lower { type plane; point (0 0 1); normal (0 0 1); velocity (-1 0 0); " << reflection << " }\n"
           "  upper { type plane; point (0 0 5); normal (0 0 -1); velocity (1 0 0); " << reflection << " }\n"
           "}\n";
    std::ofstream(dir / "system/controlDict")
        << kHeader << "application dpdFoamLike;\nstartFrom startTime;\nstartTime 0;\nstopAt endTime;\n"
                      "endTime 0.2;\ndeltaT 0.01;\nwriteControl timeStep;\nwriteInterval 20;\nreportInterval 10;\n";
    Snapshot s;
    s.box.hi = Eigen::Vector3d(4, 4, 6);
    s.speciesNames = {"fluid", "wall"};
    s.speciesFrozen = {false, true};
    const PairRandom random(9);
    fillRandom(s.particles, s.box, Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(4, 4, 5), 3.0, 0,
               [](double, double, double) { return true; }, random, 0);
    maxwellVelocities(s.particles, 0, s.particles.size(), 3, 1.0, random);
    writeSnapshot((dir / "0").string(), s);
    return dir;
}

// The sum of the "crossed" counts over every report line.
long totalCrossed(const std::string& log) {
    const std::regex crossed("crossed ([0-9]+)");
    long sum = 0;
    for (auto it = std::sregex_iterator(log.begin(), log.end(), crossed); it != std::sregex_iterator(); ++it)
        sum += std::stol((*it)[1]);
    return sum;
}

}  // namespace

TEST(WallLog, ThinBounceLayerFailuresAreReported) {
    const fs::path dir = makeCase("reflection bounceLayer; alpha 0.0001;");
    std::ostringstream log;
    runCase(dir.string(), log);
    const std::string text = log.str();
    EXPECT_NE(text.find("lower: reflection bounceLayer (layer 0.0001), velocity (-1 0 0)"), std::string::npos) << text;
    EXPECT_NE(text.find("Pair mixed     : fluid-wall: a = sqrt(25 x 9) = 15"), std::string::npos) << text;
    EXPECT_NE(text.find("walls since last report: lower returned"), std::string::npos) << text;
    // 200 particles-steps near each wall at v dt ~ 0.01 >> 1e-4: crossings in every interval.
    EXPECT_GT(totalCrossed(text), 10) << text;
    fs::remove_all(dir);
}

TEST(WallLog, ThickBounceLayerReportsNoCrossings) {
    const fs::path dir = makeCase("reflection bounceLayer; alpha 0.1;");
    std::ostringstream log;
    runCase(dir.string(), log);
    const std::string text = log.str();
    EXPECT_NE(text.find("walls since last report"), std::string::npos) << text;
    EXPECT_EQ(totalCrossed(text), 0) << text;
    fs::remove_all(dir);
}
