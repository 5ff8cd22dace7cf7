// Profile tables: what is written reads back bit for bit; a damaged file is reported with its name
// and the line at fault.
#include "sampling/ProfileTable.hpp"

#include "core/Error.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

namespace fs = std::filesystem;

namespace dpd {
namespace {

class ProfileTableTest : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = fs::temp_directory_path() /
               ("dpdProfileTable-" + std::string(info->name()) + "-" + std::to_string(::getpid()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }
    std::string writeText(const std::string& name, const std::string& text) const {
        std::ofstream(path(name)) << text;
        return path(name);
    }
    // The message of the IoError readProfileTable throws, or "" when it does not throw.
    static std::string readError(const std::string& file) {
        try {
            readProfileTable(file);
        } catch (const IoError& e) {
            return e.what();
        }
        return "";
    }
    fs::path dir_;
};

BinProfile awkwardProfile() {
    BinProfile p;
    const int n = 7;
    for (int i = 0; i < n; ++i) {
        const double x = -3.0 + i * (1.0 / 3.0);
        p.centre.push_back(x);
        p.density.push_back(4.0 + std::sin(x) / 7.0);
        p.densityErr.push_back(1e-300 * (i + 1));
        p.ux.push_back(0.1 * x * x - 1.0 / 3.0);
        p.uxErr.push_back(std::nextafter(0.01, 1.0));
        p.uy.push_back(-0.0);
        p.uyErr.push_back(0.0);
        p.uz.push_back(std::numeric_limits<double>::denorm_min() * i);
        p.uzErr.push_back(123456789.123456789);
        p.kT.push_back(1.0 + 1e-16 * i);
        p.kTErr.push_back(std::exp(-i));
        p.count.push_back(1e6 + i);
    }
    p.samples = 100;
    return p;
}

void expectSameBits(const std::vector<double>& a, const std::vector<double>& b, const std::string& what) {
    ASSERT_EQ(a.size(), b.size()) << what;
    for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i], b[i]) << what << " row " << i;
}

TEST_F(ProfileTableTest, RoundTripIsExact) {
    const BinProfile p = awkwardProfile();
    const std::string file = path("sub/dir/profile.dat");  // parent directories are created
    writeProfileTable(file, "z", p);
    const ProfileTableData t = readProfileTable(file);
    EXPECT_EQ(t.file, file);
    EXPECT_EQ(t.names, profileTableColumns("z"));
    EXPECT_EQ(t.axisName(), "z");
    EXPECT_EQ(t.rows(), p.centre.size());
    expectSameBits(t.column("z"), p.centre, "z");
    expectSameBits(t.column("density"), p.density, "density");
    expectSameBits(t.column("densityErr"), p.densityErr, "densityErr");
    expectSameBits(t.column("ux"), p.ux, "ux");
    expectSameBits(t.column("uxErr"), p.uxErr, "uxErr");
    expectSameBits(t.column("uy"), p.uy, "uy");
    expectSameBits(t.column("uyErr"), p.uyErr, "uyErr");
    expectSameBits(t.column("uz"), p.uz, "uz");
    expectSameBits(t.column("uzErr"), p.uzErr, "uzErr");
    expectSameBits(t.column("kT"), p.kT, "kT");
    expectSameBits(t.column("kTErr"), p.kTErr, "kTErr");
    expectSameBits(t.column("count"), p.count, "count");
    // Only the table is left behind: the temporary file was renamed over it.
    std::size_t files = 0;
    for (const auto& e : fs::directory_iterator(dir_ / "sub" / "dir")) {
        ++files;
        EXPECT_EQ(e.path().filename(), "profile.dat");
    }
    EXPECT_EQ(files, 1u);
}

TEST_F(ProfileTableTest, HeaderLineNamesTheAxisFirst) {
    writeProfileTable(path("p.dat"), "x", awkwardProfile());
    std::ifstream in(path("p.dat"));
    std::string header;
    std::getline(in, header);
    EXPECT_EQ(header, "# x density densityErr ux uxErr uy uyErr uz uzErr kT kTErr count");
}

