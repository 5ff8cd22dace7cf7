// Bonds in snapshots (io/SnapshotBonds.hpp): written and read back exactly, with the particles' chain
// and the connectivity ParaView draws; a bond file that does not fit its particles is refused naming
// the file, dataset and row.
#include "core/Error.hpp"
#include "io/Hdf5File.hpp"
#include "io/Snapshot.hpp"
#include "io/SnapshotBonds.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;
using namespace dpd;

namespace {

class SnapshotBondsTest : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("dpdBonds-" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + "-" +
                std::to_string(::getpid()));
        fs::remove_all(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    // Four particles in a box 3 thick along y; particles 10-11-12 form chain 0, the bond 10-11 crossing
    // the y boundary (vector +2.2, minimum image -0.8); particle 13 is free.
    static Snapshot chain() {
        Snapshot s;
        s.box.lo = {0, -1.5, 0};
        s.box.hi = {6, 1.5, 6};
        s.speciesNames = {"fluid", "polymer"};
        s.speciesFrozen = {false, false};
        s.particles.add(12, 1, 1.5, 0.3, 2.0);
        s.particles.add(10, 1, 1.0, -1.2, 2.0);
        s.particles.add(13, 0, 4.0, 0.0, 4.0);
        s.particles.add(11, 1, 1.0, 1.0, 2.0);
        s.bonds.add(10, 11, 0, {0.0, 2.2, 0.0});
        s.bonds.add(11, 12, 0, {0.5, -0.7, 0.0});
        return s;
    }
    std::string write(const Snapshot& s) {
        writeSnapshot(dir_.string(), s);
        return (dir_ / snapshotFileName).string();
    }
    fs::path dir_;
};

std::string messageOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const IoError& e) {
        return e.what();
    }
    return "no IoError";
}

}  // namespace

TEST_F(SnapshotBondsTest, RoundTripsBondsExactlyWithChainsAndConnectivity) {
    const Snapshot s = chain();
    const std::string file = write(s);
    const Snapshot r = readSnapshot(file);
    ASSERT_EQ(r.bonds.size(), 2u);
    for (std::size_t k = 0; k < 2; ++k) {
        EXPECT_EQ(r.bonds.first[k], s.bonds.first[k]);
        EXPECT_EQ(r.bonds.second[k], s.bonds.second[k]);
        EXPECT_EQ(r.bonds.chain[k], 0);
        EXPECT_EQ(r.bonds.vector(k), s.bonds.vector(k));
    }
    const Hdf5Reader h5(file);
    EXPECT_EQ(h5.readInt64(particleChainName), (std::vector<std::int64_t>{0, 0, -1, 0}));
    // Rows of ids 10 and 11 are 1 and 3; of 11 and 12, 3 and 0.
    EXPECT_EQ(h5.readInt64(bondConnectivityName), (std::vector<std::int64_t>{1, 3, 3, 0}));
    std::ifstream xmf(dir_ / snapshotXdmfFileName);
    std::stringstream text;
    text << xmf.rdbuf();
    EXPECT_NE(text.str().find("TopologyType=\"Polyline\" NumberOfElements=\"2\" NodesPerElement=\"2\""), std::string::npos);
}

TEST_F(SnapshotBondsTest, ASnapshotWithoutBondsHasNoBondDatasets) {
    Snapshot s = chain();
    s.bonds = Bonds();
    const std::string file = write(s);
    EXPECT_FALSE(Hdf5Reader(file).has("bonds"));
    EXPECT_FALSE(Hdf5Reader(file).has(particleChainName));
    EXPECT_TRUE(readSnapshot(file).bonds.empty());
}

TEST_F(SnapshotBondsTest, RefusesBondsThatDoNotFitTheParticles) {
    Snapshot s = chain();
    s.bonds.by[0] = 2.3;  // does not join -1.2 and 1.0 up to whole box lengths
    std::string m = messageOf([&] { readSnapshot(write(s)); });
    EXPECT_NE(m.find("bonds/vector' row 0"), std::string::npos) << m;
    EXPECT_NE(m.find("does not join particles 10 and 11"), std::string::npos) << m;

    s = chain();
    s.bonds.add(12, 13, 1, {2.5, -0.3, 2.0});  // particle 12 in chains 0 and 1
    m = messageOf([&] { readSnapshot(write(s)); });
    EXPECT_NE(m.find("particle 12 is in chains 0 and 1"), std::string::npos) << m;

    s = chain();
    s.bonds.first[1] = 10;
    s.bonds.second[1] = 10;
    s.bonds.bx[1] = 0.0;
    s.bonds.by[1] = 0.0;
    m = messageOf([&] { readSnapshot(write(s)); });  // bonded to itself
    EXPECT_NE(m.find("joins particle 10 to itself"), std::string::npos) << m;
}

TEST_F(SnapshotBondsTest, WritingABondToAMissingParticleIsRefused) {
    Snapshot s = chain();
    s.bonds.second[1] = 99;
    EXPECT_THROW(write(s), std::invalid_argument);
}
