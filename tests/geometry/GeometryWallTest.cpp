// Walls of any shape (walls/GeometryShape with any walls/WallRule): particles that step into the solid
// are put back on the side they came from, even across a solid one pixel thick that they would step
// right over; the reflection rules act with the field's normal; the bounce layer emits the
// flux-weighted Maxwellian; the outcome does not depend on the thread count; on a curved wall (a disc)
// specular reflection keeps the speed, the bounce layer turns approaching particles round and
// bounce-forward mirrors a crossing and reverses its velocity at the end of the step.
#include "GeometryTestFiles.hpp"

#include "geometry/GeometryDictionary.hpp"
#include "io/Dictionary.hpp"
#include "../support/WallRuleNamed.hpp"
#include "walls/GeometryShape.hpp"
#include "walls/Wall.hpp"
#include "walls/WallList.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <random>

using namespace dpd;
using namespace geometryTest;

namespace {

const std::vector<std::uint8_t> kMobile{0};

// One application of the wall to the particles after a move (dt plays no part in reflections).
WallCount reflectOnce(const Wall& w, Particles& p, const Box& box, const PairRandom& random,
                      std::uint64_t step, double kT) {
    std::vector<DeferredCrossing> deferred;
    WallStep s{p, kMobile, box, random, step, kT, 0.01, deferred, {}};
    const WallCount c = w.reflect(s, 0);
    EXPECT_TRUE(deferred.empty()) << "a geometry wall defers nothing";
    return c;
}

// A 2-D box 8 x 8 of 0.25 pixels with one solid pixel column at x in [4, 4.25): a wall one pixel
// thick across the whole box. gridSpacing 0.125 puts two cell centres inside it; smooth no keeps it
// (the anti-aliasing filter would blur a feature thinner than 2 pixels away, ImageMask.hpp).
class ThinWall : public ScratchDirectory {
protected:
    static constexpr double kLeft = 4.0, kRight = 4.25;
    Box box = box2d(8.0, 8.0);

    Wall wall(const std::string& rule, double layer = 0.0) {
        Picture pic(32, std::vector<int>(32, 255));
        for (auto& row : pic) row[16] = 0;
        writePgm(path("wall.pgm"), pic);
        const Dictionary d = Dictionary::parse("type imageMask; file \"" + path("wall.pgm") +
                                                   "\"; solidValues (0); pixelSize 0.25; gridSpacing 0.125; smooth no;",
                                               "geometryDict");
        return Wall("geometry", std::make_shared<GeometryShape>(readSolidRegion(d, "", box, 1.0).distance),
                    test::ruleNamed(rule, layer));
    }

