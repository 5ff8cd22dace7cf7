#include "geometry/GeometryDictionary.hpp"

#include "geometry/GeometryInputError.hpp"
#include "geometry/GmshGeometry.hpp"
#include "geometry/ImageMask.hpp"
#include "io/Dictionary.hpp"

#include <filesystem>

namespace dpd {

namespace {

// The distance is tabulated out to this many cutoffs on either side of the surface.
constexpr double kBandInCutoffs = 2.0;

int readExtrudeAxis(const Dictionary& d, const Box& box) {
    const int axis = d.found("extrudeAxis") ? d.getAxis("extrudeAxis") : 1;
    if (box.dimension == 2 && axis != 1)
        d.fail("extrudeAxis", "a 2-D scene lies in the x-z plane: the geometry is extruded along y");
    return axis;
}

std::string resolveFile(const Dictionary& d, const std::string& caseDir) {
    const std::filesystem::path file(d.get<std::string>("file"));
    return file.is_absolute() ? file.string() : (std::filesystem::path(caseDir) / file).string();
}

ImageMaskSettings readMaskSettings(const Dictionary& d, const Box& box) {
    d.checkKeys({"type", "file", "solidValues", "solidBelow", "solidAbove", "pixelSize", "smooth", "extrudeAxis", "origin",
                 "gridSpacing"});
    ImageMaskSettings s;
    const int given = (d.found("solidValues") ? 1 : 0) + (d.found("solidBelow") ? 1 : 0) + (d.found("solidAbove") ? 1 : 0);
    if (given != 1) d.fail("solidValues", "say which pixels are solid with exactly one of solidValues, solidBelow, solidAbove");
    if (d.found("solidValues")) {
        s.solidValues = d.get<std::vector<double>>("solidValues");
        if (s.solidValues.empty()) d.fail("solidValues", "give at least one grey level");
    } else {
        s.useThreshold = true;
        s.solidBelow = d.found("solidBelow");
        s.threshold = d.get<double>(s.solidBelow ? "solidBelow" : "solidAbove");
    }
    s.pixelSize = d.getPositive<double>("pixelSize");
    s.smooth = d.getOrDefault<bool>("smooth", true);
    s.extrudeAxis = readExtrudeAxis(d, box);
    s.origin = d.getOrDefault<Eigen::Vector3d>("origin", box.lo);
    return s;
}

GmshSettings readGmshSettings(const Dictionary& d, const std::string& caseDir, const Box& box) {
    d.checkKeys({"type", "file", "extrudeAxis", "origin", "meshSize", "gridSpacing"});
    GmshSettings s;
    s.file = resolveFile(d, caseDir);
    s.extrudeAxis = readExtrudeAxis(d, box);
    s.origin = d.getOrDefault<Eigen::Vector3d>("origin", Eigen::Vector3d::Zero());
    if (d.found("meshSize")) s.meshSize = d.getPositive<double>("meshSize");
    return s;
}

}  // namespace

double readGridSpacing(const Dictionary& d, double cutoff) {
    if (!d.found("gridSpacing")) return cutoff / 4.0;
    const double h = d.getPositive<double>("gridSpacing");
    if (h > cutoff) d.fail("gridSpacing", "must not exceed the cutoff (docs/walls.md 3.2: cells of r_c or finer)");
    return h;
}

SolidGeometry readGeometry(const Dictionary& d, const std::string& caseDir, const Box& box, double cutoff) {
    const std::string type = d.get<std::string>("type");
    const double reach = kBandInCutoffs * cutoff;
    try {
        if (type == "imageMask") {
            const ImageMaskSettings s = readMaskSettings(d, box);
            const std::string file = resolveFile(d, caseDir);
            return imageMaskGeometry(readGreyImage(file), s, box, file, reach);
        }
        if (type == "gmsh") return gmshGeometry(readGmshSettings(d, caseDir, box), box, reach);
    } catch (const GeometryInputError& e) {
        d.fail(e.keyword(), e.what());
    }
    d.fail("type", "expected imageMask or gmsh, not '" + type + "'");
}

SolidRegion readSolidRegion(const Dictionary& d, const std::string& caseDir, const Box& box, double cutoff) {
    SolidGeometry geometry = readGeometry(d, caseDir, box, cutoff);
    const BackgroundGrid grid = BackgroundGrid::covering(box, readGridSpacing(d, cutoff), geometry.uniformAxis());
    SolidFlags flags(grid, geometry);
    SignedDistanceField distance(geometry, grid, kBandInCutoffs * cutoff);
    return {std::move(geometry), std::move(flags), std::move(distance)};
}

}  // namespace dpd
