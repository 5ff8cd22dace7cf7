// The clearance table that lets a wall pass over particles far from a geometry's surface
// (geometry/DistanceClearance.hpp): a true lower bound of the field's distance over a step's reach,
// tight enough to be of use, and a wall that consults it returns exactly the particles a wall looking
// at every particle returns.
#include "geometry/DistanceClearance.hpp"
#include "geometry/ImageMask.hpp"
#include "../support/WallRuleNamed.hpp"
#include "walls/GeometryShape.hpp"
#include "walls/WallBlocks.hpp"
#include "walls/Wall.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace dpd;

namespace {

constexpr double kBand = 2.0, kSpacing = 0.1;

// A 3-D box 12 x 3 x 12 with two grains extruded along y: a disc of radius 3 in the middle and one of
// radius 1.5 across the periodic edge at x = 12, pixels of 0.1.
class TwoGrains : public ::testing::Test {
protected:
    Box box;
    SignedDistanceField field = makeField();

    SignedDistanceField makeField() {
        box.hi = Eigen::Vector3d(12.0, 3.0, 12.0);
        GreyImage image{120, 120, std::vector<double>(120 * 120, 255.0)};
        for (int row = 0; row < 120; ++row)
            for (int column = 0; column < 120; ++column) {
                const double x = 0.1 * (column + 0.5), z = 12.0 - 0.1 * (row + 0.5);
                const double edge = std::min(x, 12.0 - x);
                if (std::hypot(x - 6.0, z - 6.0) < 3.0 || std::hypot(edge, z - 6.0) < 1.5)
                    image.grey[static_cast<std::size_t>(row) * 120 + column] = 0.0;
            }
        ImageMaskSettings s;
        s.solidValues = {0.0};
        s.pixelSize = 0.1;
        const SolidGeometry g = imageMaskGeometry(image, s, box, "two grains", kBand);
        return SignedDistanceField(g, BackgroundGrid::covering(box, kSpacing, g.uniformAxis()), kBand);
    }
};

TEST_F(TwoGrains, NoPointOfAPathLiesCloserToTheSurfaceThanItsClearance) {
    const DistanceClearance clearance(field);
    EXPECT_GE(clearance.span().x(), 2.0 * kSpacing * (1.0 - 1e-6));
    EXPECT_TRUE(std::isinf(clearance.span().y())) << "the grains do not vary along y";
    std::mt19937 gen(3);
    std::uniform_real_distribution<double> u(0.0, 1.0), step(-1.0, 1.0);
    long tight = 0, checked = 0;
    for (int k = 0; k < 20000; ++k) {
        // Paths starting over the whole box and a little outside it (a moved particle before
        // wrapping), of every length the span allows along each axis (any along y).
        const Eigen::Vector3d from(-0.2 + 12.4 * u(gen), 3.0 * u(gen), -0.2 + 12.4 * u(gen));
        const Eigen::Vector3d to =
            from + Eigen::Vector3d(clearance.span().x() * step(gen), 2.0 * step(gen), clearance.span().z() * step(gen));
        const double bound = clearance.clearanceAlong(from, to);
        for (int m = 0; m <= 16; ++m) {
            const Eigen::Vector3d x = from + (m / 16.0) * (to - from);
            ASSERT_GE(field.distance(x), bound) << "from (" << from.transpose() << ") to (" << to.transpose() << ")";
        }
        // Useful: away from the surface, the bound within the two cells the path and its interpolation
        // span (diagonally) and a step of the bound of the path's nearer end.
        const double d = std::min(field.distance(from), field.distance(to));
        if (d > 0.5 && d < kBand - 0.5) {
            ++checked;
            if (bound >= d - 2.0 * kSpacing * std::sqrt(2.0) - kBand / 254.0) ++tight;
        }
    }
    ASSERT_GT(checked, 3000);
    EXPECT_EQ(tight, checked);
}

// How many of p the shape marks within a bounce layer of 0.1, chunk by chunk as the wall passes ask.
long markedNear(const WallShape& shape, const Particles& p, const std::vector<std::uint8_t>& frozenOfSpecies) {
    std::uint8_t near[kWallChunk];
    long marked = 0;
    for (long c = 0; c < static_cast<long>(p.size()); c += kWallChunk) {
        const long end = std::min<long>(c + kWallChunk, static_cast<long>(p.size()));
        shape.markWithin(p, c, end, 0.1, frozenOfSpecies, near);
        for (long i = c; i < end; ++i) marked += near[i - c];
    }
    return marked;
}

// A shape that hands every call to a geometry but marks every particle as near: the wall then looks
// at each one.
class EveryParticleNear : public WallShape {
public:
    explicit EveryParticleNear(std::shared_ptr<GeometryShape> s) : s_(std::move(s)) {}
    double signedDistance(const Eigen::Vector3d& r) const override { return s_->signedDistance(r); }
    SurfaceDistance surfaceAt(const Eigen::Vector3d& r) const override { return s_->surfaceAt(r); }
    ShapeCrossing crossing(const Particles& p, std::size_t i, const Box& b, double normalWithin,
                           SurfaceDistance& atEnd) const override {
        return s_->crossing(p, i, b, normalWithin, atEnd);
    }
    void recordPositions(const Particles& p, const std::vector<std::uint8_t>& f) override { s_->recordPositions(p, f); }
    void markFlowAxes(const Box& b, std::array<bool, 3>& v) const override { s_->markFlowAxes(b, v); }
    std::uint32_t reflectionStream() const override { return s_->reflectionStream(); }

private:
    std::shared_ptr<GeometryShape> s_;
};

TEST_F(TwoGrains, TheWallReturnsExactlyTheParticlesItWouldReturnLookingAtEveryOne) {
    const std::vector<std::uint8_t> mobile{0};
    auto shape = std::make_shared<GeometryShape>(field);
    const Wall skipping("grains", shape, test::ruleNamed("bounceLayer", 0.1));
    Wall looking("grains", std::make_shared<EveryParticleNear>(std::make_shared<GeometryShape>(field)),
                       test::ruleNamed("bounceLayer", 0.1));
    // Fluid particles everywhere in the pores, steps of up to 0.3 along each axis (some beyond the span).
    Particles p;
    std::mt19937 gen(7);
    std::uniform_real_distribution<double> u(0.0, 1.0), v(-1.0, 1.0);
    while (p.size() < 50000) {
        const Eigen::Vector3d r(12.0 * u(gen), 3.0 * u(gen), 12.0 * u(gen));
        const double speed = u(gen) < 0.9 ? 0.08 : 0.3;
        if (field.distance(r) > 0.0) p.add(p.size(), 0, r.x(), r.y(), r.z(), speed * v(gen), speed * v(gen), speed * v(gen));
    }
    Particles q = p;
    shape->recordPositions(p, mobile);
    looking.recordPositions(q, mobile);
    for (Particles* moved : {&p, &q})
        for (std::size_t i = 0; i < moved->size(); ++i)
            moved->rx[i] += moved->vx[i], moved->ry[i] += moved->vy[i], moved->rz[i] += moved->vz[i];
    const long marked = markedNear(*shape, p, mobile);
    const PairRandom random(11);
    std::vector<DeferredCrossing> deferred;
    WallStep a{p, mobile, box, random, 4, 1.0, 0.01, deferred, {}}, b{q, mobile, box, random, 4, 1.0, 0.01, deferred, {}};
    const WallCount fromSkipping = skipping.reflect(a, 0), fromLooking = looking.reflect(b, 0);
    EXPECT_LT(marked, 0.5 * static_cast<double>(p.size())) << "the table passes over most particles";
    EXPECT_GT(fromLooking.returned, 500) << "the layer and the grains must act on enough particles to be decisive";
    EXPECT_GT(fromLooking.crossed, 50);
    EXPECT_EQ(fromSkipping.returned, fromLooking.returned);
    EXPECT_EQ(fromSkipping.crossed, fromLooking.crossed);
    EXPECT_EQ(fromSkipping.leftInside, fromLooking.leftInside);
    for (std::size_t i = 0; i < p.size(); ++i) {
        ASSERT_EQ(p.rx[i], q.rx[i]) << i;
        ASSERT_EQ(p.rz[i], q.rz[i]) << i;
        ASSERT_EQ(p.vx[i], q.vx[i]) << i;
        ASSERT_EQ(p.vy[i], q.vy[i]) << i;
        ASSERT_EQ(p.vz[i], q.vz[i]) << i;
    }
}

}  // namespace

