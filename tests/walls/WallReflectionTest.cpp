// Planar walls (walls/PlaneShape.*, Wall.*, WallList.*): the reflection rules of docs/walls.md section 3.3 applied
// by a System during a step, the Maxwellian (diffuse) wall's velocity distribution, the reflection
// counters; and the frozen lattices behind a wall (setup/FrozenLattice.*, section 3.1).
#include "../support/WallRuleNamed.hpp"
#include "integrators/EulerIntegrator.hpp"
#include "integrators/GrootWarrenIntegrator.hpp"
#include "system/System.hpp"
#include "setup/FrozenLattice.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <stdexcept>

using namespace dpd;

namespace {

PlanarWallSettings wall(const Eigen::Vector3d& point, const Eigen::Vector3d& normal, const std::string& rule,
                const Eigen::Vector3d& velocity = Eigen::Vector3d::Zero()) {
    PlanarWallSettings w;
    w.name = "wall";
    w.point = point;
    w.normal = normal;
    w.rule = test::ruleNamed(rule);
    w.velocity = velocity;
    return w;
}

// A 10 x 10 x 10 box (10 x 10 in the x-z plane for dimension 2) with one mobile particle, no pair
// forces to speak of (it is alone), dt = 0.01, and the given walls.
System lonely(int dimension, const std::vector<PlanarWallSettings>& walls, const Eigen::Vector3d& r,
              const Eigen::Vector3d& v, double kT = 1.0) {
    System sys;
    sys.box.dimension = dimension;
    sys.box.lo = Eigen::Vector3d(0, 0, 0);
    sys.box.hi = Eigen::Vector3d(10, dimension == 3 ? 10 : 1, 10);
    sys.species.add({"fluid", false});
    sys.pairs = PairTable(1);
    sys.pairs.set(0, 0, {25.0, 4.5, 0.0, true});
    sys.forceParameters = {1.0, 2.0, kT, 0.01};
    sys.seed = 3;
    for (const auto& w : walls) sys.walls.addPlane(w);
    sys.particles.add(42, 0, r.x(), r.y(), r.z(), v.x(), v.y(), v.z());
    sys.initialise();
    sys.sortByCell();
    sys.computeForces();
    return sys;
}

Eigen::Vector3d position(const System& sys) {
    return {sys.particles.rx[0], sys.particles.ry[0], sys.particles.rz[0]};
}
Eigen::Vector3d velocity(const System& sys) {
    return {sys.particles.vx[0], sys.particles.vy[0], sys.particles.vz[0]};
}

// Positions go through a few roundings (r + dt v, then the mirror): 1e-12 is ~1000 ulp at 10.
constexpr double kTol = 1e-12;

void expectVectorNear(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double tol, const std::string& what) {
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(a[k], b[k], tol) << what << " component " << k;
}

}  // namespace

TEST(WallReflection, BounceBackReversesTheVelocityRelativeToTheWall) {
    // Wall z = 2 with normal +z sliding at u_w = (0.3, 0.2, 0). The particle at (5, 5, 2.05) with
    // v = (1, -0.5, -10) ends the drift at (5.01, 4.995, 1.95), 0.05 behind the plane; mirrored to
    // z = 2.05. Relative velocity v - u_w = (0.7, -0.7, -10), reversed (-0.7, 0.7, 10), plus u_w:
    // (-0.4, 0.9, 10). (A rule that ignored the wall velocity would give (-1, 0.5, 10).)
    const Eigen::Vector3d uw(0.3, 0.2, 0.0);
    for (const std::string scheme : {"GrootWarren", "Euler"}) {
        SCOPED_TRACE(scheme);
        System sys = lonely(3, {wall({0, 0, 2}, {0, 0, 1}, "bounceBack", uw)}, {5, 5, 2.05},
                            {1.0, -0.5, -10.0});
        IntegratorSettings s;
        s.type = scheme;
        const WallCounters c = makeIntegrator(s)->step(sys);
        expectVectorNear(position(sys), {5.01, 4.995, 2.05}, kTol, "position");
        expectVectorNear(velocity(sys), {-0.4, 0.9, 10.0}, kTol, "velocity");
        ASSERT_EQ(c.returned.size(), 1u);
        EXPECT_EQ(c.returned[0], 1);
        EXPECT_EQ(c.insideAfter, 0);
    }
}

