// The wall interface (walls/Wall.hpp, WallList.*): a wall of a kind the System has never heard of is run
// like the built-in ones -- its forces with the pair forces, its reflection after each move, the
// crossings it deferred completed by it (not by another wall) at the end of the step, its record of
// positions before the first step and after each one -- and wall types are chosen by name.
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

// A solid ball that pushes every particle in front of it with a constant force, defers each crossing
// and, at the end of the step, puts the particle back on the surface where it was recorded.
class BallWall : public Wall {
public:
    BallWall(Eigen::Vector3d centre, double radius, std::vector<std::string>& calls)
        : Wall("ball"), centre_(std::move(centre)), radius_(radius), calls_(calls) {}
    std::string description() const override { return "a ball of radius " + std::to_string(radius_); }
    double signedDistance(const Eigen::Vector3d& r) const override { return (r - centre_).norm() - radius_; }
    void markFlowAxes(const Box&, std::array<bool, 3>& varies) const override { varies = {true, true, true}; }
    bool actsWithForces() const override { return true; }
    void addForces(WallStep& s) const override {
        calls_.push_back("forces");
        for (std::size_t i = 0; i < s.particles.size(); ++i) s.particles.fx[i] += kPush;
    }
    void recordPositions(const Particles&, const std::vector<std::uint8_t>&) override { calls_.push_back("record"); }
    WallCount reflect(WallStep& s, std::uint32_t index) const override {
        calls_.push_back("reflect");
        WallCount c;
        for (std::size_t i = 0; i < s.particles.size(); ++i) {
            const Eigen::Vector3d r(s.particles.rx[i], s.particles.ry[i], s.particles.rz[i]);
            if (!isInsideSolid(r)) continue;
            ++c.crossed;
            ++c.returned;
            const Eigen::Vector3d out = centre_ + radius_ * (r - centre_).normalized();
            s.deferred.push_back({s.particles.id[i], index, out.x(), out.y(), out.z()});
        }
        return c;
    }
    void completeCrossing(Particles& p, std::size_t i, const DeferredCrossing& d, const Box&) const override {
        calls_.push_back("complete");
        p.rx[i] = d.x;
        p.ry[i] = d.y;
        p.rz[i] = d.z;
    }
    static constexpr double kPush = 0.5;

private:
    Eigen::Vector3d centre_;
    double radius_;
    std::vector<std::string>& calls_;
};

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

TEST(WallList, ANewKindOfWallRunsLikeTheBuiltInOnes) {
    std::vector<std::string> calls;
    // The particle starts 0.005 in front of the ball and moves into it at speed 2 (0.02 in a step).
    System sys = lonelyParticle({5, 5, 6.005}, {0, 0, -2});
    PlanarWallSettings floor;  // a planar wall before it in the list, far from the particle
    floor.name = "floor";
    floor.point = Eigen::Vector3d(0, 0, 1);
    floor.rule = ReflectionRule::bounceForward;
    sys.walls.addPlane(floor);
    sys.walls.add(std::make_shared<BallWall>(Eigen::Vector3d(5, 5, 5), 1.0, calls));
    sys.initialise();
    sys.sortByCell();
    sys.computeForces();
    EXPECT_EQ(sys.particles.fx[0], BallWall::kPush) << "the wall's force is added to the pair forces (none here)";
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
    ASSERT_NE(m.walls[0].plane(), nullptr);
    EXPECT_EQ(m.walls[0].plane()->point.z(), -3.0);
    try {
        model("sphere");
        FAIL() << "an unknown wall type must be refused";
    } catch (const InputError& e) {
        EXPECT_EQ(e.keyword(), "type");
        EXPECT_EQ(e.line(), 6);  // the line of lower's type
        EXPECT_NE(std::string(e.what()).find("expected plane"), std::string::npos) << e.what();
    }
}