    // Particles on both sides of the wall, moving towards it by up to 1.6 in one step (more than six
    // times its thickness); ends within 0.01 of a face are avoided so that "crossed" is unambiguous.
    Particles approaching(int n, unsigned seed) const {
        std::mt19937 gen(seed);
        std::uniform_real_distribution<double> u(0.0, 1.0);
        Particles p;
        while (static_cast<int>(p.size()) < n) {
            const bool left = p.size() % 2 == 0;
            const double x = left ? kLeft - 1.5 * u(gen) : kRight + 1.5 * u(gen);
            const double vx = (left ? 1.0 : -1.0) * 1.6 * u(gen), vz = 2.0 * u(gen) - 1.0;
            const double end = x + vx;
            if (std::abs(end - kLeft) < 0.01 || std::abs(end - kRight) < 0.01) continue;
            p.add(p.size(), 0, x, 0.0, 0.1 + 7.8 * u(gen), vx, 0.0, vz);
        }
        return p;
    }
    // Moves every particle by its velocity (a step of dt = 1).
    static void move(Particles& p) {
        for (std::size_t i = 0; i < p.size(); ++i) p.rx[i] += p.vx[i], p.rz[i] += p.vz[i];
    }
};

TEST_F(ThinWall, AOnePixelSolidStopsEveryParticleOnTheSideItCameFrom) {
    for (const std::string rule : {"bounceBack", "specular", "maxwellian"}) {
        Wall w = wall(rule);
        Particles p = approaching(4000, 3);
        const Particles before = p;
        w.recordPositions(p, kMobile);
        move(p);
        long expectCrossed = 0;
        for (std::size_t i = 0; i < p.size(); ++i) expectCrossed += p.rx[i] > kLeft && p.rx[i] < box.hi.x() && before.rx[i] < kLeft ? 1
                                                                    : p.rx[i] < kRight && before.rx[i] > kRight ? 1 : 0;
        const WallCount c = reflectOnce(w, p, box, PairRandom(7), 1, 1.0);
        EXPECT_EQ(c.crossed, expectCrossed) << rule;
        EXPECT_GT(c.crossed, 1000);  // most of them would have stepped over (or into) the wall
        EXPECT_EQ(c.returned, c.crossed);
        EXPECT_EQ(c.leftInside, 0);
        for (std::size_t i = 0; i < p.size(); ++i) {
            const bool left = before.rx[i] < kLeft;
            // Back on its own side, by the mirror across the face it met (exact for straight pixel
            // edges up to float storage).
            if (left) EXPECT_LE(p.rx[i], kLeft + 1e-6) << i;
            else EXPECT_GE(p.rx[i], kRight - 1e-6) << i;
            const double metFace = left ? kLeft : kRight;
            const double endX = before.rx[i] + before.vx[i];
            const bool met = left ? endX > kLeft : endX < kRight;
            if (met) EXPECT_NEAR(p.rx[i], 2.0 * metFace - endX, 1e-5) << i;
            // Leaving the face it met.
            if (met && rule != "maxwellian") EXPECT_EQ(p.vx[i] > 0, !left) << i;
            if (met && rule == "bounceBack") EXPECT_DOUBLE_EQ(p.vz[i], -before.vz[i]);
            if (met && rule == "specular") EXPECT_DOUBLE_EQ(p.vz[i], before.vz[i]);
            if (met && rule == "specular") EXPECT_NEAR(p.vx[i], -before.vx[i], 1e-5);
        }
    }
}

// Two systems copied from one step apart: a copied wall list keeps its own record of where the
// particles stood, so the original still sees the paths that stepped over the wall after a copy
// recorded other starts (the ends: it finds only the particles that end inside).
TEST_F(ThinWall, ACopiedWallListKeepsItsOwnRecordOfWhereTheParticlesStood) {
    WallList original;
    original.add(std::make_shared<Wall>(wall("bounceBack")));
    Particles p = approaching(4000, 5);
    original.recordPositions(p, kMobile);
    const WallList copy = original;
    move(p);
    WallList stepped = copy;
    stepped.recordPositions(p, kMobile);
    long expectCrossed = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
        expectCrossed += (p.rx[i] - p.vx[i] < kLeft) != (p.rx[i] < kLeft) || (p.rx[i] - p.vx[i] > kRight) != (p.rx[i] > kRight);
    std::vector<DeferredCrossing> deferred;
    const PairRandom random(7);
    Particles q = p;
    WallStep fromOriginal{p, kMobile, box, random, 1, 1.0, 0.01, deferred, {}};
    WallStep fromStepped{q, kMobile, box, random, 1, 1.0, 0.01, deferred, {}};
    EXPECT_EQ(original.reflect(fromOriginal).crossed[0], expectCrossed);
    EXPECT_GT(expectCrossed, 1000);
    // The copy's starts are the ends: only the particles that end inside the wall are found in it.
    long endInside = 0;
    for (std::size_t i = 0; i < q.size(); ++i) endInside += original[0].signedDistance({q.rx[i], q.ry[i], q.rz[i]}) < 0.0;
    EXPECT_LT(endInside, expectCrossed / 2);
    EXPECT_EQ(stepped.reflect(fromStepped).crossed[0], endInside);
}

// Bounce layer: a particle within alpha r_c of the face moving towards it leaves with its tangential
// velocity reversed and a normal speed from the flux-weighted Maxwellian p(v) = v/kT exp(-v^2/2kT),
// whose mean is sqrt(pi kT / 2) and standard deviation sqrt((4 - pi) kT / 2) = 0.655 sqrt(kT). With n
// turned particles the mean is held to 4 standard errors, 4 x 0.655 sqrt(kT / n).
TEST_F(ThinWall, TheBounceLayerEmitsTheFluxWeightedMaxwellian) {
    const double kT = 1.5, layer = 0.1;
    Wall w = wall("bounceLayer", layer);
    Particles p;
    std::mt19937 gen(11);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const int n = 20000;
    for (int i = 0; i < n; ++i) p.add(i, 0, kLeft - 0.09 * u(gen) - 0.005, 0.0, 8.0 * u(gen), 0.001 + u(gen), 0.0, u(gen) - 0.5);
    const Particles before = p;
    w.recordPositions(p, kMobile);  // no move: every particle is in the layer, approaching
    const WallCount c = reflectOnce(w, p, box, PairRandom(3), 5, kT);
    EXPECT_EQ(c.returned, n);
    EXPECT_EQ(c.crossed, 0);
    double sum = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        EXPECT_LT(p.vx[i], 0.0);
        EXPECT_DOUBLE_EQ(p.vz[i], -before.vz[i]);
        sum += -p.vx[i];
    }
    const double mean = sum / n;
    EXPECT_NEAR(mean, std::sqrt(M_PI * kT / 2.0), 4.0 * 0.655 * std::sqrt(kT / n));
    // Particles already leaving the layer are left alone.
    for (std::size_t i = 0; i < p.size(); ++i) p.vx[i] = -std::abs(p.vx[i]);
    const Particles leaving = p;
    EXPECT_EQ(reflectOnce(w, p, box, PairRandom(3), 6, kT).returned, 0);
    EXPECT_EQ(p.vx, leaving.vx);
}