TEST(WallReflection, SpecularReversesTheNormalComponent) {
    // Upper wall z = 8 with normal -z. From (3, 4, 7.97) with v = (2, 1, 5): drift to (3.02, 4.01, 8.02),
    // 0.02 behind; mirrored to z = 7.98. Normal component reversed: (2, 1, -5). The wall's tangential
    // velocity does not change a specular reflection (relative tangential part is kept, then added back).
    for (const Eigen::Vector3d uw : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0.7, -0.4, 0)}) {
        System sys = lonely(3, {wall({0, 0, 8}, {0, 0, -1}, "specular", uw)}, {3, 4, 7.97}, {2, 1, 5});
        GrootWarrenIntegrator gw(0.65);
        const WallCounters c = gw.step(sys);
        expectVectorNear(position(sys), {3.02, 4.01, 7.98}, kTol, "position");
        expectVectorNear(velocity(sys), {2.0, 1.0, -5.0}, kTol, "velocity");
        EXPECT_EQ(c.returned[0], 1);
    }
}

TEST(WallReflection, WallsAlongOtherAxesAnd2D) {
    // 2-D (x-z plane): wall x = 1.5 with normal +x, bounce-back, sliding along z at 0.6. From
    // (1.52, 0.5, 5) with v = (-4, 0, 1): drift to (1.48, 0.5, 5.01), mirrored to x = 1.52; relative
    // velocity (-4, 0, 0.4) reversed (4, 0, -0.4), plus (0, 0, 0.6): (4, 0, 0.2).
    System sys2 = lonely(2, {wall({1.5, 0, 0}, {1, 0, 0}, "bounceBack", {0, 0, 0.6})}, {1.52, 0.5, 5},
                         {-4, 0, 1});
    GrootWarrenIntegrator gw(0.65);
    EXPECT_EQ(gw.step(sys2).returned[0], 1);
    expectVectorNear(position(sys2), {1.52, 0.5, 5.01}, kTol, "position");
    expectVectorNear(velocity(sys2), {4.0, 0.0, 0.2}, kTol, "velocity");
    // 3-D wall y = 9 with normal -y, specular: from (5, 8.99, 5), v = (0, 3, -1): to (5, 9.02, 4.99),
    // mirrored to y = 8.98, velocity (0, -3, -1).
    System sys3 = lonely(3, {wall({0, 9, 0}, {0, -1, 0}, "specular")}, {5, 8.99, 5}, {0, 3, -1});
    EXPECT_EQ(gw.step(sys3).returned[0], 1);
    expectVectorNear(position(sys3), {5, 8.98, 4.99}, kTol, "position");
    expectVectorNear(velocity(sys3), {0, -3, -1}, kTol, "velocity");
}

TEST(WallReflection, CountersCountOnlyCrossings) {
    // Two walls; the particle crosses only the second. Then a particle that stays in the fluid.
    const std::vector<PlanarWallSettings> walls = {wall({0, 0, 2}, {0, 0, 1}, "bounceBack"),
                                           wall({0, 0, 8}, {0, 0, -1}, "bounceBack")};
    GrootWarrenIntegrator gw(0.65);
    System crossing = lonely(3, walls, {5, 5, 7.99}, {0, 0, 3});
    WallCounters c = gw.step(crossing);
    ASSERT_EQ(c.returned.size(), 2u);
    EXPECT_EQ(c.returned[0], 0);
    EXPECT_EQ(c.returned[1], 1);
    EXPECT_EQ(c.insideAfter, 0);
    System staying = lonely(3, walls, {5, 5, 5}, {1, 2, -3});
    c = gw.step(staying);
    EXPECT_EQ(c.returned[0], 0);
    EXPECT_EQ(c.returned[1], 0);
    expectVectorNear(velocity(staying), {1, 2, -3}, 0.0, "untouched velocity");
    // With the rule "none" nothing is reflected and the particle is reported inside the solid.
    System none = lonely(3, {wall({0, 0, 2}, {0, 0, 1}, "none")}, {5, 5, 2.01}, {0, 0, -3});
    c = gw.step(none);
    EXPECT_EQ(c.returned[0], 0);
    EXPECT_EQ(c.insideAfter, 1);
    EXPECT_NEAR(position(none).z(), 1.98, kTol);
}