TEST_F(TwoGrains, TheDistanceAloneIsTheFullLookupsDistanceToTheBit) {
    // The wall's path probes read the distance alone (GeometryShape::findEntry): the same number.
    std::mt19937 gen(5);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int k = 0; k < 20000; ++k) {
        const Eigen::Vector3d x(-0.2 + 12.4 * u(gen), 3.0 * u(gen), -0.2 + 12.4 * u(gen));
        ASSERT_EQ(field.distance(x), field.at(x).distance) << "x (" << x.transpose() << ")";
    }
}

TEST_F(TwoGrains, FrozenParticlesInTheGrainsAreNeitherMarkedNorMoved) {
    // Species 1 frozen, set in the grains and given velocities into them: a wall that visited them
    // would find every one's path in the solid.
    const std::vector<std::uint8_t> frozen{0, 1};
    auto shape = std::make_shared<GeometryShape>(field);
    const Wall wall("grains", shape, test::ruleNamed("bounceLayer", 0.1));
    Particles p;
    std::mt19937 gen(9);
    std::uniform_real_distribution<double> u(0.0, 1.0), v(-1.0, 1.0);
    while (p.size() < 2000) {
        const Eigen::Vector3d r(12.0 * u(gen), 3.0 * u(gen), 12.0 * u(gen));
        if (field.distance(r) < 0.0) p.add(p.size(), 1, r.x(), r.y(), r.z(), 0.1 * v(gen), 0.1 * v(gen), 0.1 * v(gen));
    }
    shape->recordPositions(p, frozen);
    const Particles before = p;
    const long marked = markedNear(*shape, p, frozen);
    EXPECT_EQ(marked, 0);
    const PairRandom random(11);
    std::vector<DeferredCrossing> deferred;
    WallStep step{p, frozen, box, random, 4, 1.0, 0.01, deferred, {}};
    const WallCount counts = wall.reflect(step, 0);
    EXPECT_EQ(counts.crossed, 0);
    EXPECT_EQ(counts.returned, 0);
    for (std::size_t i = 0; i < p.size(); ++i) {
        ASSERT_EQ(p.rx[i], before.rx[i]) << i;
        ASSERT_EQ(p.vx[i], before.vx[i]) << i;
    }
}
