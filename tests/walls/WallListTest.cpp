// The wall's parts (walls/Wall.hpp, WallList.*): a shape, a rule and a surface force the System has
// never heard of run like the built-in ones -- the force with the pair forces, the crossing after each
// move, the crossings deferred completed by that wall (not by another) at the end of the step, the
// record of positions before the first step and after each one -- and wall types are chosen by name.
#include "../support/WallRuleNamed.hpp"
#include "case/DpdProperties.hpp"
#include "core/Error.hpp"
#include "integrators/GrootWarrenIntegrator.hpp"
#include "io/Dictionary.hpp"
#include "system/System.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

using namespace dpd;

namespace {

// A new shape (a solid ball), a new rule (each crossing deferred, the particle put back on the surface
// at the end of the step with its velocity kept) and a new surface force (a constant push), each
// logging its calls.
class BallShape : public WallShape {
public:
    BallShape(Eigen::Vector3d centre, double radius, std::vector<std::string>& calls)
        : centre_(std::move(centre)), radius_(radius), calls_(calls) {}
    std::string description() const override { return "a ball of radius " + std::to_string(radius_); }
    double signedDistance(const Eigen::Vector3d& r) const override { return (r - centre_).norm() - radius_; }
    SurfaceDistance surfaceAt(const Eigen::Vector3d& r) const override {
        return {signedDistance(r), (r - centre_).normalized()};
    }
    ShapeCrossing crossing(const Particles& p, std::size_t i, const Box&, double, SurfaceDistance& atEnd) const override {
        calls_.push_back("reflect");
        const Eigen::Vector3d r(p.rx[i], p.ry[i], p.rz[i]);
        atEnd = surfaceAt(r);
        if (atEnd.distance >= 0.0) return {};
        return {true, centre_ + radius_ * (r - centre_).normalized(), atEnd.normal};
    }
    void recordPositions(const Particles&, const std::vector<std::uint8_t>&) override { calls_.push_back("record"); }
    void markFlowAxes(const Box&, std::array<bool, 3>& varies) const override { varies = {true, true, true}; }
    std::uint32_t reflectionStream() const override { return kStreamReflection; }

private:
    Eigen::Vector3d centre_;
    double radius_;
    std::vector<std::string>& calls_;
};

class DeferringRule : public WallRule {
public:
    explicit DeferringRule(std::vector<std::string>& calls) : calls_(calls) {}
    std::string description() const override { return "deferring"; }
    bool defersCrossing() const override { return true; }
    Eigen::Vector3d atSurface(const Eigen::Vector3d& v, const Eigen::Vector3d&, const RuleDraw&) const override { return v; }
    Eigen::Vector3d completed(const Eigen::Vector3d& v, const Eigen::Vector3d&) const override {
        calls_.push_back("complete");
        return v;
    }

private:
    std::vector<std::string>& calls_;
};

class PushForce : public SurfaceForce {
public:
    explicit PushForce(std::vector<std::string>& calls) : calls_(calls) {}
    std::string keyword() const override { return "push"; }
    std::string description() const override { return "a push"; }
    void addForces(WallStep& s, const WallShape&, const Eigen::Vector3d&) const override {
        calls_.push_back("forces");
        for (std::size_t i = 0; i < s.particles.size(); ++i) s.particles.fx[i] += kPush;
    }
    static constexpr double kPush = 0.5;

private:
    std::vector<std::string>& calls_;
};

std::shared_ptr<Wall> ballWall(std::vector<std::string>& calls) {
    auto wall = std::make_shared<Wall>("ball", std::make_shared<BallShape>(Eigen::Vector3d(5, 5, 5), 1.0, calls),
                                       std::make_shared<DeferringRule>(calls));
    wall->withForce(std::make_shared<PushForce>(calls));
    return wall;
}

// One mobile particle in a 10^3 box, alone (no pair forces), dt 0.01.
System lonelyParticle(const Eigen::Vector3d& r, const Eigen::Vector3d& v) {
    System sys;
    sys.box.lo = Eigen::Vector3d(0, 0, 0);
    sys.box.hi = Eigen::Vector3d(10, 10, 10);
    sys.species.add({"fluid", false});
    sys.pairs = PairTable(1);
    sys.pairs.set(0, 0, {25.0, 4.5, 0.0, true});
    sys.forceParameters = {1.0, 2.0, 1.0, 0.01};
    sys.particles.add(7, 0, r.x(), r.y(), r.z(), v.x(), v.y(), v.z());
    return sys;
}

}  // namespace