// A wall whose plane lies on a face of the periodic box: a particle crossing z = lo must be mirrored
// back, not wrapped round to just below z = hi (the integrators reflect before wrapping). Such walls
// are refused by buildSystem and blockFrozenWall all the same (WallList::thinWall), because fluid would
// interact with fluid through them across the periodic boundary; this test holds the reflection
// itself to docs/walls.md 3.3: at z = 0.02 moving at -4 the particle ends at -0.02, is mirrored to 0.02
// and bounced back to v_z = +4.
TEST(WallReflection, WallOnTheBoxFaceStillReflects) {
    const std::vector<PlanarWallSettings> walls = {wall({0, 0, 0}, {0, 0, 1}, "bounceBack"),
                                           wall({0, 0, 10}, {0, 0, -1}, "bounceBack")};
    GrootWarrenIntegrator gw(0.65);
    System down = lonely(3, walls, {5, 5, 0.02}, {0, 0, -4});
    const WallCounters c = gw.step(down);
    EXPECT_EQ(c.returned[0], 1);
    EXPECT_NEAR(position(down).z(), 0.02, kTol);
    EXPECT_NEAR(velocity(down).z(), 4.0, kTol);
    System up = lonely(3, walls, {5, 5, 9.98}, {0, 0, 4});
    gw.step(up);
    EXPECT_NEAR(position(up).z(), 9.98, kTol);
    EXPECT_NEAR(velocity(up).z(), -4.0, kTol);
}

TEST(WallReflection, MaxwellianSingleParticle) {
    // Diffuse wall z = 2 (normal +z) at rest: the position is mirrored as for the other rules, the new
    // velocity leaves the wall (v_z > 0). In 2-D the inactive y component stays zero.
    for (int dimension : {3, 2}) {
        System sys = lonely(dimension, {wall({0, 0, 2}, {0, 0, 1}, "maxwellian")},
                            {5, dimension == 3 ? 5.0 : 0.5, 2.05}, {1.0, 0.0, -10.0});
        GrootWarrenIntegrator gw(0.65);
        EXPECT_EQ(gw.step(sys).returned[0], 1);
        EXPECT_NEAR(position(sys).z(), 2.05, kTol);
        EXPECT_GT(velocity(sys).z(), 0.0);
        if (dimension == 2) EXPECT_EQ(velocity(sys).y(), 0.0);
    }
}