TEST_F(ThinWall, TheOutcomeDoesNotDependOnTheThreadCount) {
    Wall w = wall("bounceLayer", 0.1);
    Particles results[2];
    for (const int threads : {1, 2}) {
        omp_set_num_threads(threads);
        Particles p = approaching(3000, 5);
        w.recordPositions(p, kMobile);
        move(p);
        reflectOnce(w, p, box, PairRandom(9), 17, 1.0);
        results[threads - 1] = p;
    }
    omp_set_num_threads(omp_get_num_procs());
    EXPECT_EQ(results[0].rx, results[1].rx);
    EXPECT_EQ(results[0].vx, results[1].vx);
    EXPECT_EQ(results[0].vz, results[1].vz);
}

// A disc of radius 3 (30 pixels of 0.1, as in ImageMaskTest) in a 2-D box 12.8 x 12.8.
class DiscWall : public ScratchDirectory {
protected:
    static constexpr int kPixels = 128;
    static constexpr double kPixel = 0.1, kRadius = 3.0;
    // The contour lies within p/2 + p^2/R of the circle (ImageMaskTest).
    static constexpr double kContour = 0.5 * kPixel + kPixel * kPixel / kRadius;
    const Eigen::Vector3d centre{6.4, 0.0, 6.4};
    const Box box = box2d(kPixels * kPixel, kPixels * kPixel);

