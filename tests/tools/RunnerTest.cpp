// The solver loop's guards (tools/Runner.cpp, case/ControlDict.cpp, case/DpdProperties.cpp): nothing
// unhealthy is ever written as a result, a runaway stops within checkInterval steps whatever the
// report interval, step counts that cannot be counted are refused, and a start with mobile particles
// inside a wall is refused naming the particle's row and the wall.
#include "case/ControlDict.hpp"
#include "core/Error.hpp"
#include "io/Dictionary.hpp"
#include "io/Snapshot.hpp"
#include "io/TimeDirectories.hpp"
#include "setup/InitialConditions.hpp"
#include "tools/Runner.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

namespace fs = std::filesystem;
using namespace dpd;

namespace {

const char* kHeader = "FoamFile { version 2.0; format ascii; class dictionary; object x; }\n";

// A 5^3 box of DPD fluid at rho 3 between walls at z = 0.5 and 4.5 (no frozen particles), with the
// given controlDict entries and stability block.
fs::path makeCase(const std::string& name, const std::string& control, const std::string& stability) {
    const fs::path dir = fs::temp_directory_path() / ("dpdRunner-" + name + "-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir / "constant");
    fs::create_directories(dir / "system");
    std::ofstream(dir / "constant/dpdProperties")
        << kHeader << "kT 1;\nseed 3;\nstability { " << stability << " }\n"
        << "species { fluid { frozen no; } }\npairCoeffs { fluid-fluid { a 25; gamma 4.5; } }\n"
           "walls {\n"
           "  lower { type plane; point (0 0 0.5); normal (0 0 1); }\n"
           "  upper { type plane; point (0 0 4.5); normal (0 0 -1); }\n"
           "}\n";
    std::ofstream(dir / "system/controlDict") << kHeader << "startFrom startTime;\nstartTime 0;\n" << control;
    Snapshot s;
    s.box.hi = Eigen::Vector3d(5, 5, 5);
    s.speciesNames = {"fluid"};
    s.speciesFrozen = {false};
    const PairRandom random(9);
    fillRandom(s.particles, s.box, Eigen::Vector3d(0, 0, 0.5), Eigen::Vector3d(5, 5, 4.5), 3.0, 0,
               [](double, double, double) { return true; }, random, 0);
    maxwellVelocities(s.particles, 0, s.particles.size(), 3, 1.0, random);
    writeSnapshot((dir / "0").string(), s);
    return dir;
}

// kT of a snapshot about its mean velocity.
double snapshotKT(const Snapshot& s) {
    const Particles& p = s.particles;
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (std::size_t i = 0; i < p.size(); ++i) mean += Eigen::Vector3d(p.vx[i], p.vy[i], p.vz[i]);
    mean /= static_cast<double>(p.size());
    double sum = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) sum += (Eigen::Vector3d(p.vx[i], p.vy[i], p.vz[i]) - mean).squaredNorm();
    return sum / (3.0 * static_cast<double>(p.size() - 1));
}

// Runs the case, which must stop as unstable; returns the step the error names.
long unstableStep(const fs::path& dir) {
    std::ostringstream log;
    try {
        runCase(dir.string(), log);
    } catch (const InstabilityError& e) {
        std::smatch m;
        const std::string what = e.what();
        if (std::regex_search(what, m, std::regex("\\(step ([0-9]+)\\)"))) return std::stol(m[1]);
        ADD_FAILURE() << "no step named: " << what;
        return -1;
    }
    ADD_FAILURE() << "the run did not stop: " << log.str();
    return -1;
}

}  // namespace

// deltaT 0.5 explodes within a few steps (|v| ~ 1e3 at t = 2 in a Couette case). Writing every two
// steps, every time directory left behind must hold a healthy state: finite, kT below maxKTRatio.
TEST(Runner, ARunawayIsNeverWrittenAsResults) {
    const fs::path dir = makeCase("write", "endTime 100;\ndeltaT 0.5;\nwriteInterval 2;\nreportInterval 5000;\n", "");
    const long step = unstableStep(dir);
    EXPECT_GT(step, 0);
    EXPECT_LE(step, 20) << "stopped long after it ran away";
    const std::vector<TimeDirectory> times = listTimes(dir.string());
    ASSERT_FALSE(times.empty());
    for (const TimeDirectory& t : times) {
        SCOPED_TRACE(t.name);
        const Snapshot s = readSnapshot((dir / t.name / "particles.h5").string());  // refuses non-finite values
        EXPECT_LT(snapshotKT(s), 2.0) << "an unhealthy state was written";
    }
    fs::remove_all(dir);
}

// Reports and writes every 5000 steps: the health check still runs every checkInterval steps.
TEST(Runner, ARunawayStopsWithinTheCheckIntervalWhateverTheReports) {
    const fs::path dir = makeCase("interval", "endTime 10000;\ndeltaT 0.5;\nwriteInterval 5000;\nreportInterval 5000;\n",
                                  "checkInterval 10;");
    const long step = unstableStep(dir);
    EXPECT_GT(step, 0);
    EXPECT_EQ(step % 10, 0) << "found at a check";
    EXPECT_LE(step, 30);
    fs::remove_all(dir);
}

TEST(Runner, StepCountsThatCannotBeCountedAreRefused) {
    const auto refusal = [](const std::string& entries) -> std::string {
        try {
            readRunControl(Dictionary::parse(entries, "system/controlDict"));
        } catch (const InputError& e) {
            return e.keyword();
        }
        return "";
    };
    EXPECT_EQ(refusal("endTime 1e30; deltaT 0.01; writeInterval 10;"), "endTime");
    EXPECT_EQ(refusal("endTime 10; deltaT 0.01; writeInterval 1e30;"), "writeInterval");
    EXPECT_EQ(refusal("endTime 1e30; deltaT 0.01; writeControl runTime; writeInterval 1e25;"), "endTime");
    EXPECT_EQ(refusal("endTime 10; deltaT 0.01; writeControl runTime; writeInterval 1e25;"), "writeInterval");
    EXPECT_EQ(refusal("endTime 9e13; deltaT 0.01; writeInterval 10;"), "") << "9e15 steps still fit";
}

// A mobile particle behind the lower wall (z = 0.2 < 0.5) in the start snapshot.
TEST(Runner, AStartWithAParticleInsideAWallIsRefused) {
    // Random start positions overlap and heat the fluid at first: maxKTRatio 10.
    const fs::path dir = makeCase("inside", "endTime 0.1;\ndeltaT 0.01;\nwriteInterval 10;\n", "maxKTRatio 10;");
    Snapshot s = readSnapshot((dir / "0/particles.h5").string());
    s.particles.rz[42] = 0.2;
    writeSnapshot((dir / "0").string(), s);
    std::ostringstream log;
    try {
        runCase(dir.string(), log);
        ADD_FAILURE() << "started with a particle inside a wall";
    } catch (const IoError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("0/particles.h5: dataset 'particles/position' row 42"), std::string::npos) << what;
        EXPECT_NE(what.find("inside the solid of wall 'lower'"), std::string::npos) << what;
    }
    // The run's own tolerance (maxInsideWalls) applies to the start as well.
    std::ofstream(dir / "constant/dpdProperties", std::ios::app) << "stability { maxInsideWalls 1; }\n";
    EXPECT_NO_THROW(runCase(dir.string(), log));
    fs::remove_all(dir);
}