// Many particles cross a diffuse wall in one step; the velocities they leave with are the wall's
// flux-weighted Maxwellian at kT = 1.5, moving with the wall at u_w = (0.5, 0, 0):
//   normal: Rayleigh, p(v) = v/kT exp(-v^2 / 2kT): mean sqrt(pi kT / 2) = 1.53499, variance
//           (2 - pi/2) kT = 0.64380; E v^2 = 2 kT, Var v^2 = E v^4 - (2kT)^2 = 8kT^2 - 4kT^2 = 4 kT^2;
//   tangential (relative to the wall): Gaussian, mean 0, variance kT, Var of the square 2 kT^2.
// Each sample mean is accepted within 4 standard errors sqrt(variance / M) (M = 40,000 independent
// draws: each particle's draw is keyed by its own id). The shape of the normal distribution is tested
// with a chi^2 over 20 bins of equal Rayleigh probability (19 degrees of freedom: accept below
// 19 + 4 sqrt(38) = 43.7).
TEST(WallReflection, MaxwellianDistributionIsFluxWeightedAtTheWallTemperature) {
    const double kT = 1.5;
    const Eigen::Vector3d uw(0.5, 0.0, 0.0);
    System sys;
    sys.box.lo = Eigen::Vector3d(0, 0, 0);
    sys.box.hi = Eigen::Vector3d(30, 30, 6);
    sys.species.add({"fluid", false});
    sys.pairs = PairTable(1);
    sys.pairs.set(0, 0, {0.0, 0.0, 0.0, false});  // ideal gas: only the wall acts
    sys.forceParameters = {1.0, 2.0, kT, 0.01};
    sys.seed = 99;
    sys.walls.addPlane(wall({0, 0, 2}, {0, 0, 1}, "maxwellian", uw));
    const PairRandom placement(5);
    const int m = 40000;
    for (int k = 0; k < m; ++k) {
        const auto u = placement.particleUniforms(0, k, kStreamInitialPosition);
        // z in (2, 2.02) moving at -2: every particle is behind the plane after a step of 0.01.
        sys.particles.add(k, 0, 30 * u[0], 30 * u[1], 2.0 + 0.02 * u[2], 0.3, -0.1, -2.0);
    }
    sys.initialise();
    sys.sortByCell();
    sys.computeForces();
    GrootWarrenIntegrator gw(0.65);
    const WallCounters c = gw.step(sys);
    EXPECT_EQ(c.returned[0], m);
    EXPECT_EQ(c.insideAfter, 0);

    double sn = 0, sn2 = 0, sx = 0, sx2 = 0, sy = 0, sy2 = 0;
    std::vector<long> bins(20, 0);
    for (int i = 0; i < m; ++i) {
        const double vn = sys.particles.vz[i];
        const double vx = sys.particles.vx[i] - uw.x(), vy = sys.particles.vy[i] - uw.y();
        ASSERT_GT(vn, 0.0);
        ASSERT_GE(sys.particles.rz[i], 2.0);
        sn += vn; sn2 += vn * vn;
        sx += vx; sx2 += vx * vx;
        sy += vy; sy2 += vy * vy;
        // Rayleigh CDF F(v) = 1 - exp(-v^2 / 2kT): the bin is floor(20 F).
        bins[std::min(19, static_cast<int>(20.0 * (1.0 - std::exp(-vn * vn / (2.0 * kT)))))]++;
    }
    const double M = m;
    const double meanN = sn / M, meanN2 = sn2 / M;
    RecordProperty("rayleighMean", std::to_string(meanN));
    std::printf("    Rayleigh mean %.5f (expected %.5f), <v_n^2> %.4f, <v_x^2> %.4f, <v_y^2> %.4f\n", meanN,
                std::sqrt(M_PI * kT / 2.0), meanN2, sx2 / M, sy2 / M);
    const double expectedMean = std::sqrt(M_PI * kT / 2.0);
    EXPECT_NEAR(meanN, expectedMean, 4.0 * std::sqrt((2.0 - M_PI / 2.0) * kT / M)) << "normal mean";
    EXPECT_NEAR(meanN2, 2.0 * kT, 4.0 * std::sqrt(4.0 * kT * kT / M)) << "normal second moment";
    EXPECT_NEAR(sx / M, 0.0, 4.0 * std::sqrt(kT / M)) << "tangential x mean (relative to the wall)";
    EXPECT_NEAR(sy / M, 0.0, 4.0 * std::sqrt(kT / M)) << "tangential y mean";
    EXPECT_NEAR(sx2 / M, kT, 4.0 * std::sqrt(2.0 * kT * kT / M)) << "tangential x variance";
    EXPECT_NEAR(sy2 / M, kT, 4.0 * std::sqrt(2.0 * kT * kT / M)) << "tangential y variance";
    double chi2 = 0.0;
    for (long b : bins) chi2 += (b - M / 20.0) * (b - M / 20.0) / (M / 20.0);
    EXPECT_LT(chi2, 19.0 + 4.0 * std::sqrt(38.0)) << "chi^2 of the normal velocity against Rayleigh";
}

