// Slabs of cell planes per rank (parallel/SlabDecomposition.hpp): balanced cuts by hand for even and
// uneven weights, every rank at least its minimum of planes, owners of planes, and the refusals.
#include "parallel/SlabDecomposition.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

using namespace dpd;

TEST(SlabDecomposition, EvenWeightsCutEvenly) {
    const SlabDecomposition d = SlabDecomposition::balanced(std::vector<double>(12, 1.0), 4);
    ASSERT_EQ(d.ranks(), 4);
    for (int r = 0; r < 4; ++r) {
        EXPECT_EQ(d.first(r), 3 * r);
        EXPECT_EQ(d.end(r), 3 * r + 3);
    }
    EXPECT_EQ(d.describe(), "0-2 | 3-5 | 6-8 | 9-11");
}

TEST(SlabDecomposition, CutsFollowTheWeight) {
    // Twelve planes, the last four three times as heavy (a wall's or a denser region's planes): total
    // 8 + 12 = 20, half at 10, reached after plane 9 (8 + 2 x 3 = 14 > 10: the cut nearest 10 is
    // after plane 8, 8 + 3 = 11, against 8 alone: |10 - 8| = 2 > |11 - 10| = 1).
    std::vector<double> w(12, 1.0);
    for (int k = 8; k < 12; ++k) w[k] = 3.0;
    const SlabDecomposition d = SlabDecomposition::balanced(w, 2);
    EXPECT_EQ(d.first(1), 9);
    EXPECT_EQ(d.ownerOf(8), 0);
    EXPECT_EQ(d.ownerOf(9), 1);
    EXPECT_EQ(d.ownerOf(11), 1);
}

TEST(SlabDecomposition, EveryRankKeepsItsMinimum) {
    // All the weight in plane 0: balance alone would leave ranks empty; each keeps its minimum.
    std::vector<double> w(8, 0.0);
    w[0] = 100.0;
    const SlabDecomposition three = SlabDecomposition::balanced(w, 3);
    for (int r = 0; r < 3; ++r) EXPECT_GE(three.end(r) - three.first(r), 1) << r;
    const SlabDecomposition two = SlabDecomposition::balanced(w, 2);
    EXPECT_EQ(two.first(1), 2);  // two ranks: two planes each at least (ghost planes must differ)
}

TEST(SlabDecomposition, TooFewPlanesIsRefused) {
    try {
        SlabDecomposition::balanced(std::vector<double>(5, 1.0), 6);
        FAIL() << "no error";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("5 planes"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("6 ranks need at least 6"), std::string::npos) << e.what();
    }
    EXPECT_THROW(SlabDecomposition::balanced(std::vector<double>(3, 1.0), 2), std::invalid_argument);
    EXPECT_THROW(SlabDecomposition::fromCuts({0, 1, 12}), std::invalid_argument);  // 1 plane of 2 ranks
    EXPECT_THROW(SlabDecomposition::fromCuts({1, 6, 12}), std::invalid_argument);  // not from plane 0
    EXPECT_NO_THROW(SlabDecomposition::fromCuts({0, 1, 2, 12}));                   // 3 ranks: 1 plane is enough
}

// With chains a rank's ghosts reach as far as a bond (r_max over the cell width, rounded up, in whole
// planes), all from its neighbour on that side: each slab holds that many planes, and with two ranks
// twice as many (the one neighbour's slab gives both sides' ghost planes, which must not share one).
TEST(SlabDecomposition, SlabsHoldTheGhostPlanesABondReaches) {
    EXPECT_EQ(SlabDecomposition::ghostPlanesFor(1.0, 1.0), 1);
    EXPECT_EQ(SlabDecomposition::ghostPlanesFor(1.0, 1.25), 1);
    EXPECT_EQ(SlabDecomposition::ghostPlanesFor(3.0, 1.0), 3);
    EXPECT_EQ(SlabDecomposition::ghostPlanesFor(3.0, 1.03), 3);
    EXPECT_EQ(SlabDecomposition::ghostPlanesFor(3.1, 1.0), 4);
    EXPECT_THROW(SlabDecomposition::fromCuts({0, 5, 30}, 3), std::invalid_argument);
    EXPECT_NO_THROW(SlabDecomposition::fromCuts({0, 6, 30}, 3));
    EXPECT_THROW(SlabDecomposition::fromCuts({0, 2, 5, 30}, 3), std::invalid_argument);
    EXPECT_EQ(SlabDecomposition::fromCuts({0, 3, 6, 30}, 3).ghostPlanes(), 3);
    // Balanced cuts keep to it however the weight lies.
    std::vector<double> w(30, 1.0);
    w[0] = 100.0;
    const SlabDecomposition two = SlabDecomposition::balanced(w, 2, 3);
    EXPECT_EQ(two.first(1), 6);
    const SlabDecomposition five = SlabDecomposition::balanced(w, 5, 3);
    for (int r = 0; r < 5; ++r) EXPECT_GE(five.end(r) - five.first(r), 3) << r;
    try {
        SlabDecomposition::balanced(std::vector<double>(11, 1.0), 2, 3);
        FAIL() << "no error";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("2 ranks need at least 12 (3 ghost planes a side"), std::string::npos) << e.what();
    }
}
