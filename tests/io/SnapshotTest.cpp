#include "io/Snapshot.hpp"

#include "core/Error.hpp"
#include "io/Hdf5File.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <random>
#include <sstream>

namespace fs = std::filesystem;

namespace {

// Every test gets its own directory: ctest runs test processes in parallel.
class TemporaryDirectoryTest : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = fs::temp_directory_path() /
               ("dpdIo-" + std::string(info->test_suite_name()) + "-" + info->name() + "-" +
                std::to_string(::getpid()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }
    std::vector<std::string> entries(const fs::path& d) const {
        std::vector<std::string> names;
        for (const auto& e : fs::directory_iterator(d)) names.push_back(e.path().filename().string());
        std::sort(names.begin(), names.end());
        return names;
    }

    fs::path dir_;
};

class Hdf5Test : public TemporaryDirectoryTest {};
class SnapshotTest : public TemporaryDirectoryTest {};

// Expects an IoError whose message contains every one of the given fragments.
template <class F>
void expectIoError(F&& f, const std::vector<std::string>& fragments) {
    try {
        f();
        ADD_FAILURE() << "no IoError thrown";
    } catch (const dpd::IoError& e) {
        for (const auto& fragment : fragments)
            EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos)
                << "message '" << e.what() << "' lacks '" << fragment << "'";
    }
}