    Wall disc(const std::string& rule, double alpha = 0.0) {
        Picture pic(kPixels, std::vector<int>(kPixels, 255));
        for (int r = 0; r < kPixels; ++r)
            for (int c = 0; c < kPixels; ++c)
                if ((Eigen::Vector3d((c + 0.5) * kPixel, 0.0, (kPixels - 1 - r + 0.5) * kPixel) - centre).norm() < kRadius)
                    pic[r][c] = 0;
        writePng(path("disc.png"), pic);
        const Dictionary d = Dictionary::parse("type imageMask; file \"" + path("disc.png") +
                                                   "\"; solidValues (0); pixelSize 0.1; gridSpacing 0.1;",
                                               "geometryDict");
        return Wall("disc", std::make_shared<GeometryShape>(readSolidRegion(d, "", box, 1.0).distance),
                    test::ruleNamed(rule, alpha));
    }
    // n particles at distance [from, from + width) outside the circle, moving inwards by `along`
    // (0.1..0.3 per unit time, tilted up to 0.3 rad off the radius).
    Particles around(int n, double from, double width, unsigned seed) const {
        Particles parts;
        std::mt19937 gen(seed);
        std::uniform_real_distribution<double> u(0.0, 1.0);
        for (int i = 0; i < n; ++i) {
            const double phi = 2.0 * M_PI * u(gen), along = 0.1 + 0.2 * u(gen), tilt = 0.6 * (u(gen) - 0.5);
            const Eigen::Vector3d radial(std::cos(phi), 0.0, std::sin(phi)), tangent(-std::sin(phi), 0.0, std::cos(phi));
            const Eigen::Vector3d r = centre + (kRadius + from + width * u(gen)) * radial;
            const Eigen::Vector3d v = along * (-radial + tilt * tangent);
            parts.add(i, 0, r.x(), 0.0, r.z(), v.x(), 0.0, v.z());
        }
        return parts;
    }
    static void move(Particles& p) {
        for (std::size_t i = 0; i < p.size(); ++i) p.rx[i] += p.vx[i], p.rz[i] += p.vz[i];
    }
    // The particles in the fluid by the wall's own distance field (the contour is not the circle).
    static Particles outside(const Wall& w, const Particles& p) {
        Particles kept;
        for (std::size_t i = 0; i < p.size(); ++i)
            if (w.signedDistance({p.rx[i], p.ry[i], p.rz[i]}) >= 0.0)
                kept.add(kept.size(), 0, p.rx[i], p.ry[i], p.rz[i], p.vx[i], p.vy[i], p.vz[i]);
        return kept;
    }
};

TEST_F(DiscWall, ParticlesEnteringADiscAreMirroredBackOut) {
    const double R = kRadius;
    Wall w = disc("specular");
    // Start 0.05..0.25 outside, step 0.1..0.3 inwards (a mixture of normal and tangential).
    Particles parts = around(2000, 0.05, 0.2, 1);
    const Particles before = parts;
    w.recordPositions(parts, kMobile);
    move(parts);
    const WallCount c = reflectOnce(w, parts, box, PairRandom(1), 1, 1.0);
    EXPECT_GT(c.crossed, 500);
    EXPECT_EQ(c.leftInside, 0);
    // A returned particle is at least kContour close to being outside it, and its mirror image is at most 2 (depth + that) from
    // where it ended.
    const double contour = kContour;
    for (std::size_t i = 0; i < parts.size(); ++i) {
        const Eigen::Vector3d r(parts.rx[i], 0.0, parts.rz[i]);
        EXPECT_GT((r - centre).norm(), R - contour) << i;
        const Eigen::Vector3d end(before.rx[i] + before.vx[i], 0.0, before.rz[i] + before.vz[i]);
        const double depth = std::max(0.0, R - (end - centre).norm());
        EXPECT_LE((r - end).norm(), 2.0 * (depth + contour)) << i;
        const Eigen::Vector3d v(parts.vx[i], 0.0, parts.vz[i]), v0(before.vx[i], 0.0, before.vz[i]);
        EXPECT_NEAR(v.norm(), v0.norm(), 1e-6);  // specular keeps the speed
    }
}

