#pragma once
// A 2-D image mask as a solid (METHODS.md 3.2): a grey image whose pixels are solid or fluid, laid
// in the plane of two box axes and extruded along the third (GeometryFrame::planar).
//
// Placement: the image is seen with its first in-plane axis (columns) to the right and its second
// (rows) pointing up, so image row 0 (the top of the picture) sits at the HIGH end of the second
// axis. With extrudeAxis y: columns run along x, rows down z (row 0 at the largest z). `origin` is
// the box position of the image's lower-left corner; the image must cover the box exactly
// (width x pixelSize and height x pixelSize equal the box lengths), and repeats periodically.
//
// Surface: pixel centres carry 1 (solid) or 0 (fluid). A point is solid where the bilinear
// interpolation of these values is >= 1/2, and the surface is the marching-squares contour at 1/2
// (through the midpoints between neighbouring solid and fluid pixel centres; in a checkerboard
// 2x2 block the two solid pixels join). A shape drawn with pixels of size p is thus recovered to
// within p/2; the classification and the contour segments differ by at most 0.06 p.
#include "core/Box.hpp"
#include "geometry/GreyImage.hpp"
#include "geometry/SolidGeometry.hpp"

#include <Eigen/Core>

#include <memory>
#include <vector>

namespace dpd {

struct ImageMaskSettings {
    std::vector<double> solidValues;     // grey levels that are solid, or else
    double threshold = 0.0;              // grey < threshold (solidBelow) or > threshold is solid
    bool useThreshold = false;
    bool solidBelow = true;
    double pixelSize = 1.0;
    int extrudeAxis = 1;
    Eigen::Vector3d origin{0, 0, 0};
};

// The solid/fluid pixels of an image: 1 = solid, stored from the BOTTOM row up (index j = 0 is the
// image's last row), so that j grows with the box's second in-plane axis.
struct PixelMask {
    int width = 0, height = 0;
    std::vector<std::uint8_t> solid;
    bool at(int i, int j) const;  // periodic in i and j
};

PixelMask thresholdImage(const GreyImage& image, const ImageMaskSettings& s);

// Throws GeometryInputError when the image does not cover the box (keyword "pixelSize").
// source: the file name, for messages; searchReach as for SolidGeometry.
SolidGeometry imageMaskGeometry(const GreyImage& image, const ImageMaskSettings& s, const Box& box,
                                const std::string& source, double searchReach);

}  // namespace dpd
