// blockFrozenWall's walls (setup/BlockFrozenWall.*): a lattice deeper than one cutoff is built to the
// published count but only its points within one cutoff of the fluid are frozen into the state, unless
// the wall lets the fluid in (reflection none).
#include "case/DpdProperties.hpp"
#include "io/Dictionary.hpp"
#include "setup/BlockFrozenWall.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using namespace dpd;

namespace {

// A channel of 6 x 3 between walls at z = -3 and 3, each with the given reflection.
DpdModel channel(const std::string& reflection) {
    const std::string rule = "reflection " + reflection + ";";
    return readDpdModel(Dictionary::parse(
        "dimension 3; kT 1; cutoff 1; seed 3;\n"
        "species { fluid { frozen no; } wall { frozen yes; } }\n"
        "pairCoeffs { fluid-fluid { a 18.75; gamma 4.5; } fluid-wall { a 18.75; gamma 4.5; } }\n"
        "walls { lower { type plane; point (0 0 -3); normal (0 0 1); " + rule + " }\n"
        "        upper { type plane; point (0 0 3); normal (0 0 -1); " + rule + " } }\n",
        "constant/dpdProperties"));
}

// An fcc wall at density 4 (lattice constant 1: planes 0.25, 0.75, 1.25 behind the wall in a
// thickness of 1.5, each with 2 points per unit area) in a box that holds 1.5 of solid a side.
BlockFrozenWallReport build(const DpdModel& model, Snapshot& snap) {
    const Dictionary d = Dictionary::parse(
        "box { min (-3 -1.5 -4.5); max (3 1.5 4.5); }\n"
        "fluid { species fluid; density 4; }\n"
        "wall { species wall; lattice fcc; density 4; thickness 1.5; }\n",
        "system/blockFrozenWallDict");
    BlockFrozenWallReport report;
    snap = buildBlockFrozenWall(d, model, report);
    return report;
}

std::size_t frozenDeeperThan(const Snapshot& snap, double depth) {
    std::size_t n = 0;
    for (std::size_t i = 0; i < snap.particles.size(); ++i)
        if (snap.particles.species[i] == 1 && std::abs(snap.particles.rz[i]) > 3.0 + depth) ++n;
    return n;
}

}  // namespace

TEST(BlockFrozenWall, LatticeBeyondOneCutoffIsCountedButNotFrozen) {
    Snapshot snap;
    const BlockFrozenWallReport r = build(channel("bounceLayer; alpha 0.1"), snap);
    ASSERT_EQ(r.latticePerWall.size(), 2u);
    for (int w = 0; w < 2; ++w) {
        EXPECT_EQ(r.latticePerWall[w], 6u * 3u * 6u);  // 3 planes x 2 per unit area x 18
        EXPECT_EQ(r.frozenPerWall[w], 6u * 3u * 4u);   // the planes at 0.25 and 0.75
    }
    EXPECT_EQ(frozenDeeperThan(snap, 1.0), 0u);
    EXPECT_EQ(snap.particles.size(), r.fluid + r.frozenPerWall[0] + r.frozenPerWall[1]);
}

TEST(BlockFrozenWall, WallThatLetsTheFluidInKeepsItsWholeLattice) {
    Snapshot snap;
    const BlockFrozenWallReport r = build(channel("none"), snap);
    for (int w = 0; w < 2; ++w) EXPECT_EQ(r.frozenPerWall[w], r.latticePerWall[w]);
    EXPECT_EQ(frozenDeeperThan(snap, 1.0), 2u * 6u * 3u * 2u);  // the plane at 1.25 of both walls
}
