// Walls of any shape (walls/GeometryWall): particles that step into the solid are put back on the
// side they came from, even across a solid one pixel thick that they would step right over; the
// reflection rules act with the field's normal; the bounce layer emits the flux-weighted Maxwellian;
// the outcome does not depend on the thread count; and the field's normals of a disc mask are within
// a few degrees of the analytic ones.
#include "GeometryTestFiles.hpp"

#include "geometry/GeometryDictionary.hpp"
#include "io/Dictionary.hpp"
#include "walls/GeometryWall.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <random>

using namespace dpd;
using namespace geometryTest;

namespace {

const std::vector<std::uint8_t> kMobile{0};

// One application of the wall to the particles after a move (dt plays no part in reflections).
WallCount reflectOnce(const GeometryWall& w, Particles& p, const Box& box, const PairRandom& random,
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

    GeometryWall wall(ReflectionRule rule, double layer = 0.0) {
        Picture pic(32, std::vector<int>(32, 255));
        for (auto& row : pic) row[16] = 0;
        writePgm(path("wall.pgm"), pic);
        const Dictionary d = Dictionary::parse("type imageMask; file \"" + path("wall.pgm") +
                                                   "\"; solidValues (0); pixelSize 0.25; gridSpacing 0.125; smooth no;",
                                               "geometryDict");
        return GeometryWall(readSolidRegion(d, "", box, 1.0).distance, rule, layer);
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
    for (const ReflectionRule rule : {ReflectionRule::bounceBack, ReflectionRule::specular, ReflectionRule::maxwellian}) {
        GeometryWall w = wall(rule);
        Particles p = approaching(4000, 3);
        const Particles before = p;
        w.recordPositions(p, kMobile);
        move(p);
        long expectCrossed = 0;
        for (std::size_t i = 0; i < p.size(); ++i) expectCrossed += p.rx[i] > kLeft && p.rx[i] < box.hi.x() && before.rx[i] < kLeft ? 1
                                                                    : p.rx[i] < kRight && before.rx[i] > kRight ? 1 : 0;
        const WallCount c = reflectOnce(w, p, box, PairRandom(7), 1, 1.0);
        EXPECT_EQ(c.crossed, expectCrossed) << reflectionRuleName(rule);
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
            if (met && rule != ReflectionRule::maxwellian) EXPECT_EQ(p.vx[i] > 0, !left) << i;
            if (met && rule == ReflectionRule::bounceBack) EXPECT_DOUBLE_EQ(p.vz[i], -before.vz[i]);
            if (met && rule == ReflectionRule::specular) EXPECT_DOUBLE_EQ(p.vz[i], before.vz[i]);
            if (met && rule == ReflectionRule::specular) EXPECT_NEAR(p.vx[i], -before.vx[i], 1e-5);
        }
    }
}

// Bounce layer: a particle within alpha r_c of the face moving towards it leaves with its tangential
// velocity reversed and a normal speed from the flux-weighted Maxwellian p(v) = v/kT exp(-v^2/2kT),
// whose mean is sqrt(pi kT / 2) and standard deviation sqrt((4 - pi) kT / 2) = 0.655 sqrt(kT). With n
// turned particles the mean is held to 4 standard errors, 4 x 0.655 sqrt(kT / n).
TEST_F(ThinWall, TheBounceLayerEmitsTheFluxWeightedMaxwellian) {
    const double kT = 1.5, layer = 0.1;
    GeometryWall w = wall(ReflectionRule::bounceLayer, layer);
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
    GeometryWall w = wall(ReflectionRule::bounceLayer, 0.1);
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

// A disc of radius 3 (30 pixels of 0.1, as in ImageMaskTest): particles stepping into it are put back
// outside along the normal, and a specular reflection keeps their speed.
class DiscWall : public ScratchDirectory {};

TEST_F(DiscWall, ParticlesEnteringADiscAreMirroredBackOut) {
    const int n = 128;
    const double p = 0.1, R = 3.0;
    const Eigen::Vector3d centre(6.4, 0.0, 6.4);
    Picture pic(n, std::vector<int>(n, 255));
    for (int r = 0; r < n; ++r)
        for (int c = 0; c < n; ++c)
            if (Eigen::Vector3d((c + 0.5) * p, 0.0, (n - 1 - r + 0.5) * p).operator-(centre).norm() < R) pic[r][c] = 0;
    writePng(path("disc.png"), pic);
    const Dictionary d = Dictionary::parse("type imageMask; file \"" + path("disc.png") +
                                               "\"; solidValues (0); pixelSize 0.1; gridSpacing 0.1;",
                                           "geometryDict");
    const Box box = box2d(n * p, n * p);
    GeometryWall w(readSolidRegion(d, "", box, 1.0).distance, ReflectionRule::specular, 0.0);
    Particles parts;
    std::mt19937 gen(1);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int i = 0; i < 2000; ++i) {
        // Start 0.05..0.25 outside, step 0.1..0.3 inwards (a mixture of normal and tangential).
        const double phi = 2.0 * M_PI * u(gen), along = 0.1 + 0.2 * u(gen), tilt = 0.6 * (u(gen) - 0.5);
        const Eigen::Vector3d radial(std::cos(phi), 0.0, std::sin(phi)), tangent(-std::sin(phi), 0.0, std::cos(phi));
        const Eigen::Vector3d r = centre + (R + 0.05 + 0.2 * u(gen)) * radial;
        const Eigen::Vector3d v = along * (-radial + tilt * tangent);
        parts.add(i, 0, r.x(), 0.0, r.z(), v.x(), 0.0, v.z());
    }
    const Particles before = parts;
    w.recordPositions(parts, kMobile);
    for (std::size_t i = 0; i < parts.size(); ++i) parts.rx[i] += parts.vx[i], parts.rz[i] += parts.vz[i];
    const WallCount c = reflectOnce(w, parts, box, PairRandom(1), 1, 1.0);
    EXPECT_GT(c.crossed, 500);
    EXPECT_EQ(c.leftInside, 0);
    // The contour lies within p/2 + p^2/R of the circle (ImageMaskTest), so a returned particle is
    // at least that close to being outside it, and its mirror image is at most 2 (depth + that) from
    // where it ended.
    const double contour = 0.5 * p + p * p / R;
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

}  // namespace
