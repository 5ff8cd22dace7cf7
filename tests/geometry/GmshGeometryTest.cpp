// gmsh geometries (geometry/GmshGeometry): a missing file, a file that does not parse and one
// without a "fluid"/"solid" group are clear errors; a channel drawn in gmsh (as two solid rectangles,
// as one fluid rectangle, or as an extruded fluid volume) gives the same flags as the equivalent
// image mask and the exact distance to its walls.
#include "GeometryTestFiles.hpp"

#include "core/Error.hpp"
#include "geometry/GeometryDictionary.hpp"
#include "io/Dictionary.hpp"

#include <gtest/gtest.h>
#include <omp.h>

using namespace dpd;
using namespace geometryTest;

namespace {

// The channel of every test: box x 0..8, z 0..6 (y 0..3 in 3-D), solid below z = 1.5 and above 4.5.
Box channelBox(int dimension) {
    Box b;
    b.dimension = dimension;
    b.lo = Eigen::Vector3d(0, dimension == 3 ? 0.0 : -0.5, 0);
    b.hi = Eigen::Vector3d(8, dimension == 3 ? 3.0 : 0.5, 6);
    return b;
}

const char* twoSolidRectangles = R"(
Point(1) = {0, 0, 0}; Point(2) = {8, 0, 0}; Point(3) = {8, 1.5, 0}; Point(4) = {0, 1.5, 0};
Point(5) = {0, 4.5, 0}; Point(6) = {8, 4.5, 0}; Point(7) = {8, 6, 0}; Point(8) = {0, 6, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Curve Loop(2) = {5, 6, 7, 8}; Plane Surface(2) = {2};
Physical Surface("solid") = {1, 2};
)";

const char* oneFluidRectangle = R"(
Point(1) = {0, 1.5, 0}; Point(2) = {8, 1.5, 0}; Point(3) = {8, 4.5, 0}; Point(4) = {0, 4.5, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Physical Surface("fluid") = {1};
)";

const char* fluidVolume = R"(
Point(1) = {0, 0, 1.5}; Point(2) = {8, 0, 1.5}; Point(3) = {8, 3, 1.5}; Point(4) = {0, 3, 1.5};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
out[] = Extrude {0, 0, 3} { Surface{1}; };
Physical Volume("fluid") = {out[1]};
)";

// The same channel as a 16 x 12 mask of 0.5 pixels (rows 0-2 and 9-11 solid).
std::vector<bool> maskFlags(const std::string& file, const Box& box) {
    Picture pic(12, std::vector<int>(16, 255));
    for (int c = 0; c < 16; ++c) pic[0][c] = pic[1][c] = pic[2][c] = pic[9][c] = pic[10][c] = pic[11][c] = 0;
    writePgm(file, pic);
    const SolidRegion r = readSolidRegion(
        Dictionary::parse("type imageMask; file \"" + file + "\"; solidValues (0); pixelSize 0.5; gridSpacing 0.25;", "maskDict"),
        "", box, 1.0);
    std::vector<bool> v;
    for (std::size_t c = 0; c < r.flags.grid().size(); ++c) v.push_back(r.flags.isSolid(c));
    return v;
}

SolidRegion gmshRegion(const std::string& file, const Box& box) {
    return readSolidRegion(Dictionary::parse("type gmsh; file \"" + file + "\"; gridSpacing 0.25;", "gmshDict"), "", box, 1.0);
}

class GmshGeometry : public ScratchDirectory {};

TEST_F(GmshGeometry, MissingUnparsableOrUngroupedFilesAreClearErrors) {
    writeText(path("bad.geo"), "Point(1) = {0, 0, 0;\n");
    writeText(path("nogroup.geo"), "Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Line(1) = {1, 2};\n");
    for (const auto& [file, says] : std::vector<std::pair<std::string, std::string>>{
             {path("none.geo"), "no such gmsh file"}, {path("bad.geo"), "gmsh cannot read it"},
             {path("nogroup.geo"), "no physical group named \"fluid\" or \"solid\""}}) {
        const std::string e = inputError([&] { gmshRegion(file, channelBox(2)); });
        EXPECT_NE(e.find("gmshDict"), std::string::npos) << e;
        EXPECT_NE(e.find("keyword 'file'"), std::string::npos) << e;
        EXPECT_NE(e.find(file), std::string::npos) << e;
        EXPECT_NE(e.find(says), std::string::npos) << e;
    }
    writeText(path("fluid.geo"), oneFluidRectangle);
    EXPECT_NE(inputError([&] {
                  readSolidRegion(Dictionary::parse("type gmsh; file \"" + path("fluid.geo") + "\"; origin (3 0 0);", "gmshDict"), "",
                                  channelBox(2), 1.0);
              }).find("outside the box"),
              std::string::npos);
}

