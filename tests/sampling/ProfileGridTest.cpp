// Bins on a 2-D grid (BinLayout with two axes; BinLayoutDictionary, BinProfile, ProfileGrid): a
// uniform fluid gives flat fields within their statistical errors, and error bars of the right size;
// a known velocity field is recovered bin by bin; the .vti file opens in VTK's own reader with every
// value in its cell; sections, the 2-D table and the stored bins round-trip; 1-D files keep their form.
#include "core/Error.hpp"
#include "io/Dictionary.hpp"
#include "io/Hdf5File.hpp"
#include "sampling/BinAccumulatorFile.hpp"
#include "sampling/BinLayoutDictionary.hpp"
#include "sampling/BinProfile.hpp"
#include "sampling/ProfileGrid.hpp"
#include "sampling/ProfileTable.hpp"

#include <gtest/gtest.h>
#include <unistd.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkXMLImageDataReader.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <random>

using namespace dpd;
namespace fs = std::filesystem;

namespace {

constexpr double kLx = 8.0, kLz = 4.0;

Box box2d() {
    Box b;
    b.dimension = 2;
    b.lo = Eigen::Vector3d(0, -0.5, 0);
    b.hi = Eigen::Vector3d(kLx, 0.5, kLz);
    return b;
}

BinLayout gridLayout(const std::string& text) {
    return readBinLayout(Dictionary::parse(text, "controlDict"), box2d());
}

using VelocityField = std::function<Eigen::Vector3d(double x, double z)>;

// `samples` independent samples of n particles placed uniformly in the 2-D box with velocities
// u(x, z) + Maxwellian noise at kT: the samples are uncorrelated, so every error is known exactly.
BinAccumulator sampleFluid(const BinLayout& layout, int n, int samples, long perBlock, double kT, const VelocityField& u) {
    BinAccumulator acc(layout, {1}, perBlock);
    std::mt19937 gen(42);
    std::uniform_real_distribution<double> uni(0.0, 1.0);
    std::normal_distribution<double> normal(0.0, std::sqrt(kT));
    for (int s = 0; s < samples; ++s) {
        Particles p;
        for (int i = 0; i < n; ++i) {
            const double x = kLx * uni(gen), z = kLz * uni(gen);
            const Eigen::Vector3d v = u(x, z);
            p.add(i, 0, x, 0.0, z, v.x() + normal(gen), 0.0, v.z() + normal(gen));
        }
        acc.sample(p);
    }
    return acc;
}

class ProfileGrid : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("dpdProfileGrid-" + std::to_string(::getpid()) + "-" +
                                            ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }
    fs::path dir_;
};

// 32 bins of area 1, 400 particles per sample: a bin's count per sample is binomial with p = 1/32,
// so its density over M samples has the exact error sqrt(n p (1 - p) / M). The sum over the bins of
// ((rho - rho0) / error)^2 is chi-square with 32 degrees of freedom (mean 32, sd 8): held below
// 32 + 5 x 8. The same for the mean velocity (error sqrt(kT / count)) and kT (in 2-D the mean of two
// squared components: error kT sqrt(2 / (2 count)) = kT / sqrt(count)). The block errors (10 blocks:
// each relative error uncertain by 1/sqrt(2 x 9) = 0.24, over 32 bins 0.042) average within 5 x 0.042
// of the exact ones.
TEST_F(ProfileGrid, AUniformFluidGivesFlatFieldsWithinTheirErrors) {
    const BinLayout layout = gridLayout("axes (x z); nBins (8 4);");
    ASSERT_EQ(layout.binCount(), 32);
    const int n = 400, samples = 2000;
    const double kT = 1.3;
    const BinAccumulator acc = sampleFluid(layout, n, samples, 200, kT, [](double, double) { return Eigen::Vector3d::Zero(); });
    const BinProfile p = computeProfile(acc, binCrossSection(layout, box2d()), 2);
    ASSERT_EQ(p.density.size(), 32u);
    ASSERT_EQ(p.blocksForErrors, 10);
    const double q = 1.0 / 32.0, rho0 = n * q / 1.0;
    const double rhoErr = std::sqrt(n * q * (1 - q) / samples);
    double chiRho = 0.0, chiU = 0.0, chiKT = 0.0, errRatio = 0.0;
    for (int b = 0; b < 32; ++b) {
        chiRho += std::pow((p.density[b] - rho0) / rhoErr, 2);
        chiU += std::pow(p.ux[b] / std::sqrt(kT / p.count[b]), 2);
        chiKT += std::pow((p.kT[b] - kT) / (kT / std::sqrt(p.count[b])), 2);
        errRatio += p.densityErr[b] / rhoErr / 32.0;
        EXPECT_DOUBLE_EQ(p.centre[b], layout.centre(b % 8));
        EXPECT_DOUBLE_EQ(p.centre2[b], layout.centre2(b / 8));
    }
    EXPECT_LT(chiRho, 72.0);
    EXPECT_LT(chiU, 72.0);
    EXPECT_LT(chiKT, 72.0);
    EXPECT_NEAR(errRatio, 1.0, 0.21);
}

