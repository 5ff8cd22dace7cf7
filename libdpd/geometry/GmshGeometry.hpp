#pragma once
// A gmsh geometry (.geo or .msh) as a solid, through the gmsh C++ API.
//
// Convention: the file defines ONE physical group named "fluid" or "solid" (a Physical Surface for a
// planar geometry, a Physical Volume for a spatial one). Points inside its elements are fluid (or
// solid), every other point of the box the opposite. A .geo (or a .msh without elements in that
// group) is meshed with gmsh (linear elements; meshSize caps the element size). Curved boundaries
// are represented by the mesh's straight facets, so meshSize sets how closely they are followed.
//
// Placement (GeometryFrame): a surface group must lie in gmsh's x-y plane; its x runs along the
// first in-plane box axis and its y along the second (extrudeAxis y: gmsh x -> box x, gmsh y ->
// box z). A volume group keeps gmsh's x, y, z. `origin` is the box position of gmsh's (0, 0, 0);
// the mesh must lie inside the box, which repeats periodically.
//
// Point location: barycentric coordinates in the triangles (tetrahedra) filed in a bucket grid.
// Surface: the facets (edges, triangles) of the group's elements that belong to one element only,
// except those whose other side is in the group too across the periodic box.
#include "core/Box.hpp"
#include "geometry/SolidGeometry.hpp"

#include <Eigen/Core>

#include <string>

namespace dpd {

struct GmshSettings {
    std::string file;        // path to read
    int extrudeAxis = 1;     // planar geometries only
    Eigen::Vector3d origin{0, 0, 0};
    double meshSize = 0.0;   // 0: gmsh's default sizes
};

// Throws GeometryInputError (keyword "file") when the file is missing, does not parse, has no
// "fluid"/"solid" group, has elements other than triangles, quadrangles or tetrahedra, or lies
// outside the box.
SolidGeometry gmshGeometry(const GmshSettings& s, const Box& box, double searchReach);

}  // namespace dpd
