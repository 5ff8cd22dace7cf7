#pragma once
// A 2-D image mask as a solid (docs/walls.md 3.2): a grey image whose pixels are solid or fluid, laid
// in the plane of two box axes and extruded along the third (GeometryFrame::planar).
//
// Placement: the image is seen with its first in-plane axis (columns) to the right and its second
// (rows) pointing up, so image row 0 (the top of the picture) sits at the HIGH end of the second
// axis. With extrudeAxis y: columns run along x, rows down z (row 0 at the largest z). `origin` is
// the box position of the image's lower-left corner; the image must cover the box exactly
// (width x pixelSize and height x pixelSize equal the box lengths), and repeats periodically.
//
// Surface: pixel centres carry 1 (solid) or 0 (fluid), then (smooth yes, the default) a binomial
// filter (1 4 6 4 1)/16 along each axis, a Gaussian of one pixel's width. A point is solid where the
// bilinear interpolation of these values is >= 1/2, and the surface is the marching-squares contour
// at 1/2 (vertices where the values cross 1/2 along the edges between pixel centres).
//  - Without smoothing, the contour passes through the midpoints between neighbouring solid and fluid
//    pixel centres: a shape drawn with pixels of size p is recovered to within p/2, but its normals
//    turn in steps of 45 degrees.
//  - Smoothing anti-aliases the staircase: smooth boundaries come out within a small fraction of a
//    pixel with smooth normals; a straight boundary along pixel edges stays exactly in place (the
//    filter is symmetric) when the solid and fluid on either side are at least 2 pixels thick;
//    corners are rounded over about a pixel, and features thinner than 2 pixels may vanish.
// The classification and the contour's straight segments differ by at most 0.06 p.
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
    bool smooth = true;
};

// The solid/fluid pixels of an image: 1 = solid, 0 = fluid (in between once smoothed), stored from
// the BOTTOM row up (index j = 0 is the image's last row), so that j grows with the box's second
// in-plane axis.
struct PixelMask {
    int width = 0, height = 0;
    std::vector<double> solid;
    double at(int i, int j) const;  // periodic in i and j
    void smooth();                  // the binomial filter, periodic
};

PixelMask thresholdImage(const GreyImage& image, const ImageMaskSettings& s);

// Throws GeometryInputError when the image does not cover the box (keyword "pixelSize").
// source: the file name, for messages; searchReach as for SolidGeometry.
SolidGeometry imageMaskGeometry(const GreyImage& image, const ImageMaskSettings& s, const Box& box,
                                const std::string& source, double searchReach);

}  // namespace dpd
