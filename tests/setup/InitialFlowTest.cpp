// The initial Poiseuille flow of blockFrozenWall (setup/InitialFlow.*): the profile is the analytic
// no-slip solution of the case's body force and walls, and every geometry it cannot serve is refused
// naming the keyword.
#include "analysis/PoiseuilleFit.hpp"
#include "../support/InputErrorOf.hpp"
#include "core/Error.hpp"
#include "io/Dictionary.hpp"
#include "case/DpdProperties.hpp"
#include "setup/InitialFlow.hpp"

#include <gtest/gtest.h>

#include <string>

using namespace dpd;

namespace {

// A channel case: walls at z = -5 and +5 (in either order), body force g along x.
std::string properties(const std::string& walls, const std::string& force = "uniform; value (0.02 0 0)") {
    return "dimension 3; kT 1; cutoff 1; seed 1;\n"
           "species { fluid { frozen no; } wall { frozen yes; } }\n"
           "pairCoeffs { fluid-fluid { a 18.75; gamma 4.5; } fluid-wall { a 18.75; gamma 4.5; } }\n"
           "bodyForce { type " + force + "; }\n"
           "walls { " + walls + " }\n";
}

const std::string kLower = "lower { type plane; point (0 0 -5); normal (0 0 1); reflection bounceBack; }";
const std::string kUpper = "upper { type plane; point (0 0 5); normal (0 0 -1); reflection bounceBack; }";

InitialFlow read(const std::string& props, const std::string& fluid) {
    const DpdModel model = readDpdModel(Dictionary::parse(props, "constant/dpdProperties"));
    const Dictionary d = Dictionary::parse(fluid, "system/blockFrozenWallDict");
    Box box;
    box.lo = Eigen::Vector3d(-5, -1.5, -6);
    box.hi = Eigen::Vector3d(5, 1.5, 6);
    return readInitialFlow(d, model, box, 0, 4.0);
}

std::string refusal(const std::string& props, const std::string& fluid) {
    return test::inputErrorOf([&] { read(props, fluid); });
}

}  // namespace

TEST(InitialFlow, AbsentMeansNone) {
    const InitialFlow f = read(properties(kLower + kUpper), "species fluid; density 4;");
    EXPECT_EQ(f.type, InitialFlow::Type::none);
    EXPECT_EQ(f.velocityAt(0.0).norm(), 0.0);
}

TEST(InitialFlow, PoiseuilleProfileIsTheAnalyticNoSlipSolution) {
    // Walls listed upper first: the reader must still find which is the lower one.
    const InitialFlow f = read(properties(kUpper + kLower), "initialFlow { type poiseuille; nu 0.25; }");
    ASSERT_EQ(f.type, InitialFlow::Type::poiseuille);
    EXPECT_EQ(f.axis, 2);
    EXPECT_DOUBLE_EQ(f.lower, -5.0);
    EXPECT_DOUBLE_EQ(f.upper, 5.0);
    // u_max = g d^2 / (8 nu) = 0.02 * 100 / 2 = 1 at the centre; zero at and beyond the walls.
    EXPECT_NEAR(f.velocityAt(0.0).x(), 1.0, 1e-14);
    EXPECT_NEAR(f.velocityAt(2.5).x(), 0.75, 1e-14);
    EXPECT_EQ(f.velocityAt(0.0).y(), 0.0);
    EXPECT_EQ(f.velocityAt(5.0).norm(), 0.0);
    EXPECT_EQ(f.velocityAt(-5.5).norm(), 0.0);
}

TEST(InitialFlow, DefaultViscosityIsTheKineticTheoryEstimate) {
    const InitialFlow f = read(properties(kLower + kUpper), "initialFlow { type poiseuille; }");
    EXPECT_DOUBLE_EQ(f.nu, kineticTheoryViscosity(1.0, 4.5, 4.0, 1.0));
}

TEST(InitialFlow, AddsTheProfileToTheThermalVelocities) {
    const InitialFlow f = read(properties(kLower + kUpper), "initialFlow { type poiseuille; nu 0.25; }");
    Particles p;
    p.add(0, 0, 0.0, 0.0, 0.0, 0.1, 0.2, 0.3);
    p.add(1, 0, 0.0, 0.0, 5.2, 0.1, 0.2, 0.3);  // behind the upper wall: untouched
    addInitialFlow(p, 0, p.size(), f);
    EXPECT_NEAR(p.vx[0], 1.1, 1e-14);
    EXPECT_DOUBLE_EQ(p.vy[0], 0.2);
    EXPECT_DOUBLE_EQ(p.vz[0], 0.3);
    EXPECT_DOUBLE_EQ(p.vx[1], 0.1);
}

