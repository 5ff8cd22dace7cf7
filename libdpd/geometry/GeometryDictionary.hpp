#pragma once
// The `geometry` block of constant/dpdProperties: the solid of a case of any shape (docs/walls.md 3.2),
// read by randomEquilWall (and by the solver once it reflects on curved walls). It lives in
// constant/, beside the files it names, since the shape belongs to the case, not to one tool.
//
//   geometry                                   // an image mask
//   {
//       type        imageMask;
//       file        "constant/geometry/mask.png";   // .png, .pgm/.ppm, .tif/.tiff; relative to the case
//       solidValues (0);          // grey levels (0..255 for 8-bit images) that are solid; or instead
//       // solidBelow 128;        //   grey < 128 is solid, or
//       // solidAbove 128;        //   grey > 128 is solid
//       pixelSize   0.1;          // side of one pixel in box units; the image must cover the box
//       smooth      yes;          // anti-alias the pixel staircase (ImageMask.hpp); default yes
//       extrudeAxis y;            // the axis normal to the image (y, the only choice in 2-D)
//       origin      (-80 0 -80);  // box position of the image's lower-left corner; default box min
//       gridSpacing 0.125;        // background grid of the flags and the distance; default cutoff/4
//   }
//
//   geometry                                   // a gmsh geometry
//   {
//       type        gmsh;
//       file        "constant/geometry/channel.geo";   // .geo or .msh with a physical group
//                                                      // named "fluid" or "solid"
//       extrudeAxis y;            // for a surface group: the axis normal to gmsh's x-y plane
//       origin      (0 0 0);      // box position of gmsh's (0 0 0); default (0 0 0)
//       meshSize    0.2;          // optional cap on the element size when gmsh meshes the file
//       gridSpacing 0.125;
//   }
//
// Image row 0 (the top of the picture) lies at the high end of the second in-plane axis (z for
// extrudeAxis y): the picture appears in the box as it does on screen, x to the right, z up.
#include "core/Box.hpp"
#include "geometry/SignedDistanceField.hpp"
#include "geometry/SolidFlags.hpp"
#include "geometry/SolidGeometry.hpp"

#include <string>

namespace dpd {

class Dictionary;

// The solid, its flags on the background grid and its signed distance out to +-2 cutoffs.
struct SolidRegion {
    SolidGeometry geometry;
    SolidFlags flags;
    SignedDistanceField distance;
};

// Reads the geometry block (a sub-dictionary) and builds everything on the box. Every problem,
// including those found in the image or gmsh file, is an InputError naming the dictionary's file,
// line and keyword.
SolidGeometry readGeometry(const Dictionary& geometryDict, const std::string& caseDir, const Box& box, double cutoff);
// The background grid's cell size: gridSpacing, default cutoff / 4, at most the cutoff.
double readGridSpacing(const Dictionary& geometryDict, double cutoff);
SolidRegion readSolidRegion(const Dictionary& geometryDict, const std::string& caseDir, const Box& box, double cutoff);

}  // namespace dpd