// ---------------------------------------------------------------------------------------------------
// Frozen lattices.

namespace {

Box box3(double lx, double ly, double lz) {
    Box b;
    b.lo = Eigen::Vector3d(0, 0, 0);
    b.hi = Eigen::Vector3d(lx, ly, lz);
    return b;
}

// Smallest distance between two points, periodic along the in-plane axes x and y.
double minimumDistance(const std::vector<Eigen::Vector3d>& pts, const Box& box) {
    double best = 1e300;
    const Eigen::Vector3d L = box.length();
    for (std::size_t i = 0; i < pts.size(); ++i)
        for (std::size_t j = i + 1; j < pts.size(); ++j) {
            Eigen::Vector3d d = pts[i] - pts[j];
            for (int a = 0; a < 2; ++a) d[a] -= L[a] * std::round(d[a] / L[a]);
            best = std::min(best, d.norm());
        }
    return best;
}

}  // namespace

TEST(FrozenLattice, FccNumberDensityBehindTheWall) {
    // fcc at density 4: lattice constant a = (4 / 4)^(1/3) = 1; (100) planes every a/2 at depths
    // a/4, 3a/4, 5a/4, ..., each with 2 points per in-plane cell.
    FrozenLatticeSettings s;
    s.lattice = "fcc";
    s.density = 4.0;
    s.thickness = 1.0;
    {
        // Commensurate box 6 x 5: 2 planes (0.25, 0.75) x 2 x 6 x 5 = 120 points in 6 x 5 x 1: exactly
        // 4 per unit area per unit depth.
        const Box box = box3(6.0, 5.0, 12.0);
        const PlanarWallSettings w = wall({0, 0, 3}, {0, 0, 1}, "bounceBack");
        const auto pts = frozenLattice(box, w, s);
        EXPECT_EQ(pts.size(), 120u);
        EXPECT_DOUBLE_EQ(pts.size() / (6.0 * 5.0 * s.thickness), 4.0);
        std::set<double> depths;
        for (const auto& r : pts) {
            const double depth = w.point.z() - r.z();
            EXPECT_GT(depth, 0.0);
            EXPECT_LT(depth, s.thickness);
            EXPECT_GE(r.x(), 0.0); EXPECT_LT(r.x(), 6.0);
            EXPECT_GE(r.y(), 0.0); EXPECT_LT(r.y(), 5.0);
            depths.insert(std::round(depth * 1e9) / 1e9);
        }
        EXPECT_EQ(depths, (std::set<double>{0.25, 0.75}));
        // fcc: nearest neighbours a / sqrt(2) apart (an un-staggered stack would put points a/2 apart).
        EXPECT_NEAR(minimumDistance(pts, box), 1.0 / std::sqrt(2.0), 1e-12);
    }
    {
        // Non-commensurate box 6.3 x 5 and thickness 1.3 (3 planes: 0.25, 0.75, 1.25), upper wall
        // (normal -z, solid above z = 9). In-plane cells fitted: round(6.3 / 1) = 6 of 1.05 along x,
        // 5 of 1 along y. Expected exactly 3 x 2 x 6 x 5 = 180 points, i.e. 180 / (6.3 x 5 x 1.3)
        // = 4 x (1 / 1.05) x (1.5 / 1.3) per unit area per unit depth: the fitted spacing thins the
        // density by 1/1.05, and 1.3 holds 1.5 plane spacings' worth of planes.
        const Box box = box3(6.3, 5.0, 12.0);
        s.thickness = 1.3;
        const PlanarWallSettings w = wall({0, 0, 9}, {0, 0, -1}, "bounceBack");
        const auto pts = frozenLattice(box, w, s);
        EXPECT_EQ(pts.size(), 180u);
        for (const auto& r : pts) {
            const double depth = r.z() - w.point.z();
            EXPECT_GT(depth, 0.0);
            EXPECT_LT(depth, s.thickness);
            EXPECT_LT(w.signedDistance(r.x(), r.y(), r.z()), 0.0);  // behind the plane
        }
        // Nearest neighbours: in-plane (0,0)-(1/2,1/2) is sqrt(0.525^2 + 0.5^2) = 0.725; between planes
        // (0,0)-(0,1/2) is sqrt(0.5^2 + 0.5^2) = 0.7071.
        EXPECT_NEAR(minimumDistance(pts, box), std::sqrt(0.5), 1e-12);
    }
    {
        // 2-D (x-z): 2 points per a x a cell, a = sqrt(2 / 4) = 0.70711; lines every a/2 = 0.35355 at
        // depths 0.17678, 0.53033, 0.88388 (< 1), alternating offsets. Box 10 long: round(10 / a) = 14
        // points per line: 42 in all.
        Box box = box3(10.0, 1.0, 10.0);
        box.dimension = 2;
        s.thickness = 1.0;
        const PlanarWallSettings w = wall({0, 0, 3}, {0, 0, 1}, "bounceBack");
        const auto pts = frozenLattice(box, w, s);
        EXPECT_EQ(pts.size(), 3u * 14u);
        for (const auto& r : pts) {
            EXPECT_EQ(r.y(), 0.5);
            EXPECT_GT(w.point.z() - r.z(), 0.0);
            EXPECT_LT(w.point.z() - r.z(), 1.0);
        }
    }
}