TEST(InitialFlow, ReversePoiseuilleIsTwoOppositeParabolas) {
    const std::string props = "dimension 3; kT 1; cutoff 1; seed 1;\n"
                              "species { fluid { frozen no; } }\n"
                              "pairCoeffs { fluid-fluid { a 18.75; gamma 4.5; } }\n"
                              "bodyForce { type reversePoiseuille; value (0.02 0 0); gradientAxis z; }\n";
    const InitialFlow f = read(props, "initialFlow { type reversePoiseuille; nu 0.25; }");
    ASSERT_EQ(f.type, InitialFlow::Type::reversePoiseuille);
    // Box [-6, 6) along z: +g drives [-6, 0), peak g h^2 / (8 nu) = 0.02 * 36 / 2 = 0.36 at z = -3;
    // -g drives [0, 6), the mirror image; the velocity is zero at the half boundaries.
    EXPECT_NEAR(f.velocityAt(-3.0).x(), 0.36, 1e-14);
    EXPECT_NEAR(f.velocityAt(3.0).x(), -0.36, 1e-14);
    EXPECT_NEAR(f.velocityAt(0.0).x(), 0.0, 1e-14);
    EXPECT_NEAR(f.velocityAt(-4.5).x(), 0.27, 1e-14);
    // Walls and reverse Poiseuille do not go together.
    EXPECT_NE(refusal(properties(kLower + kUpper), "initialFlow { type reversePoiseuille; }").find("without walls"),
              std::string::npos);
}

TEST(InitialFlow, RefusesWhatItCannotServe) {
    const std::string fluid = "initialFlow { type poiseuille; }";
    EXPECT_NE(refusal(properties(kLower), fluid).find("two planar walls"), std::string::npos);
    const std::string moving =
        "upper { type plane; point (0 0 5); normal (0 0 -1); velocity (1 0 0); reflection bounceBack; }";
    EXPECT_NE(refusal(properties(kLower + moving), fluid).find("at rest"), std::string::npos);
    EXPECT_NE(refusal(properties(kLower + kUpper, "none"), fluid).find("uniform body force"), std::string::npos);
    EXPECT_NE(refusal(properties(kLower + kUpper, "uniform; value (0.02 0 0.01)"), fluid).find("normal"),
              std::string::npos);
    const std::string unknown = refusal(properties(kLower + kUpper), "initialFlow { type couette; }");
    EXPECT_NE(unknown.find("unknown initial flow"), std::string::npos);
    EXPECT_NE(unknown.find("type"), std::string::npos);
    EXPECT_NE(refusal(properties(kLower + kUpper), "initialFlow { type poiseuille; nu -1; }").find("positive"),
              std::string::npos);
}

// The walls of a geometry block (randomEquilWall) are not planar walls: axis and wallPositions
// place the channel of the start.
TEST(InitialFlow, PoiseuilleBetweenGivenWallPositions) {
    const std::string noWalls = properties("");
    const InitialFlow f = read(noWalls, "initialFlow { type poiseuille; nu 0.25; axis z; wallPositions (-4 6); }");
    ASSERT_EQ(f.type, InitialFlow::Type::poiseuille);
    EXPECT_EQ(f.axis, 2);
    // Centre z = 1, u_max = 0.02 * 100 / (8 * 0.25) = 1; zero at and beyond the given walls.
    EXPECT_NEAR(f.velocityAt(1.0).x(), 1.0, 1e-14);
    EXPECT_EQ(f.velocityAt(-4.5).norm(), 0.0);
    EXPECT_EQ(f.velocityAt(6.0).norm(), 0.0);
    // Both keywords or neither; not beside planar walls; a real axis; lower before upper.
    EXPECT_NE(refusal(noWalls, "initialFlow { type poiseuille; axis z; }").find("both"), std::string::npos);
    EXPECT_NE(refusal(properties(kLower + kUpper), "initialFlow { type poiseuille; axis z; wallPositions (-4 6); }")
                  .find("planar walls"),
              std::string::npos);
    EXPECT_NE(refusal(noWalls, "initialFlow { type poiseuille; axis w; wallPositions (-4 6); }").find("'axis'"),
              std::string::npos);
    EXPECT_NE(refusal(noWalls, "initialFlow { type poiseuille; axis z; wallPositions (6 -4); }").find("upper > lower"),
              std::string::npos);
    EXPECT_NE(refusal(noWalls, "initialFlow { type poiseuille; axis x; wallPositions (-4 6); }").find("normal"),
              std::string::npos);
}