TEST_F(GmshGeometry, ChannelGivesTheSameFlagsAsTheMaskAndExactDistances) {
    writeText(path("solid.geo"), twoSolidRectangles);
    writeText(path("fluid.geo"), oneFluidRectangle);
    const Box box = channelBox(2);
    const std::vector<bool> expected = maskFlags(path("mask.pgm"), box);
    for (const std::string name : {"solid.geo", "fluid.geo"}) {
        SCOPED_TRACE(name);
        const SolidRegion r = gmshRegion(path(name), box);
        std::vector<bool> v;
        for (std::size_t c = 0; c < r.flags.grid().size(); ++c) v.push_back(r.flags.isSolid(c));
        EXPECT_EQ(v, expected);
        EXPECT_DOUBLE_EQ(r.flags.porosity(), 0.5);
        // Only the two walls are surface: the rectangles' sides on the periodic box faces are not.
        for (double z = 0.05; z < 6.0; z += 0.1) {
            const double exact = 1.5 - std::abs(z - 3.0);   // walls at z = 1.5 and 4.5
            const SurfaceDistance s = r.geometry.signedDistance({0.3 + z, 0.0, z}, 2.0);
            EXPECT_NEAR(s.distance, exact, 1e-9) << z;
            if (std::abs(z - 3.0) > 0.01 && std::abs(exact) > 1e-9 && std::abs(exact) < 1.49)
                EXPECT_NEAR(s.normal.z(), z < 3.0 ? 1.0 : -1.0, 1e-9) << z;  // towards z = 3
        }
    }
}

TEST_F(GmshGeometry, ExtrudedFluidVolumeGivesTheSameFlagsAsTheMaskIn3D) {
    writeText(path("volume.geo"), fluidVolume);
    const Box box = channelBox(3);
    const SolidRegion r = gmshRegion(path("volume.geo"), box);
    EXPECT_EQ(r.geometry.uniformAxis(), -1);
    // The volume's flags vary along x, y, z; the mask's are extruded along y: compare cell by cell.
    Picture pic(12, std::vector<int>(16, 255));
    for (int c = 0; c < 16; ++c) pic[0][c] = pic[1][c] = pic[2][c] = pic[9][c] = pic[10][c] = pic[11][c] = 0;
    writePgm(path("mask.pgm"), pic);
    const SolidRegion m = readSolidRegion(
        Dictionary::parse("type imageMask; file \"" + path("mask.pgm") + "\"; solidValues (0); pixelSize 0.5; gridSpacing 0.25;", "maskDict"),
        "", box, 1.0);
    const BackgroundGrid& g = r.flags.grid();
    for (int k = 0; k < g.n[2]; ++k)
        for (int j = 0; j < g.n[1]; ++j)
            for (int i = 0; i < g.n[0]; ++i) ASSERT_EQ(r.flags.isSolid(i, j, k), m.flags.isSolidAt(g.centre(i, j, k))) << i << j << k;
    EXPECT_NEAR(r.geometry.signedDistance({4.0, 1.0, 2.0}, 2.0).distance, 0.5, 1e-9);
    EXPECT_NEAR(r.geometry.signedDistance({4.0, 1.0, 0.5}, 2.0).distance, -1.0, 1e-9);
}

}  // namespace

// gmsh sets OpenMP's thread count for the process; reading a geometry must leave the caller's (a run
// that read a gmsh channel went on one thread of two).
TEST_F(GmshGeometry, ReadingAGeometryLeavesTheThreadCountAlone) {
    writeText(path("fluid.geo"), oneFluidRectangle);
    const int before = omp_get_max_threads();
    omp_set_num_threads(3);
    gmshRegion(path("fluid.geo"), channelBox(2));
    EXPECT_EQ(omp_get_max_threads(), 3);
    omp_set_num_threads(before);
}