TEST(FrozenLattice, LayersAtTheGivenDepthsAndSpacing) {
    // Three layers at 0.15, 0.35, 0.75 behind z = 3, spacing 0.5 along x and 1 along y: in a 6 x 5 box
    // 12 x 5 = 60 points per layer.
    FrozenLatticeSettings s;
    s.lattice = "layers";
    s.layerDepths = {0.15, 0.35, 0.75};
    s.layerSpacing = {0.5, 1.0};
    const Box box = box3(6.0, 5.0, 12.0);
    const PlanarWallSettings w = wall({0, 0, 3}, {0, 0, 1}, "bounceBack");
    const auto pts = frozenLattice(box, w, s);
    ASSERT_EQ(pts.size(), 180u);
    std::map<double, int> perDepth;
    std::set<double> xs, ys;
    for (const auto& r : pts) {
        const double depth = w.point.z() - r.z();
        // Exactly the depths asked for (to the rounding of 3 - depth).
        const double nearest = *std::min_element(s.layerDepths.begin(), s.layerDepths.end(), [&](double a, double b) {
            return std::abs(a - depth) < std::abs(b - depth);
        });
        EXPECT_NEAR(depth, nearest, 1e-14);
        ++perDepth[nearest];
        xs.insert(r.x());
        ys.insert(r.y());
    }
    EXPECT_EQ(perDepth.size(), 3u);
    for (const auto& [depth, count] : perDepth) EXPECT_EQ(count, 60) << "depth " << depth;
    ASSERT_EQ(xs.size(), 12u);
    ASSERT_EQ(ys.size(), 5u);
    const std::vector<double> xv(xs.begin(), xs.end()), yv(ys.begin(), ys.end());
    for (std::size_t k = 1; k < xv.size(); ++k) EXPECT_NEAR(xv[k] - xv[k - 1], 0.5, 1e-12);
    for (std::size_t k = 1; k < yv.size(); ++k) EXPECT_NEAR(yv[k] - yv[k - 1], 1.0, 1e-12);
    // An upper wall gets the same depths on the other side.
    const PlanarWallSettings up = wall({0, 0, 9}, {0, 0, -1}, "bounceBack");
    std::set<long> upDepths;
    for (const auto& r : frozenLattice(box, up, s)) upDepths.insert(std::lround((r.z() - 9.0) * 100));
    EXPECT_EQ(upDepths, (std::set<long>{15, 35, 75}));
}