template <class T, class Allocator>
bool bitIdentical(const std::vector<T, Allocator>& a, const std::vector<T, Allocator>& b) {
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

dpd::Snapshot randomSnapshot(std::size_t n, int dimension, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> uniform(-1e3, 1e3);
    dpd::Snapshot s;
    s.box.dimension = dimension;
    s.box.lo = {-1.5, 0.0, 2.25};
    s.box.hi = {10.0, dimension == 3 ? 7.0 : 1.0, 12.125};
    s.speciesNames = {"fluid", "wall", "polymer"};
    s.speciesFrozen = {false, true, false};
    s.time = 0.1 + 0.2;  // not representable exactly in decimal: must survive bit for bit
    s.step = 123456789012LL;
    auto& p = s.particles;
    // Positions within half a box length of the box (a snapshot may hold unwrapped ones; the reader
    // refuses those more than a box length out).
    const auto near = [&](int a) {
        const double l = s.box.hi[a] - s.box.lo[a];
        return std::uniform_real_distribution<double>(s.box.lo[a] - 0.5 * l, s.box.hi[a] + 0.5 * l)(rng);
    };
    for (std::size_t i = 0; i < n; ++i) {
        const double x = near(0);
        const double y = dimension == 3 ? near(1) : 0.0;
        const double z = near(2);
        p.add(rng(), static_cast<int>(rng() % 3), x, y, z, uniform(rng),
              dimension == 3 ? uniform(rng) : 0.0, uniform(rng));
        p.fx.back() = uniform(rng);
        p.fy.back() = dimension == 3 ? uniform(rng) : 0.0;
        p.fz.back() = uniform(rng);
    }
    if (n >= 4) {  // awkward values that a text format or a conversion would mangle
        p.rx[0] = -0.0;
        p.vx[1] = std::numeric_limits<double>::denorm_min();
        p.fz[2] = std::numeric_limits<double>::max();
        p.id[3] = std::numeric_limits<std::uint64_t>::max();
    }
    return s;
}

void expectSameSnapshot(const dpd::Snapshot& a, const dpd::Snapshot& b) {
    EXPECT_EQ(a.box.dimension, b.box.dimension);
    EXPECT_EQ(a.box.lo, b.box.lo);
    EXPECT_EQ(a.box.hi, b.box.hi);
    EXPECT_EQ(a.speciesNames, b.speciesNames);
    EXPECT_EQ(a.speciesFrozen, b.speciesFrozen);
    EXPECT_EQ(a.time, b.time);
    EXPECT_EQ(a.step, b.step);
    const auto& p = a.particles;
    const auto& q = b.particles;
    ASSERT_EQ(p.size(), q.size());
    EXPECT_TRUE(bitIdentical(p.rx, q.rx) && bitIdentical(p.ry, q.ry) && bitIdentical(p.rz, q.rz));
    EXPECT_TRUE(bitIdentical(p.vx, q.vx) && bitIdentical(p.vy, q.vy) && bitIdentical(p.vz, q.vz));
    EXPECT_TRUE(bitIdentical(p.fx, q.fx) && bitIdentical(p.fy, q.fy) && bitIdentical(p.fz, q.fz));
    EXPECT_EQ(p.id, q.id);
    EXPECT_EQ(p.species, q.species);
}

// Edits a written file behind the library's back, to build malformed snapshots.
void replaceDataset(const std::string& file, const std::string& name, hid_t type, const void* data,
                    const std::vector<hsize_t>& dims) {
    dpd::Hdf5Handle f(H5Fopen(file.c_str(), H5F_ACC_RDWR, H5P_DEFAULT), H5Fclose);
    ASSERT_TRUE(f.valid());
    H5Ldelete(f.get(), name.c_str(), H5P_DEFAULT);
    if (!data) return;
    dpd::Hdf5Handle space(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr), H5Sclose);
    dpd::Hdf5Handle d(H5Dcreate2(f.get(), name.c_str(), type, space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                      H5Dclose);
    ASSERT_TRUE(d.valid());
    ASSERT_GE(H5Dwrite(d.get(), type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), 0);
}

std::string readText(const std::string& file) {
    std::ifstream in(file);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

}  // namespace

// ----------------------------------------------------------------------------------- Hdf5 --

TEST_F(Hdf5Test, RoundTripsDatasetsOfEveryTypeWithShapes) {
    const std::string file = path("a.h5");
    {
        dpd::Hdf5Writer w(file);
        w.writeDoubles("fields/deep/u", {1.0, 2.0, 3.0, 4.0, 5.0, 6.0}, {2, 3});
        w.writeUInt64("ids", {0, 1, std::numeric_limits<std::uint64_t>::max()});
        w.writeInt64("big", {-5, std::numeric_limits<std::int64_t>::min()});
        w.writeInt32("small", {-7, 8});
        w.writeUInt8("bytes", {0, 255});
        w.writeDoubles("empty", {}, {0, 3});
        w.commit();
    }
    dpd::Hdf5Reader r(file);
    std::vector<hsize_t> dims;
    EXPECT_EQ(r.readDoubles("fields/deep/u", &dims), (std::vector<double>{1, 2, 3, 4, 5, 6}));
    EXPECT_EQ(dims, (std::vector<hsize_t>{2, 3}));
    EXPECT_EQ(r.readUInt64("ids"), (std::vector<std::uint64_t>{0, 1, std::numeric_limits<std::uint64_t>::max()}));
    EXPECT_EQ(r.readInt64("big"), (std::vector<std::int64_t>{-5, std::numeric_limits<std::int64_t>::min()}));
    EXPECT_EQ(r.readInt32("small"), (std::vector<std::int32_t>{-7, 8}));
    EXPECT_EQ(r.readUInt8("bytes"), (std::vector<std::uint8_t>{0, 255}));
    EXPECT_TRUE(r.readDoubles("empty", &dims).empty());
    EXPECT_EQ(dims, (std::vector<hsize_t>{0, 3}));
    EXPECT_EQ(r.readDoubles("small"), (std::vector<double>{-7.0, 8.0}));  // integers widen to doubles
}

TEST_F(Hdf5Test, RoundTripsAttributesOnRootAndGroups) {
    const std::string file = path("a.h5");
    {
        dpd::Hdf5Writer w(file);
        w.writeDoubles("g/x", {1.0});
        w.writeAttribute("/", "time", 2.5);
        w.writeAttribute("/", "step", std::int64_t{-42});
        w.writeAttribute("/", "count", 7);
        w.writeAttribute("/", "name", "caf\xc3\xa9 box");
        w.writeAttribute("/", "lo", std::vector<double>{0.0, -1.0, 2.0});
        w.writeAttribute("/", "flags", std::vector<std::int64_t>{1, 0});
        w.writeAttribute("/", "names", std::vector<std::string>{"A", "", "long name"});
        w.writeAttribute("/", "none", std::vector<std::string>{});
        w.writeAttribute("g", "unit", "m/s");
        w.writeAttribute("g/x", "scale", 3.0);
        w.writeAttribute("/", "time", 3.5);  // rewriting replaces
        w.commit();
    }
    dpd::Hdf5Reader r(file);
    EXPECT_EQ(r.attributeDouble("/", "time"), 3.5);
    EXPECT_EQ(r.attributeInt("/", "step"), -42);
    EXPECT_EQ(r.attributeInt("/", "count"), 7);
    EXPECT_EQ(r.attributeDouble("/", "count"), 7.0);
    EXPECT_EQ(r.attributeString("/", "name"), "caf\xc3\xa9 box");
    EXPECT_EQ(r.attributeDoubles("/", "lo"), (std::vector<double>{0.0, -1.0, 2.0}));
    EXPECT_EQ(r.attributeInts("/", "flags"), (std::vector<std::int64_t>{1, 0}));
    EXPECT_EQ(r.attributeStrings("/", "names"), (std::vector<std::string>{"A", "", "long name"}));
    EXPECT_TRUE(r.attributeStrings("/", "none").empty());
    EXPECT_EQ(r.attributeString("g", "unit"), "m/s");
    EXPECT_EQ(r.attributeDouble("g/x", "scale"), 3.0);
    EXPECT_TRUE(r.hasAttribute("/", "time"));
    EXPECT_FALSE(r.hasAttribute("/", "nothing"));
    EXPECT_FALSE(r.hasAttribute("nowhere", "time"));
}

TEST_F(Hdf5Test, ReadsFixedLengthStringAttributes) {
    // Files from other tools (h5py with numpy bytes, Fortran codes) use fixed-length strings.
    const std::string file = path("fixed.h5");
    {
        dpd::Hdf5Handle f(H5Fcreate(file.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
        dpd::Hdf5Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
        H5Tset_size(type.get(), 6);
        H5Tset_strpad(type.get(), H5T_STR_NULLPAD);
        const hsize_t n = 2;
        dpd::Hdf5Handle space(H5Screate_simple(1, &n, nullptr), H5Sclose);
        dpd::Hdf5Handle a(H5Acreate2(f.get(), "names", type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
        const char data[12] = {'w', 'a', 'l', 'l', 0, 0, 'f', 'l', 'u', 'i', 'd', 's'};
        ASSERT_GE(H5Awrite(a.get(), type.get(), data), 0);
        dpd::Hdf5Handle padded(H5Tcopy(type.get()), H5Tclose);
        H5Tset_strpad(padded.get(), H5T_STR_SPACEPAD);
        dpd::Hdf5Handle scalar(H5Screate(H5S_SCALAR), H5Sclose);
        dpd::Hdf5Handle b(H5Acreate2(f.get(), "one", padded.get(), scalar.get(), H5P_DEFAULT, H5P_DEFAULT),
                          H5Aclose);
        ASSERT_GE(H5Awrite(b.get(), padded.get(), "ab    "), 0);
    }
    dpd::Hdf5Reader r(file);
    EXPECT_EQ(r.attributeStrings("/", "names"), (std::vector<std::string>{"wall", "fluids"}));
    EXPECT_EQ(r.attributeString("/", "one"), "ab");
}

TEST_F(Hdf5Test, CommitLeavesOnlyTheFinalFile) {
    dpd::Hdf5Writer w(path("out.h5"));
    w.writeDoubles("x", {1.0});
    EXPECT_TRUE(fs::exists(w.temporaryPath()));
    EXPECT_FALSE(fs::exists(path("out.h5")));  // readers never see the file being filled
    w.commit();
    EXPECT_EQ(entries(dir_), std::vector<std::string>{"out.h5"});
    EXPECT_THROW(w.writeDoubles("y", {1.0}), dpd::IoError);
}

TEST_F(Hdf5Test, CommitReplacesAnExistingFile) {
    for (double value : {1.0, 2.0}) {
        dpd::Hdf5Writer w(path("out.h5"));
        w.writeDoubles("x", {value});
        w.commit();
    }
    EXPECT_EQ(dpd::Hdf5Reader(path("out.h5")).readDoubles("x"), std::vector<double>{2.0});
    EXPECT_EQ(entries(dir_), std::vector<std::string>{"out.h5"});
}

TEST_F(Hdf5Test, WriterDestroyedWithoutCommitLeavesNothing) {
    {
        dpd::Hdf5Writer w(path("out.h5"));
        w.writeDoubles("x", {1.0, 2.0});
    }
    EXPECT_TRUE(entries(dir_).empty());
}

TEST_F(Hdf5Test, WriterRejectsShapeNotMatchingData) {
    dpd::Hdf5Writer w(path("out.h5"));
    EXPECT_THROW(w.writeDoubles("x", {1.0, 2.0, 3.0}, {2, 2}), std::invalid_argument);
}

TEST_F(Hdf5Test, WriterInMissingDirectoryThrowsIoError) {
    expectIoError([&] { dpd::Hdf5Writer w(path("no/such/dir/out.h5")); }, {"no/such/dir/out.h5"});
}

TEST_F(Hdf5Test, AttributeOnMissingObjectThrowsIoError) {
    dpd::Hdf5Writer w(path("out.h5"));
    expectIoError([&] { w.writeAttribute("nowhere", "a", 1.0); }, {"out.h5", "nowhere", "'a'"});
}

TEST_F(Hdf5Test, MissingFileThrowsIoErrorNamingIt) {
    expectIoError([&] { dpd::Hdf5Reader r(path("missing.h5")); }, {"missing.h5"});
}

TEST_F(Hdf5Test, NonHdf5FileThrowsIoError) {
    std::ofstream(path("text.h5")) << "not hdf5\n";
    expectIoError([&] { dpd::Hdf5Reader r(path("text.h5")); }, {"text.h5"});
}

TEST_F(Hdf5Test, MissingDatasetAndAttributeThrowIoErrorNamingThem) {
    {
        dpd::Hdf5Writer w(path("a.h5"));
        w.writeDoubles("g/x", {1.0});
        w.commit();
    }
    dpd::Hdf5Reader r(path("a.h5"));
    expectIoError([&] { r.readDoubles("g/y"); }, {"a.h5", "no dataset 'g/y'"});
    expectIoError([&] { r.readDoubles("h/deeper/y"); }, {"a.h5", "no dataset 'h/deeper/y'"});
    expectIoError([&] { r.readDoubles("g"); }, {"a.h5", "'g'"});  // a group, not a dataset
    expectIoError([&] { r.attributeDouble("/", "time"); }, {"a.h5", "no attribute 'time'"});
    expectIoError([&] { r.attributeString("g/x", "unit"); }, {"a.h5", "'unit'", "g/x"});
}

TEST_F(Hdf5Test, WrongTypesThrowIoError) {
    {
        dpd::Hdf5Writer w(path("a.h5"));
        w.writeDoubles("x", {1.5});
        w.writeAttribute("/", "s", "text");
        w.writeAttribute("/", "v", std::vector<double>{1.0, 2.0});
        w.commit();
    }
    dpd::Hdf5Reader r(path("a.h5"));
    expectIoError([&] { r.readInt32("x"); }, {"a.h5", "'x'"});  // would truncate
    expectIoError([&] { r.attributeDouble("/", "s"); }, {"a.h5", "'s'"});
    expectIoError([&] { r.attributeStrings("/", "v"); }, {"a.h5", "'v'"});
    expectIoError([&] { r.attributeDouble("/", "v"); }, {"a.h5", "'v'", "2 values"});
}

TEST_F(Hdf5Test, HasFollowsNestedPaths) {
    {
        dpd::Hdf5Writer w(path("a.h5"));
        w.writeDoubles("a/b/c", {1.0});
        w.commit();
    }
    dpd::Hdf5Reader r(path("a.h5"));
    EXPECT_TRUE(r.has("/"));
    EXPECT_TRUE(r.has("a"));
    EXPECT_TRUE(r.has("a/b"));
    EXPECT_TRUE(r.has("a/b/c"));
    EXPECT_TRUE(r.has("/a/b/c"));
    EXPECT_FALSE(r.has("a/c"));
    EXPECT_FALSE(r.has("x/y/z"));
    EXPECT_FALSE(r.has("a/b/c/d"));
}

// ------------------------------------------------------------------------------- Snapshot --

TEST_F(SnapshotTest, RoundTripIsBitExactIn3D) {
    const dpd::Snapshot s = randomSnapshot(357, 3, 1);
    dpd::writeSnapshot(path("0.5"), s);
    expectSameSnapshot(s, dpd::readSnapshot(path("0.5/particles.h5")));
}

TEST_F(SnapshotTest, RoundTripIn2DKeepsDimensionAndFlatY) {
    const dpd::Snapshot s = randomSnapshot(256, 2, 2);
    dpd::writeSnapshot(path("1"), s);
    const dpd::Snapshot back = dpd::readSnapshot(path("1/particles.h5"));
    expectSameSnapshot(s, back);
    EXPECT_EQ(back.box.dimension, 2);
    for (std::size_t i = 0; i < back.particles.size(); ++i) ASSERT_EQ(back.particles.ry[i], 0.0);
}

TEST_F(SnapshotTest, EmptySnapshotRoundTrips) {
    dpd::Snapshot s;
    s.speciesNames = {"A"};
    s.time = 4.0;
    dpd::writeSnapshot(path("4"), s);
    const dpd::Snapshot back = dpd::readSnapshot(path("4/particles.h5"));
    EXPECT_EQ(back.particles.size(), 0u);
    EXPECT_EQ(back.speciesFrozen, std::vector<bool>{false});  // empty speciesFrozen means none frozen
    EXPECT_EQ(back.time, 4.0);
}

TEST_F(SnapshotTest, FileLayoutMatchesTheDocumentation) {
    const dpd::Snapshot s = randomSnapshot(300, 3, 3);
    dpd::writeSnapshot(path("2"), s);
    dpd::Hdf5Reader r(path("2/particles.h5"));
    std::vector<hsize_t> dims;
    for (const char* name : {"particles/position", "particles/velocity", "particles/force"}) {
        r.readDoubles(name, &dims);
        EXPECT_EQ(dims, (std::vector<hsize_t>{300, 3})) << name;
    }
    const std::vector<double> position = r.readDoubles("particles/position");
    EXPECT_EQ(position[3 * 5 + 2], s.particles.rz[5]);  // rows are (x, y, z)
    r.readUInt64("particles/id", &dims);
    EXPECT_EQ(dims, std::vector<hsize_t>{300});
    r.readInt32("particles/species", &dims);
    EXPECT_EQ(dims, std::vector<hsize_t>{300});
    EXPECT_EQ(r.attributeString("/", "format"), "dpdFoamLike-snapshot-1");
    EXPECT_EQ(r.attributeDouble("/", "time"), s.time);
    EXPECT_EQ(r.attributeInt("/", "step"), s.step);
    EXPECT_EQ(r.attributeInt("/", "dimension"), 3);
    EXPECT_EQ(r.attributeDoubles("/", "boxLo"), (std::vector<double>{-1.5, 0.0, 2.25}));
    EXPECT_EQ(r.attributeDoubles("/", "boxHi"), (std::vector<double>{10.0, 7.0, 12.125}));
    EXPECT_EQ(r.attributeStrings("/", "speciesNames"), (std::vector<std::string>{"fluid", "wall", "polymer"}));
    EXPECT_EQ(r.attributeInts("/", "speciesFrozen"), (std::vector<std::int64_t>{0, 1, 0}));
}

TEST_F(SnapshotTest, XdmfCompanionReferencesTheH5ByRelativeName) {
    dpd::writeSnapshot(path("0.25"), randomSnapshot(200, 3, 4));
    const std::string xmf = readText(path("0.25/particles.xmf"));
    ASSERT_FALSE(xmf.empty());
    EXPECT_NE(xmf.find("TopologyType=\"Polyvertex\""), std::string::npos);
    EXPECT_NE(xmf.find("NumberOfElements=\"200\""), std::string::npos);
    EXPECT_NE(xmf.find("GeometryType=\"XYZ\""), std::string::npos);
    EXPECT_NE(xmf.find("<Time Value=\"0.30000000000000004\"/>"), std::string::npos);  // shortest exact text
    for (const char* dataset : {"position", "velocity", "force", "species", "id"})
        EXPECT_NE(xmf.find(std::string(">particles.h5:/particles/") + dataset + "<"), std::string::npos) << dataset;
    EXPECT_NE(xmf.find(">particles.h5:/xdmf/connectivity<"), std::string::npos);
    EXPECT_EQ(xmf.find(dir_.string()), std::string::npos);  // no absolute path: the case can move
    EXPECT_NE(xmf.find("Name=\"velocity\" AttributeType=\"Vector\""), std::string::npos);
    EXPECT_NE(xmf.find("Name=\"species\" AttributeType=\"Scalar\""), std::string::npos);
    // every dataset the XDMF names exists in the HDF5 file
    dpd::Hdf5Reader r(path("0.25/particles.h5"));
    const std::string prefix = "particles.h5:/";
    for (std::size_t at = xmf.find(prefix); at != std::string::npos; at = xmf.find(prefix, at + 1)) {
        const std::size_t begin = at + prefix.size();
        const std::string dataset = xmf.substr(begin, xmf.find('<', begin) - begin);
        EXPECT_TRUE(r.has(dataset)) << dataset;
    }
}

TEST_F(SnapshotTest, LeavesNoTemporaryFilesAndCreatesNestedTimeDirectory) {
    const std::string timeDir = path("case/0.75");
    dpd::writeSnapshot(timeDir, randomSnapshot(50, 3, 5));
    dpd::writeSnapshot(timeDir, randomSnapshot(60, 3, 6));  // overwriting is fine too
    EXPECT_EQ(entries(timeDir), (std::vector<std::string>{"particles.h5", "particles.xmf"}));
    EXPECT_EQ(dpd::readSnapshot(timeDir + "/particles.h5").particles.size(), 60u);
}

TEST_F(SnapshotTest, InconsistentSnapshotIsRejectedBeforeWriting) {
    dpd::Snapshot s = randomSnapshot(10, 3, 7);
    s.particles.species[4] = 3;  // only three species named
    EXPECT_THROW(dpd::writeSnapshot(path("bad"), s), std::invalid_argument);
    s = randomSnapshot(10, 3, 7);
    s.particles.vz.pop_back();
    EXPECT_THROW(dpd::writeSnapshot(path("bad"), s), std::invalid_argument);
    EXPECT_FALSE(fs::exists(path("bad/particles.h5")));
}

TEST_F(SnapshotTest, ReadingMissingFileThrowsIoErrorNamingIt) {
    expectIoError([&] { dpd::readSnapshot(path("9/particles.h5")); }, {"9/particles.h5"});
}

TEST_F(SnapshotTest, FileMissingADatasetThrowsIoErrorNamingFileAndDataset) {
    dpd::writeSnapshot(path("1"), randomSnapshot(20, 3, 8));
    const std::string file = path("1/particles.h5");
    replaceDataset(file, "particles/force", H5T_NATIVE_DOUBLE, nullptr, {});
    expectIoError([&] { dpd::readSnapshot(file); }, {file, "particles/force"});
}

TEST_F(SnapshotTest, FileMissingAnAttributeThrowsIoErrorNamingIt) {
    dpd::writeSnapshot(path("1"), randomSnapshot(20, 3, 8));
    const std::string file = path("1/particles.h5");
    {
        dpd::Hdf5Handle f(H5Fopen(file.c_str(), H5F_ACC_RDWR, H5P_DEFAULT), H5Fclose);
        H5Adelete(f.get(), "boxHi");
    }
    expectIoError([&] { dpd::readSnapshot(file); }, {file, "boxHi"});
}

TEST_F(SnapshotTest, WrongShapeThrowsIoErrorNamingFileAndDataset) {
    dpd::writeSnapshot(path("1"), randomSnapshot(20, 3, 9));
    const std::string file = path("1/particles.h5");
    const std::vector<double> flat(40, 0.0);
    replaceDataset(file, "particles/velocity", H5T_NATIVE_DOUBLE, flat.data(), {20, 2});
    expectIoError([&] { dpd::readSnapshot(file); }, {file, "particles/velocity", "(20, 2)"});
}

TEST_F(SnapshotTest, IdCountDifferentFromPositionsThrowsIoError) {
    dpd::writeSnapshot(path("1"), randomSnapshot(20, 3, 10));
    const std::string file = path("1/particles.h5");
    const std::vector<std::uint64_t> ids(19, 1);
    replaceDataset(file, "particles/id", H5T_NATIVE_UINT64, ids.data(), {19});
    expectIoError([&] { dpd::readSnapshot(file); }, {file, "particles/id"});
}

TEST_F(SnapshotTest, SpeciesIndexOutOfRangeThrowsIoError) {
    dpd::writeSnapshot(path("1"), randomSnapshot(20, 3, 11));
    const std::string file = path("1/particles.h5");
    std::vector<std::int32_t> species(20, 0);
    species[13] = 3;  // three species are named: 0, 1, 2
    replaceDataset(file, "particles/species", H5T_NATIVE_INT32, species.data(), {20});
    expectIoError([&] { dpd::readSnapshot(file); }, {file, "particles/species", "row 13"});
    species[13] = -1;
    replaceDataset(file, "particles/species", H5T_NATIVE_INT32, species.data(), {20});
    expectIoError([&] { dpd::readSnapshot(file); }, {file, "particles/species"});
}

TEST_F(SnapshotTest, ForeignHdf5FileThrowsIoErrorNamingFormat) {
    {
        dpd::Hdf5Writer w(path("other.h5"));
        w.writeDoubles("data", {1.0});
        w.writeAttribute("/", "format", "something-else");
        w.commit();
    }
    expectIoError([&] { dpd::readSnapshot(path("other.h5")); }, {"other.h5", "format", "something-else"});
}

TEST_F(SnapshotTest, H5pyReadsTheFile) {
    // h5py is one of the set-up's packages (etc/installDependencies): without it this claim is unproven, a failure.
    ASSERT_EQ(std::system("/usr/bin/python3 -c 'import h5py' >/dev/null 2>&1"), 0)
        << "h5py is missing: run etc/installDependencies (python3-h5py)";
    dpd::Snapshot s = randomSnapshot(123, 3, 12);
    s.time = 1.25;
    dpd::writeSnapshot(path("1.25"), s);
    const std::string script = path("check.py");
    std::ofstream(script) << "import sys, h5py\n"
                             "f = h5py.File(sys.argv[1], 'r')\n"
                             "assert f['particles/position'].shape == (123, 3), f['particles/position'].shape\n"
                             "assert f.attrs['time'] == 1.25, f.attrs['time']\n"
                             "assert [str(n) for n in f.attrs['speciesNames']] == ['fluid', 'wall', 'polymer']\n"
                             "assert f.attrs['format'] == 'dpdFoamLike-snapshot-1'\n"
                             "assert list(f.attrs['speciesFrozen']) == [0, 1, 0]\n";
    const std::string command = "/usr/bin/python3 '" + script + "' '" + path("1.25/particles.h5") + "'";
    EXPECT_EQ(std::system(command.c_str()), 0) << command;
}

// Values no run can have written are refused on reading, naming the file, the dataset and the row:
// a non-finite number anywhere, a position more than one box length outside the box, an id twice.
TEST_F(SnapshotTest, ImpossibleValuesAreRefusedNamingDatasetAndRow) {
    const auto refused = [&](const std::string& name, const std::function<void(dpd::Snapshot&)>& spoil,
                             const std::vector<std::string>& fragments) {
        SCOPED_TRACE(name);
        dpd::Snapshot s = randomSnapshot(40, 3, 5);
        spoil(s);
        dpd::writeSnapshot(path(name), s);
        const std::string file = path(name + "/particles.h5");
        std::vector<std::string> all = fragments;
        all.push_back(file);
        expectIoError([&] { dpd::readSnapshot(file); }, all);
    };
    const double nan = std::numeric_limits<double>::quiet_NaN();
    refused("1", [&](dpd::Snapshot& s) { s.particles.rz[17] = nan; }, {"'particles/position' row 17", "nan"});
    refused("2", [&](dpd::Snapshot& s) { s.particles.vy[3] = std::numeric_limits<double>::infinity(); },
            {"'particles/velocity' row 3"});
    refused("3", [&](dpd::Snapshot& s) { s.particles.fx[39] = -nan; }, {"'particles/force' row 39"});
    // z = 1e6 in a box 2.25..12.125; 22 = hi + 1.0 box length is still read (wrapped by the run).
    refused("4", [&](dpd::Snapshot& s) { s.particles.rz[8] = 1e6; }, {"'particles/position' row 8", "1000000",
                                                                       "more than one box length outside"});
    refused("5", [&](dpd::Snapshot& s) { s.particles.id[30] = s.particles.id[4]; }, {"'particles/id'", "rows 4 and 30"});
    refused("6", [&](dpd::Snapshot& s) { s.time = nan; }, {"attribute 'time'"});
    dpd::Snapshot edge = randomSnapshot(40, 3, 5);
    edge.particles.rz[8] = 12.125 + 9.875;
    dpd::writeSnapshot(path("7"), edge);
    EXPECT_NO_THROW(dpd::readSnapshot(path("7/particles.h5")));
}