TEST(WallList, ANewShapeRuleAndForceRunLikeTheBuiltInOnes) {
    std::vector<std::string> calls;
    // The particle starts 0.005 in front of the ball and moves into it at speed 2 (0.02 in a step).
    System sys = lonelyParticle({5, 5, 6.005}, {0, 0, -2});
    PlanarWallSettings floor;  // a planar wall before it in the list, far from the particle
    floor.name = "floor";
    floor.point = Eigen::Vector3d(0, 0, 1);
    floor.rule = test::ruleNamed("bounceForward");
    sys.walls.addPlane(floor);
    sys.walls.add(ballWall(calls));
    sys.initialise();
    sys.sortByCell();
    sys.computeForces();
    EXPECT_EQ(sys.particles.fx[0], PushForce::kPush) << "the wall's force is added to the pair forces (none here)";
    EXPECT_TRUE(sys.hasVelocityDependentNonPairForces());
    EXPECT_TRUE(sys.isInsideSolid(5, 5, 5.5));
    EXPECT_FALSE(sys.isInsideSolid(5, 5, 6.5));
    calls.clear();

    const WallCounters c = GrootWarrenIntegrator(0.65).step(sys);
    const std::vector<std::string> expected = {"reflect", "forces", "complete", "record"};
    EXPECT_EQ(calls, expected) << "reflect after the move, forces at the new positions, then the end of the step";
    ASSERT_EQ(c.returned.size(), 2u);
    EXPECT_EQ(c.returned[0], 0) << "the planar wall saw nothing";
    EXPECT_EQ(c.returned[1], 1);
    EXPECT_EQ(c.crossed[1], 1);
    const Eigen::Vector3d r(sys.particles.rx[0], sys.particles.ry[0], sys.particles.rz[0]);
    EXPECT_NEAR((r - Eigen::Vector3d(5, 5, 5)).norm(), 1.0, 1e-12) << "completed by the ball, on its surface";
}

TEST(WallList, WallTypesAreChosenByName) {
    const auto model = [](const std::string& type) {
        return readDpdModel(Dictionary::parse(
            "kT 1;\nspecies { fluid { frozen no; } }\npairCoeffs { fluid-fluid { a 25; gamma 4.5; } }\n"
            "walls\n{\n    lower { type " + type + "; point (0 0 -3); normal (0 0 1); }\n}\n",
            "constant/dpdProperties"));
    };
    const DpdModel m = model("plane");
    ASSERT_EQ(m.walls.size(), 1u);
    EXPECT_EQ(m.walls[0].name(), "lower");
    ASSERT_EQ(m.planes().size(), 1u);
    EXPECT_EQ(m.planes()[0]->point.z(), -3.0);
    try {
        model("sphere");
        FAIL() << "an unknown wall type must be refused";
    } catch (const InputError& e) {
        EXPECT_EQ(e.keyword(), "type");
        EXPECT_EQ(e.line(), 6);  // the line of lower's type
        EXPECT_NE(std::string(e.what()).find("expected plane"), std::string::npos) << e.what();
    }
}

namespace {

// A case with a geometry block (not built: reading the model does not open its file) and `rest`.
DpdModel geometryCase(const std::string& rest) {
    return readDpdModel(Dictionary::parse(
        "kT 1;\nspecies { fluid { frozen no; } }\npairCoeffs { fluid-fluid { a 25; gamma 4.5; } }\n"
        "geometry { type imageMask; file \"mask.png\"; pixelSize 0.5; solidValues (0); }\n" + rest,
        "constant/dpdProperties"));
}

}  // namespace

TEST(WallList, AGeometryWallIsAWallTypeAndTheOlderKeywordStillReads) {
    // Named in the walls block, with any rule and its parameters.
    const DpdModel named = geometryCase("walls { grains { type geometry; reflection bounceForward; } }\n");
    ASSERT_EQ(named.walls.size(), 1u);
    EXPECT_EQ(named.walls[0].name(), "grains");
    EXPECT_EQ(named.walls[0].rule().description(), "bounceForward");
    EXPECT_TRUE(named.planes().empty()) << "a geometry is not a plane for the channel fits";
    EXPECT_TRUE(named.inputNotes.empty());
    // A geometry block alone gets a bounce-back wall named geometry, without a note.
    const DpdModel implicit = geometryCase("");
    ASSERT_EQ(implicit.walls.size(), 1u);
    EXPECT_EQ(implicit.walls[0].name(), "geometry");
    EXPECT_EQ(implicit.walls[0].rule().description(), "bounceBack");
    EXPECT_TRUE(implicit.inputNotes.empty());
    // The older geometryWall block reads as that wall, with a note for the log.
    const DpdModel older = geometryCase("geometryWall { reflection bounceLayer; alpha 0.1; }\n");
    ASSERT_EQ(older.walls.size(), 1u);
    EXPECT_EQ(older.walls[0].name(), "geometry");
    EXPECT_EQ(older.walls[0].rule().description(), "bounceLayer (layer 0.1)");
    ASSERT_EQ(older.inputNotes.size(), 1u);
    EXPECT_NE(older.inputNotes[0].find("geometryWall"), std::string::npos) << older.inputNotes[0];
    // Both at once, or a geometry wall without a geometry block, are refused by keyword.
    try {
        geometryCase("walls { grains { type geometry; } }\ngeometryWall { reflection specular; }\n");
        FAIL() << "two geometry walls for one geometry must be refused";
    } catch (const InputError& e) {
        EXPECT_EQ(e.keyword(), "geometryWall");
    }
    try {
        readDpdModel(Dictionary::parse("kT 1;\nspecies { fluid { frozen no; } }\npairCoeffs { fluid-fluid { a 25; gamma 4.5; } }\n"
                                       "walls { grains { type geometry; } }\n",
                                       "constant/dpdProperties"));
        FAIL() << "a geometry wall without a geometry block must be refused";
    } catch (const InputError& e) {
        EXPECT_EQ(e.keyword(), "type");
        EXPECT_NE(std::string(e.what()).find("geometry block"), std::string::npos) << e.what();
    }
}