TEST_F(ProfileTableTest, OverwritesAnExistingTable) {
    BinProfile p = awkwardProfile();
    writeProfileTable(path("p.dat"), "z", p);
    p.ux.assign(p.ux.size(), 2.5);
    writeProfileTable(path("p.dat"), "z", p);
    EXPECT_EQ(readProfileTable(path("p.dat")).column("ux").front(), 2.5);
}

TEST_F(ProfileTableTest, CommentsAndBlankLinesAreSkipped) {
    const std::string file = writeText("c.dat", "\n# y a b\n1 2 3\n\n# a comment\n4 5 6\n");
    const ProfileTableData t = readProfileTable(file);
    EXPECT_EQ(t.axisName(), "y");
    ASSERT_EQ(t.rows(), 2u);
    EXPECT_EQ(t.column("b")[1], 6.0);
}

TEST_F(ProfileTableTest, MissingColumnNamesFileAndColumn) {
    const std::string file = writeText("c.dat", "# z density\n1 2\n");
    const ProfileTableData t = readProfileTable(file);
    try {
        t.column("ux");
        FAIL() << "expected IoError";
    } catch (const IoError& e) {
        const std::string msg = e.what();
        EXPECT_NE(msg.find(file), std::string::npos) << msg;
        EXPECT_NE(msg.find("'ux'"), std::string::npos) << msg;
    }
}

TEST_F(ProfileTableTest, RowWithTooFewValuesNamesFileAndLine) {
    const std::string file = writeText("short.dat", "# z a b\n1 2 3\n4 5 6\n7 8\n");
    const std::string msg = readError(file);
    EXPECT_NE(msg.find(file + ":4:"), std::string::npos) << msg;
    EXPECT_NE(msg.find("expected 3 values"), std::string::npos) << msg;
}

TEST_F(ProfileTableTest, RowWithTooManyValuesNamesFileAndLine) {
    const std::string file = writeText("long.dat", "# z a\n\n1 2 3\n");
    EXPECT_NE(readError(file).find(file + ":3:"), std::string::npos) << readError(file);
}

TEST_F(ProfileTableTest, ValueThatIsNotANumberNamesFileLineAndColumn) {
    const std::string file = writeText("bad.dat", "# z a b\n1 2 3\n4 5x 6\n");
    const std::string msg = readError(file);
    EXPECT_NE(msg.find(file + ":3:"), std::string::npos) << msg;
    EXPECT_NE(msg.find("'5x'"), std::string::npos) << msg;
    EXPECT_NE(msg.find("column 'a'"), std::string::npos) << msg;
}

TEST_F(ProfileTableTest, DataBeforeTheHeaderIsAnError) {
    const std::string file = writeText("nohead.dat", "1 2 3\n");
    EXPECT_NE(readError(file).find(file + ":1:"), std::string::npos) << readError(file);
}

TEST_F(ProfileTableTest, RepeatedColumnIsAnError) {
    const std::string file = writeText("dup.dat", "# z a a\n1 2 3\n");
    const std::string msg = readError(file);
    EXPECT_NE(msg.find(file + ":1:"), std::string::npos) << msg;
    EXPECT_NE(msg.find("'a'"), std::string::npos) << msg;
}

TEST_F(ProfileTableTest, EmptyOrHeaderOnlyOrMissingFilesAreErrors) {
    const std::string empty = writeText("empty.dat", "");
    EXPECT_NE(readError(empty).find(empty), std::string::npos);
    const std::string headerOnly = writeText("header.dat", "# z a\n");
    EXPECT_NE(readError(headerOnly).find("no rows"), std::string::npos) << readError(headerOnly);
    const std::string missing = path("missing.dat");
    EXPECT_NE(readError(missing).find(missing), std::string::npos) << readError(missing);
}

TEST_F(ProfileTableTest, ArraysOfDifferentLengthAreRejectedAndNothingIsWritten) {
    BinProfile p = awkwardProfile();
    p.kT.pop_back();
    EXPECT_THROW(writeProfileTable(path("p.dat"), "z", p), std::invalid_argument);
    EXPECT_FALSE(fs::exists(path("p.dat")));
}

}  // namespace
}  // namespace dpd
