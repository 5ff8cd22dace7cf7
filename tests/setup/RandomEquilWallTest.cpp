// randomEquilWall (setup/RandomEquilWall) on a small channel mask, and the percolation check
// (geometry/Percolation) it relies on.
#include "../geometry/GeometryTestFiles.hpp"

#include "../support/InputErrorOf.hpp"
#include "core/Error.hpp"
#include "geometry/GeometryDictionary.hpp"
#include "geometry/Percolation.hpp"
#include "setup/RandomEquilWall.hpp"
#include "io/Dictionary.hpp"
#include "case/DpdProperties.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace dpd;
using namespace geometryTest;

namespace {

// 3-D box x 0..8, y 0..3, z 0..8; a 16 x 16 mask of 0.5 pixels extruded along y whose top and
// bottom three rows are solid: walls 1.5 thick at z < 1.5 and z > 6.5 (so the solid is 3 thick
// across the periodic boundary and its middle lies deeper than one cutoff).
Picture channel(int solidRows) { return channelPicture(16, solidRows); }

std::string properties(const std::string& extra) {
    return "dimension 3; kT 1; seed 5;\n"
           "species { fluid { frozen no; } wall { frozen yes; } }\n"
           "pairCoeffs { fluid-fluid { a 18.75; gamma 4.5; } fluid-wall { a 18.75; gamma 4.5; } }\n"
           "bodyForce { type uniform; value (0.02 0 0); }\n"
           "geometry { type imageMask; file \"constant/geometry/mask.pgm\"; solidValues (0); pixelSize 0.5; }\n" + extra;
}

const char* equilDict = "box { min (0 0 0); max (8 3 8); }\nfluid { species fluid; density 4; }\nwall { species wall; }\n"
                        "equilibration { time 2; deltaT 0.02; }\n";

class RandomEquilWall : public ScratchDirectory {
protected:
    Snapshot build(const Picture& mask, const std::string& dict, RandomEquilWallReport& report,
                   const std::string& extraProperties = "") {
        writePgm(path("constant/geometry/mask.pgm"), mask);
        const Dictionary props = Dictionary::parse(properties(extraProperties), path("constant/dpdProperties"));
        const Dictionary d = Dictionary::parse(dict, path("system/randomEquilWallDict"));
        return buildRandomEquilWall(d, props, readDpdModel(props), dir_.string(), report);
    }
    std::string error(const Picture& mask, const std::string& dict) {
        RandomEquilWallReport r;
        return test::inputErrorOf([&] { build(mask, dict, r); });
    }
};

TEST_F(RandomEquilWall, ChannelCountsPorosityAndFrozenDensity) {
    RandomEquilWallReport r;
    const Snapshot s = build(channel(3), equilDict, r);
    const double density = 4.0, lx = 8.0, ly = 3.0;
    EXPECT_EQ(r.filled, static_cast<std::size_t>(density * 8 * 3 * 8));
    EXPECT_EQ(r.fluid + r.frozen + r.dropped, r.filled);
    EXPECT_EQ(s.particles.size(), r.fluid + r.frozen);
    EXPECT_DOUBLE_EQ(r.gridPorosity, 5.0 / 8.0);   // the fluid is 1.5 < z < 6.5
    // The instantaneous kT of the 768 particles scatters by sqrt(2 / (3 N)) = 0.030 about 1 (the random
    // start's excess heat is gone within the 2 time units of equilibration: the thermostat relaxes it
    // in ~0.2); 4 of those, 0.12. NaN fails.
    const double kTScatter = std::sqrt(2.0 / (3.0 * static_cast<double>(r.filled)));
    EXPECT_TRUE(std::abs(r.equilibratedKT - 1.0) <= 4.0 * kTScatter) << "kT " << r.equilibratedKT;
    std::printf("    equilibrated kT %.4f (scatter %.4f)\n", r.equilibratedKT, kTScatter);
    // Counts in a region of volume V of the uniform equilibrated fluid: mean density x V, with at most
    // Poisson scatter sqrt(mean) (a DPD liquid is less compressible than an ideal gas, so its number
    // fluctuations are smaller); 4 standard deviations.
    const double fluidMean = density * lx * ly * 5.0, frozenMean = density * lx * ly * 2.0 * 1.0;
    EXPECT_NEAR(static_cast<double>(r.fluid), fluidMean, 4.0 * std::sqrt(fluidMean));
    EXPECT_NEAR(static_cast<double>(r.frozen), frozenMean, 4.0 * std::sqrt(frozenMean));
    EXPECT_NEAR(r.particlePorosity, 5.0 / 8.0, 4.0 * std::sqrt(fluidMean) / r.filled);
    // Every particle where it belongs: fluid in the channel, frozen within one cutoff of it, ids
    // 0..N-1 with the fluid first, frozen particles at rest, no net fluid momentum.
    Eigen::Vector3d momentum(0, 0, 0);
    for (std::size_t i = 0; i < s.particles.size(); ++i) {
        const double z = s.particles.rz[i];
        EXPECT_EQ(s.particles.id[i], i);
        if (s.speciesNames[s.particles.species[i]] == "fluid") {
            ASSERT_LT(i, r.fluid);
            EXPECT_TRUE(z >= 1.5 && z <= 6.5) << z;
            momentum += Eigen::Vector3d(s.particles.vx[i], s.particles.vy[i], s.particles.vz[i]);
        } else {
            ASSERT_GE(i, r.fluid);
            const double depth = z < 1.5 ? 1.5 - z : z - 6.5;
            EXPECT_TRUE(depth >= 0.0 && depth <= 1.0) << z;
            EXPECT_EQ(s.particles.vx[i], 0.0);
        }
    }
    EXPECT_LT(momentum.norm(), 1e-9);
}

// A wall thickness (a published wall's depth) counts the solid particles within it of the fluid and
// changes nothing else: the same particles are frozen and dropped, to the bit.
TEST_F(RandomEquilWall, AWallThicknessCountsTheSolidWithinItAndKeepsTheSameParticles) {
    const auto withThickness = [](const std::string& t) {
        std::string d = equilDict;
        const std::string plainWall = "wall { species wall; }";
        return d.replace(d.find(plainWall), plainWall.size(), "wall { species wall; thickness " + t + "; }");
    };
    RandomEquilWallReport plain, thick, whole;
    const Snapshot a = build(channel(3), equilDict, plain);
    const Snapshot b = build(channel(3), withThickness("1.2"), thick);
    EXPECT_EQ(plain.withinThickness, 0u);
    EXPECT_DOUBLE_EQ(thick.thickness, 1.2);
    EXPECT_EQ(thick.frozen, plain.frozen);
    EXPECT_EQ(thick.dropped, plain.dropped);
    ASSERT_EQ(b.particles.size(), a.particles.size());
    for (std::size_t i = 0; i < a.particles.size(); ++i) {
        ASSERT_EQ(b.particles.rz[i], a.particles.rz[i]) << i;
        ASSERT_EQ(b.particles.species[i], a.particles.species[i]) << i;
    }
    // The solid within 1.2 of the fluid: both walls' layers 1.2 deep, a Poisson count about the
    // density x volume (4 standard deviations), more than the frozen layers 1 deep hold.
    const double mean = 4.0 * 8.0 * 3.0 * 2.0 * 1.2;
    EXPECT_NEAR(static_cast<double>(thick.withinThickness), mean, 4.0 * std::sqrt(mean));
    EXPECT_GT(thick.withinThickness, thick.frozen);
    // The walls are 1.5 deep: a thickness of 1.5 holds the whole solid.
    build(channel(3), withThickness("1.5"), whole);
    EXPECT_EQ(whole.withinThickness, whole.frozen + whole.dropped);
    EXPECT_NE(error(channel(3), withThickness("-1")).find("keyword 'thickness'"), std::string::npos);
}

TEST_F(RandomEquilWall, RefusesAllSolidAllFluidAndBlockedGeometries) {
    Picture allSolid(16, std::vector<int>(16, 0)), allFluid(16, std::vector<int>(16, 255));
    std::string e = error(allSolid, equilDict);
    EXPECT_NE(e.find("constant/dpdProperties"), std::string::npos) << e;
    EXPECT_NE(e.find("keyword 'file'"), std::string::npos) << e;
    EXPECT_NE(e.find("has no fluid"), std::string::npos) << e;
    EXPECT_NE(error(allFluid, equilDict).find("has no solid"), std::string::npos);
    // A channel along x blocked by a solid column: the body force along x cannot drive a flow.
    Picture blocked = channel(3);
    for (int r = 0; r < 16; ++r) blocked[r][7] = blocked[r][8] = blocked[r][9] = 0;
    e = error(blocked, equilDict);
    EXPECT_NE(e.find("does not percolate along x"), std::string::npos) << e;
    // Along z the channel is closed by its walls: asked for by drivingAxis, it is refused there.
    e = error(channel(3), std::string(equilDict) + "drivingAxis z;");
    EXPECT_NE(e.find("randomEquilWallDict"), std::string::npos) << e;
    EXPECT_NE(e.find("keyword 'drivingAxis'"), std::string::npos) << e;
}

// Percolation on hand-made flags: face connection across the periodic box counts, a corner does not.
TEST_F(RandomEquilWall, PercolationNeedsAFaceConnectedPathAcrossThePeriodicBox) {
    Box box;
    box.dimension = 2;
    box.lo = Eigen::Vector3d(0, -0.5, 0);
    box.hi = Eigen::Vector3d(8, 0.5, 8);
    const auto flagsOf = [&](const Picture& pic) {
        writePgm(path("p.pgm"), pic);
        const SolidGeometry g = readGeometry(
            Dictionary::parse("type imageMask; file \"" + path("p.pgm") + "\"; solidValues (0); pixelSize 1; smooth no;", "d"), "", box, 1.0);
        return SolidFlags(BackgroundGrid::covering(box, 1.0, g.uniformAxis()), g);
    };
    Picture pic(8, std::vector<int>(8, 0));
    for (int c = 0; c < 8; ++c) pic[3][c] = 255;   // one open row: a channel along x
    EXPECT_TRUE(fluidPercolates(flagsOf(pic), 0));
    EXPECT_FALSE(fluidPercolates(flagsOf(pic), 2));
    Picture diagonal(8, std::vector<int>(8, 0));
    for (int k = 0; k < 8; ++k) diagonal[k][k] = 255;   // cells touching only at corners
    EXPECT_FALSE(fluidPercolates(flagsOf(diagonal), 0));
    for (int k = 0; k < 8; ++k) diagonal[k][(k + 1) % 8] = 255;   // a staircase joined by faces
    EXPECT_TRUE(fluidPercolates(flagsOf(diagonal), 0));
    EXPECT_TRUE(fluidPercolates(flagsOf(diagonal), 2));
}

// With initialFlow the fluid starts in the laminar profile between the given walls: the thermal
// velocities keep zero mean, so the velocities less the profile sum to zero exactly (not a
// statistical statement), and the frozen wall stays at rest.
TEST_F(RandomEquilWall, InitialFlowAddsTheLaminarProfileToTheFluid) {
    RandomEquilWallReport r;
    const std::string dict = "box { min (0 0 0); max (8 3 8); }\n"
                             "fluid { species fluid; density 4; initialFlow { type poiseuille; nu 0.25; axis z; "
                             "wallPositions (1.5 6.5); } }\nwall { species wall; }\nequilibration { time 2; deltaT 0.02; }\n";
    const Snapshot s = build(channel(3), dict, r);
    double residual = 0.0, profileMomentum = 0.0;
    for (std::size_t i = 0; i < s.particles.size(); ++i) {
        const double z = s.particles.rz[i];
        const double u = 0.02 * (z - 1.5) * (6.5 - z) / (2.0 * 0.25);
        if (i < r.fluid) {
            residual += s.particles.vx[i] - u;
            profileMomentum += u;
        } else {
            EXPECT_EQ(s.particles.vx[i], 0.0);
        }
    }
    EXPECT_GT(profileMomentum / r.fluid, 0.1);  // mean of the parabola: 2/3 of its peak 0.25
    EXPECT_LT(std::abs(residual), 1e-9);
    EXPECT_NE(error(channel(3), std::string(equilDict).replace(std::string(equilDict).find("density 4;"), 10,
                                                                "density 4; initialFlow { type poiseuille; }"))
                  .find("wallPositions"),
              std::string::npos);
}

}  // namespace