// u = (A sin(2 pi z / Lz), 0, B cos(2 pi x / Lx)): a bin's mean of sin(k z) over its width w is
// sin(k z_c) sin(k w / 2) / (k w / 2). Each bin's mean velocity has the error sqrt((kT + var_u) / count)
// with var_u <= A^2 + B^2 an upper bound of the field's spread; chi-square over 64 bins (mean 64,
// sd 11.3) held below 64 + 5 x 11.3.
TEST_F(ProfileGrid, AKnownVelocityFieldIsRecovered) {
    const BinLayout layout = gridLayout("axes (x z); nBins (8 8);");
    const double A = 0.5, B = 0.3, kT = 1.0;
    const double kx = 2 * M_PI / kLx, kz = 2 * M_PI / kLz;
    const BinAccumulator acc = sampleFluid(layout, 640, 2000, 200, kT, [&](double x, double z) {
        return Eigen::Vector3d(A * std::sin(kz * z), 0.0, B * std::cos(kx * x));
    });
    const BinProfile p = computeProfile(acc, binCrossSection(layout, box2d()), 2);
    const auto binMean = [](double k, double w) { return std::sin(k * w / 2) / (k * w / 2); };
    double chi = 0.0;
    for (int b = 0; b < 64; ++b) {
        const double ux = A * std::sin(kz * p.centre2[b]) * binMean(kz, layout.width2());
        const double uz = B * std::cos(kx * p.centre[b]) * binMean(kx, layout.width());
        const double err = std::sqrt((kT + A * A + B * B) / p.count[b]);
        chi += std::pow((p.ux[b] - ux) / err, 2) + std::pow((p.uz[b] - uz) / err, 2);
    }
    EXPECT_LT(chi, 2 * 64 + 5 * 16.0);  // 128 degrees of freedom: mean 128, sd 16
    // The field is not flat: its amplitude shows far outside the errors.
    double peak = 0.0;
    for (int b = 0; b < 64; ++b) peak = std::max(peak, p.ux[b]);
    EXPECT_GT(peak, 0.4);
}

// The .vti file, read back by VTK: extents, spacing and origin in the box's axes, and every bin's
// value in its cell, whichever axis comes first.
TEST_F(ProfileGrid, TheImageFileOpensInVtkWithEveryValueInItsCell) {
    for (const std::string axes : {"(x z)", "(z x)"}) {
        const BinLayout layout = gridLayout("axes " + axes + "; nBins (" + (axes == "(x z)" ? "8 4" : "4 8") + ");");
        const BinAccumulator acc = sampleFluid(layout, 200, 20, 10, 1.0, [](double x, double z) {
            return Eigen::Vector3d(x, 0.0, 10 * z);
        });
        const BinProfile p = computeProfile(acc, 1.0, 2);
        writeProfileImage(path("grid.vti"), layout, p);
        vtkNew<vtkXMLImageDataReader> reader;
        reader->SetFileName(path("grid.vti").c_str());
        reader->Update();
        vtkImageData* image = reader->GetOutput();
        ASSERT_EQ(image->GetNumberOfCells(), 32) << axes;
        int dims[3];
        image->GetDimensions(dims);
        EXPECT_EQ(dims[0], 9);
        EXPECT_EQ(dims[1], 1);
        EXPECT_EQ(dims[2], 5);
        double spacing[3], origin[3];
        image->GetSpacing(spacing);
        image->GetOrigin(origin);
        EXPECT_DOUBLE_EQ(spacing[0], 1.0);
        EXPECT_DOUBLE_EQ(spacing[2], 1.0);
        EXPECT_DOUBLE_EQ(origin[0], 0.0);
        vtkDataArray* density = image->GetCellData()->GetArray("density");
        vtkDataArray* velocity = image->GetCellData()->GetArray("velocity");
        ASSERT_NE(density, nullptr);
        ASSERT_NE(velocity, nullptr);
        ASSERT_NE(image->GetCellData()->GetArray("kTErr"), nullptr);
        EXPECT_EQ(velocity->GetNumberOfComponents(), 3);
        for (int b = 0; b < 32; ++b) {
            // The cell holding the bin's centre.
            double centre[3] = {0, 0, 0};
            centre[layout.axis] = p.centre[b];
            centre[layout.axis2] = p.centre2[b];
            const int ix = static_cast<int>(centre[0]), iz = static_cast<int>(centre[2]);
            const vtkIdType cell = ix + 8 * iz;
            EXPECT_DOUBLE_EQ(density->GetTuple1(cell), p.density[b]) << axes << " bin " << b;
            EXPECT_DOUBLE_EQ(velocity->GetComponent(cell, 0), p.ux[b]);
            EXPECT_DOUBLE_EQ(velocity->GetComponent(cell, 2), p.uz[b]);
        }
    }
}