TEST(FrozenLattice, StaggeredLayersSitInTheHollowsOfTheLayerInFront) {
    // Two layers at 0 (on the plane) and 0.5 behind z = 3, spacing 0.5 x 1 in a 6 x 5 box: staggered,
    // the second layer's x and y are the first's shifted by half a cell (0.25, 0.5); the first layer
    // and the count are those of the unstaggered wall.
    FrozenLatticeSettings s;
    s.lattice = "layers";
    s.layerDepths = {0.0, 0.5};
    s.layerSpacing = {0.5, 1.0};
    const Box box = box3(6.0, 5.0, 12.0);
    const PlanarWallSettings w = wall({0, 0, 3}, {0, 0, 1}, "bounceBack");
    const auto inRegister = frozenLattice(box, w, s);
    s.staggered = true;
    const auto staggered = frozenLattice(box, w, s);
    ASSERT_EQ(staggered.size(), 120u);
    ASSERT_EQ(inRegister.size(), 120u);
    // Lattice coordinates of each point, (x - lo) / spacing - 1/4 (addLayer's quarter-cell origin):
    // whole numbers in the front layer, whole numbers plus one half in the staggered one behind it.
    const auto fraction = [](double u) { return u - std::floor(u); };
    std::set<std::pair<long, long>> front, back;
    for (const auto& r : staggered) {
        const double depth = w.point.z() - r.z();
        EXPECT_TRUE(std::abs(depth) < 1e-14 || std::abs(depth - 0.5) < 1e-14) << "depth " << depth;
        const double u = (r.x() - box.lo.x()) / 0.5 - 0.25, v = (r.y() - box.lo.y()) / 1.0 - 0.25;
        const double expected = depth < 0.25 ? 0.0 : 0.5;
        EXPECT_NEAR(fraction(u + 0.25) - 0.25, expected, 1e-9) << "x " << r.x() << " depth " << depth;
        EXPECT_NEAR(fraction(v + 0.25) - 0.25, expected, 1e-9) << "y " << r.y() << " depth " << depth;
        (depth < 0.25 ? front : back).insert({std::lround(2 * u), std::lround(2 * v)});
    }
    EXPECT_EQ(front.size(), 60u);
    EXPECT_EQ(back.size(), 60u);
    for (std::size_t k = 0; k < 60; ++k) EXPECT_EQ(staggered[k], inRegister[k]);
}

TEST(FrozenLattice, RejectsImpossibleSettings) {
    const Box box = box3(6.0, 5.0, 12.0);
    FrozenLatticeSettings s;
    s.lattice = "layers";
    s.layerDepths = {0.15};
    s.layerSpacing = {0.5};  // a 3-D wall needs two spacings
    EXPECT_THROW(frozenLattice(box, wall({0, 0, 3}, {0, 0, 1}, "bounceBack"), s), std::invalid_argument);
    s.lattice = "fcc";
    PlanarWallSettings oblique = wall({0, 0, 3}, Eigen::Vector3d(1, 0, 1).normalized(), "bounceBack");
    EXPECT_THROW(frozenLattice(box, oblique, s), std::invalid_argument);
    s.lattice = "hexagonal";
    EXPECT_THROW(frozenLattice(box, wall({0, 0, 3}, {0, 0, 1}, "bounceBack"), s), std::invalid_argument);
    s.lattice = "layers";
    s.layerSpacing = {0.5, 1.0};
    s.layerDepths = {-0.1};  // in front of the wall, in the fluid
    EXPECT_THROW(frozenLattice(box, wall({0, 0, 3}, {0, 0, 1}, "bounceBack"), s), std::invalid_argument);
}