// The bounce layer on a curved surface: a particle within alpha r_c of the disc (by the field's
// distance) moving towards it leaves with its velocity along the surface (the field's tangent)
// reversed and a normal speed from the flux-weighted Maxwellian, mean sqrt(pi kT / 2) held to 4
// standard errors, 4 x 0.655 sqrt(kT / n); particles leaving it or beyond it are left alone.
TEST_F(DiscWall, TheBounceLayerTurnsApproachingParticlesRoundOnACurvedWall) {
    const double kT = 1.2, alpha = 0.1;
    Wall w = disc("bounceLayer", alpha);
    Particles p = outside(w, around(6000, -0.05, 0.25, 4));
    w.recordPositions(p, kMobile);  // no move: the layer alone acts
    const Particles before = p;
    const WallCount c = reflectOnce(w, p, box, PairRandom(5), 2, kT);
    EXPECT_EQ(c.crossed, 0);
    long turned = 0;
    double speedSum = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const Eigen::Vector3d r(before.rx[i], 0.0, before.rz[i]);
        const SurfaceDistance s = w.shape().surfaceAt(r);
        const Eigen::Vector3d v0(before.vx[i], 0.0, before.vz[i]), v(p.vx[i], 0.0, p.vz[i]);
        const bool caught = s.distance >= 0.0 && s.distance < alpha && s.normal.squaredNorm() > 0.0 && v0.dot(s.normal) < 0.0;
        if (!caught) {
            EXPECT_EQ(v, v0) << i;
            continue;
        }
        ++turned;
        const Eigen::Vector3d n = s.normal, t0 = v0 - v0.dot(n) * n, t = v - v.dot(n) * n;
        EXPECT_GT(v.dot(n), 0.0) << i;
        EXPECT_LT((t + t0).norm(), 1e-12) << i;
        speedSum += v.dot(n);
    }
    EXPECT_EQ(c.returned, turned);
    ASSERT_GT(turned, 1000) << "the layer must catch enough particles for the mean to be decisive";
    EXPECT_NEAR(speedSum / turned, std::sqrt(M_PI * kT / 2.0), 4.0 * 0.655 * std::sqrt(kT / turned));
}

// Bounce-forward on a curved surface: a particle that stepped into the disc is left where it is until
// the end of the step, then goes to its mirror image across the surface with its velocity reversed
// (the wall is at rest); the others are untouched.
TEST_F(DiscWall, BounceForwardMirrorsACrossingAndReversesItsVelocityAfterTheStep) {
    Wall w = disc("bounceForward");
    Particles p = around(2000, 0.05, 0.2, 6);
    const Particles before = p;
    w.recordPositions(p, kMobile);
    move(p);
    const Particles moved = p;
    std::vector<DeferredCrossing> deferred;
    WallStep s{p, kMobile, box, PairRandom(2), 1, 1.0, 0.01, deferred, {}};
    const WallCount c = w.reflect(s, 0);
    EXPECT_GT(c.crossed, 500);
    EXPECT_EQ(c.returned, c.crossed);
    ASSERT_EQ(static_cast<long>(deferred.size()), c.crossed);
    EXPECT_EQ(p.rx, moved.rx) << "nothing moves before the end of the step";
    EXPECT_EQ(p.vx, moved.vx);
    std::vector<bool> crossed(p.size(), false);
    for (const DeferredCrossing& d : deferred) {
        const std::size_t i = d.id;  // ids are the particles' indices here
        crossed[i] = true;
        w.completeCrossing(p, i, d, box);
    }
    for (std::size_t i = 0; i < p.size(); ++i) {
        const Eigen::Vector3d r(p.rx[i], 0.0, p.rz[i]), end(moved.rx[i], 0.0, moved.rz[i]);
        const Eigen::Vector3d v(p.vx[i], 0.0, p.vz[i]), v0(before.vx[i], 0.0, before.vz[i]);
        if (!crossed[i]) {
            EXPECT_EQ(r, end) << i;
            EXPECT_EQ(v, v0) << i;
            continue;
        }
        EXPECT_GT((r - centre).norm(), kRadius - kContour) << i;
        const double depth = std::max(0.0, kRadius - (end - centre).norm());
        EXPECT_LE((r - end).norm(), 2.0 * (depth + kContour)) << i;
        EXPECT_EQ(v, Eigen::Vector3d(-v0)) << i;
    }
}

}  // namespace