TEST_F(ProfileGrid, SectionsTablesAndStoredBinsRoundTrip) {
    const Dictionary d = Dictionary::parse("axes (x z); nBins (8 4); sections (2.5 7.9);", "controlDict");
    const BinLayout layout = readBinLayout(d, box2d());
    const std::vector<double> sections = readSections(d, layout);
    ASSERT_EQ(sections.size(), 2u);
    const BinAccumulator acc = sampleFluid(layout, 200, 40, 10, 1.0, [](double x, double) { return Eigen::Vector3d(x, 0, 0); });
    writeBins(path("grid.h5"), acc, 2, 1.0, 3.5, sections);
    const StoredBins stored = readBins(path("grid.h5"));
    EXPECT_EQ(stored.accumulator.layout().axis2, 2);
    EXPECT_EQ(stored.accumulator.layout().nBins2, 4);
    EXPECT_EQ(stored.sections, sections);
    const BinProfile p = computeProfile(acc, 1.0, 2), q = computeProfile(stored.accumulator, 1.0, 2);
    EXPECT_EQ(p.density, q.density);
    EXPECT_EQ(p.ux, q.ux);

    // The section at x = 2.5 is bin column 2, along z.
    const BinProfile s = profileSection(layout, p, 2.5);
    ASSERT_EQ(s.centre.size(), 4u);
    for (int j = 0; j < 4; ++j) {
        EXPECT_DOUBLE_EQ(s.centre[j], layout.centre2(j));
        EXPECT_DOUBLE_EQ(s.density[j], p.density[2 + 8 * j]);
        EXPECT_DOUBLE_EQ(s.ux[j], p.ux[2 + 8 * j]);
    }
    EXPECT_EQ(sectionFileName("flow", layout, 2.5), "flow_x2.5.dat");
    writeProfileTable(path(sectionFileName("flow", layout, 2.5)), "z", s);
    EXPECT_EQ(readProfileTable(path("flow_x2.5.dat")).names.front(), "z");

    // The 2-D table: both axes first, one row per bin.
    writeProfileTable(path("grid.dat"), "x", p, "z");
    const ProfileTableData t = readProfileTable(path("grid.dat"));
    ASSERT_EQ(t.rows(), 32u);
    EXPECT_EQ(t.names[0], "x");
    EXPECT_EQ(t.names[1], "z");
    EXPECT_EQ(t.column("z"), p.centre2);
    EXPECT_EQ(t.column("density"), p.density);
}

TEST_F(ProfileGrid, OneAxisFilesKeepTheirFormAndBadLayoutsNameTheKeyword) {
    const BinLayout line = gridLayout("axis z; nBins 4;");
    EXPECT_FALSE(line.twoAxes());
    BinAccumulator acc = sampleFluid(line, 50, 5, 5, 1.0, [](double, double) { return Eigen::Vector3d::Zero(); });
    writeBins(path("line.h5"), acc, 2, kLx, 1.0);
    const Hdf5Reader r(path("line.h5"));
    EXPECT_FALSE(r.hasAttribute("/", "axis2"));
    EXPECT_FALSE(r.hasAttribute("/", "sections"));
    EXPECT_EQ(r.attributeString("/", "format"), "dpdFoamLike-bins-2");
    EXPECT_FALSE(readBins(path("line.h5")).accumulator.layout().twoAxes());

    const auto error = [](const std::string& text) {
        try {
            gridLayout(text);
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_NE(error("axes (x z); nBins (8);").find("nBins"), std::string::npos);
    EXPECT_NE(error("axes (x y); nBins (8 8);").find("axes"), std::string::npos);
    EXPECT_NE(error("axes (x x); nBins (8 8);").find("axes"), std::string::npos);
    EXPECT_NE(error("axis x; nBins 8; sections (1);").find("sections"), std::string::npos);
    EXPECT_NE(error("axes (x z); nBins (8 8); min (0 0 0);").find("min"), std::string::npos);
    const Dictionary d = Dictionary::parse("axes (x z); nBins (8 4); sections (9);", "controlDict");
    EXPECT_THROW(readSections(d, readBinLayout(d, box2d())), InputError);
}

}  // namespace
